#pragma once
// Every figure of `frontpack analyze` for a packing of shapes, in the analysis of sphere packings
// (core/metrics/packing_analysis.hpp), from the same metric code wherever the figure is defined
// for any shape:
//  * the contact network is the validator's (validate_shapes: the narrow phase's gaps, contact
//    normals from it, not the centre lines); coordination, rattlers, z(xi), both fabric tensors
//    and the relative projections are computed from it;
//  * sizes are volume-equivalent radii r_eq = (3 V / 4 pi)^(1/3) (2D: sqrt(A / pi)): r_min,
//    r_max, the classes of z(xi), and the mean diameter of g(r) (over the centres);
//  * VF of the container: the shapes' exact measures; VF of the core and in the reference ball:
//    whole particles inside by their exact measure, the ones the boundary cuts by QMC against
//    Shape::contains (container_volume_fraction.hpp);
//  * homogeneity of the centres with the margin of the largest circumscribed radius; the VF in
//    cells (a uniformity figure over cells of 8 mean diameters) with each particle as its ball
//    of the same volume at its centre;
//  * the size test: the validator's (one template); the orientation tensor of the body x axes
//    and its nematic order.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/io/scene.hpp"
#include "core/metrics/packing_analysis.hpp"
#include "core/metrics/validate.hpp"
#include "shapes/particle.hpp"

namespace fp {

/// The radius of the ball (disk) of the same measure: the r_eq of the analysis.
template <int D>
double equivalent_radius(double measure) {
  if constexpr (D == 3) return std::cbrt(3.0 * measure / (4.0 * std::numbers::pi));
  else return std::sqrt(measure / std::numbers::pi);
}

/// `requested` per template id (contact/shape_validation.hpp), `families` its names for the
/// table; options.contact_tolerance is the tolerance of the validation and of the contacts.
template <int D>
PackingAnalysis analyze_shape_packing(const ShapePacking<D>& packing, const Container<D>& container,
                                      const std::vector<RequestedTemplate>& requested,
                                      const std::vector<std::string>& families, const AnalysisOptions& options = {});

/// The same for a packing of the scene's templates, at options.contact_tolerance.
template <int D>
PackingAnalysis analyze_shape_packing(const ShapePacking<D>& packing, const Scene& scene, const AnalysisOptions& options);

}  // namespace fp
