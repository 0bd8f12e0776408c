#pragma once
// Private to core/geometry: CGAL's polygon algorithms behind an Eigen-only interface, so that the
// CGAL headers stay in polygon_cgal.cpp (see mesh_cgal.hpp for the other CGAL door).
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp::detail {

/// True if no two edges of the closed polygon meet, except consecutive ones at their common
/// vertex (CGAL::is_simple_2: a plane sweep, O(n log n), with exact predicates). False for
/// repeated points and for consecutive edges that overlap.
bool is_simple_polygon(const std::vector<Vec2>& vertices);

}  // namespace fp::detail
