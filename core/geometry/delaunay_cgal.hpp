#pragma once
// The Delaunay tetrahedra of a set of points (CGAL's Delaunay_triangulation_3, exact predicates):
// the "void spaces" of paper 000's step 7b are the tetrahedra of the triangulation of the sphere
// centres. CGAL is confined to delaunay_cgal.cpp.
#include <array>
#include <cstdint>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

/// The finite cells of the Delaunay triangulation of `points`, as indices into it, each
/// positively oriented. Points given twice are one vertex (the first index); fewer than four
/// points, or all on a plane, give none.
std::vector<std::array<std::uint32_t, 4>> delaunay_tetrahedra(const std::vector<Vec3>& points);

/// 2D: the finite faces of the Delaunay triangulation of `points`, each counter-clockwise; the
/// same rules (duplicates, fewer than three points or all on a line: none).
std::vector<std::array<std::uint32_t, 3>> delaunay_triangles(const std::vector<Vec2>& points);

/// The simplices of the dimension's triangulation (tetrahedra or triangles).
template <int D>
std::vector<std::array<std::uint32_t, D + 1>> delaunay_simplices(const std::vector<Vec<D>>& points) {
  if constexpr (D == 3) return delaunay_tetrahedra(points);
  else return delaunay_triangles(points);
}

}  // namespace fp
