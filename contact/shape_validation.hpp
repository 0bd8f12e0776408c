#pragma once
// Checks a packing of general particles from the particles alone, with the verdict and report of
// sphere packings (core/metrics/validate_particles.hpp: the same loops, broad phase, issues, size
// and mix tests): every pair whose circumscribed spheres meet by the narrow phase's gap, every
// particle against the container (ShapeContainment: exact for boxes and convex polygons, the hull
// balls otherwise). The length unit of a particle is its circumscribed radius; its size is the
// one drawn from its template's law. The figures the packer reports are the ones this finds.
#include <vector>

#include "core/geometry/container.hpp"
#include "core/io/scene.hpp"
#include "core/metrics/contact_network.hpp"
#include "core/metrics/validate.hpp"
#include "shapes/particle.hpp"

namespace fp {

/// What a scene of shapes asks for, per template id (its list of particle templates).
std::vector<RequestedTemplate> requested_templates(const Scene& scene);

/// Without `requested` only overlaps, containment, sizes > 0 and emptiness are checked. With
/// `network`, the contacts (normals from the narrow phase) are listed there too.
template <int D>
ValidationReport validate_shapes(const ShapePacking<D>& packing, const Container<D>& container, double tolerance,
                                 const std::vector<RequestedTemplate>& requested = {},
                                 double sizes_alpha = kRadiiAlpha, ContactNetwork<D>* network = nullptr);

}  // namespace fp
