#pragma once
// The Delaunay triangulation of a set of points (CGAL's Delaunay_triangulation_3 and _2, exact
// predicates): the "void spaces" of paper 000's step 7b are the tetrahedra (2D: triangles) of
// the triangulation of the sphere centres. It grows: points are added in batches, and each batch
// returns the simplices it made, so that a void filling round looks only at the voids around
// what the previous round added. CGAL is confined to delaunay_cgal.cpp.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D>
class GrowingDelaunay {
 public:
  using Simplex = std::array<std::uint32_t, D + 1>;
  GrowingDelaunay();
  ~GrowingDelaunay();
  GrowingDelaunay(const GrowingDelaunay&) = delete;
  GrowingDelaunay& operator=(const GrowingDelaunay&) = delete;

  /// Inserts points[from], points[from + 1], ... (the earlier ones were inserted by earlier
  /// calls with the same vector, grown since) and returns the finite simplices made since the
  /// previous call (on the first, all of them), as indices into `points`, each positively
  /// oriented, sorted by their sorted vertex indices. A point given twice is one vertex (the
  /// smaller index); while the points lie on a plane (2D: a line) there are none.
  std::vector<Simplex> insert(const std::vector<Vec<D>>& points, std::size_t from);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The finite edges of the Delaunay triangulation of `points` (its neighbours: paper 001's
/// contact pairs), each as (i, j) with i < j, sorted. A point given twice is one vertex (the
/// smaller index); the other has no edge.
template <int D>
std::vector<std::array<std::uint32_t, 2>> delaunay_edges(const std::vector<Vec<D>>& points);

/// The finite cells of the Delaunay triangulation of `points` (one batch of GrowingDelaunay<3>).
std::vector<std::array<std::uint32_t, 4>> delaunay_tetrahedra(const std::vector<Vec3>& points);

/// 2D: the finite faces, each counter-clockwise (one batch of GrowingDelaunay<2>).
std::vector<std::array<std::uint32_t, 3>> delaunay_triangles(const std::vector<Vec2>& points);

}  // namespace fp
