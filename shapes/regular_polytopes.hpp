#pragma once
// Vertex sets of regular polygons and of the five Platonic solids, on the unit circle / sphere
// (the `sides` and `platonic` shortcuts of the polygon and polyhedron families).
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

/// Regular n-gon (n >= 3), counter-clockwise, with a horizontal bottom edge.
std::vector<Vec2> regular_polygon(int sides);

/// Platonic solid by its number of faces: 4 tetrahedron, 6 cube, 8 octahedron, 12 dodecahedron,
/// 20 icosahedron; empty for any other number.
std::vector<Vec3> platonic_solid(int faces);

}  // namespace fp
