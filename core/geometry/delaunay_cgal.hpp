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

}  // namespace fp
