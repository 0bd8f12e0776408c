#pragma once
// Plane sections of a packing of shapes (core/metrics/packing_sections.hpp draws them): each
// particle the plane cuts gives the loops where its surface mesh crosses the plane, exact for
// polyhedra (their mesh is their surface) and to kSectionResolution for curved shapes; in 2D each
// particle's outline. Absolute coordinates.
#include <vector>

#include "core/geometry/container.hpp"
#include "core/metrics/packing_sections.hpp"
#include "shapes/particle.hpp"

namespace fp {

/// The surface resolution of the sections' curved shapes (Shape::surface): finer than the
/// surfaces file's, as a section is looked at closely.
inline constexpr int kSectionResolution = 32;

template <int D>
std::vector<PackingSection> shape_sections(const ShapePacking<D>& packing, const Container<D>& container, int grid = 512);

}  // namespace fp
