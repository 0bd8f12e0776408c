#pragma once
// Checks a packing of general particles from the particles alone: every pair whose circumscribed
// spheres meet (found with a grid, then the narrow phase), every particle against the container
// (its hull balls: exact for convex containers). The figures the packer reports are the ones
// this finds. Also counts contacts (|gap| <= tolerance) for the coordination number. With the
// requested templates, the sizes and the mix are tested as the radii of spheres are
// (core/metrics/radii_fit.hpp): one verdict for spheres and shapes; an empty packing fails.
#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/io/scene.hpp"
#include "core/metrics/radii_fit.hpp"
#include "core/metrics/validate.hpp"
#include "core/sampling/chi_square_test.hpp"
#include "shapes/particle.hpp"

namespace fp {

struct ShapeValidation {
  bool ok = true;
  double tolerance = 0;            ///< relative to the smaller circumscribed radius of a pair
  std::uint64_t pairs_checked = 0; ///< pairs given to the narrow phase
  std::uint64_t overlaps = 0;      ///< pairs overlapping beyond the tolerance
  double max_overlap_rel = 0;      ///< largest overlap depth / smaller circumscribed radius
  int worst_a = -1, worst_b = -1;
  std::uint64_t outside = 0;       ///< particles reaching beyond the container by more than the tolerance
  double max_outside_rel = 0;      ///< largest protrusion / circumscribed radius
  std::uint64_t contacts = 0;      ///< particle pairs with |gap| <= tolerance
  double max_contact_gap_rel = 0;  ///< largest |gap| / smaller circumscribed radius among those contacts
                                   ///< (how exactly the solvers made them touch)
  std::uint64_t wall_contacts = 0; ///< particles within the tolerance of the boundary
  double mean_coordination = 0;    ///< 2 contacts / N
  bool empty = false;              ///< no particle at all: a failure

  /// Sizes and mix against the request. Each of the `tests` tests passes at sizes_alpha / tests
  /// (Bonferroni: the chance that a correct packing fails stays below sizes_alpha).
  double sizes_alpha = kRadiiAlpha;
  int tests = 0;
  std::vector<RadiiFit> sizes;     ///< per template id: its placed sizes against its size law
  std::uint64_t sizes_out_of_range = 0;  ///< sizes their template's law cannot produce (radius_excess)
  bool mix_tested = false;         ///< two templates or more: chi-square of the counts per template
  ChiSquareResult mix;
  bool sizes_ok() const;

  std::string summary() const;
};

/// What a packing was asked for, per template id: the size law and the share by number.
struct RequestedTemplate {
  const RadiusDistribution* size = nullptr;
  double fraction = 1.0;
};

/// What a scene of shapes asks for, per template id (its list of particle templates).
std::vector<RequestedTemplate> requested_templates(const Scene& scene);

/// Without `requested` only overlaps, containment and emptiness are checked.
template <int D>
ShapeValidation validate_shapes(const ShapePacking<D>& packing, const Container<D>& container, double tolerance,
                                const std::vector<RequestedTemplate>& requested = {},
                                double sizes_alpha = kRadiiAlpha);

}  // namespace fp
