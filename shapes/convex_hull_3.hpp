#pragma once
// Convex hull of points in space (CGAL convex_hull_3 with exact predicates, so coplanar and
// duplicate points are handled exactly). CGAL stays in convex_hull_3.cpp (library
// fp_shapes_cgal, linked PRIVATE): this header is Eigen only.
#include <array>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

struct ConvexHull3 {
  std::vector<Vec3> vertices;               ///< the extreme points only
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside (coplanar faces are triangulated)
};

/// Throws std::invalid_argument when the points span no volume (fewer than 4, or coincident,
/// collinear or coplanar up to 1e-12 of their extent).
ConvexHull3 convex_hull_3(const std::vector<Vec3>& points);

}  // namespace fp
