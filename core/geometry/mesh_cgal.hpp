#pragma once
// Private to core/geometry: the only door to CGAL. Eigen/STL types only, so that CGAL headers
// (10-30 s of compile each, and -frounding-math) stay in mesh_cgal.cpp and mesh_cgal_io.cpp.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp::detail {

/// Points and polygons (vertex indices) as read from a file, before any checking.
struct PolygonSoup {
  std::vector<Vec3> points;
  std::vector<std::vector<std::size_t>> polygons;
};

/// Reads an OFF, OBJ or STL (ascii or binary) file, chosen by extension. On failure returns
/// false and sets `error` to the reason.
bool read_polygon_soup(const std::string& path, PolygonSoup& soup, std::string& error);

/// The sign of the orientation of d against the plane abc, exact (CGAL's filtered predicate):
/// +1, 0 (coplanar) or -1.
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Spatial queries on a closed triangle surface: AABB tree + CGAL::Side_of_triangle_mesh,
/// both built eagerly in the constructor, so that const queries are thread-safe.
/// Facets with zero area are left out of the tree (they change neither parity nor distances).
/// Needs a closed, edge- and vertex-manifold, consistently oriented surface (throws otherwise).
class TriangleSurfaceIndex {
 public:
  TriangleSurfaceIndex(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles);
  ~TriangleSurfaceIndex();
  TriangleSurfaceIndex(const TriangleSurfaceIndex&) = delete;
  TriangleSurfaceIndex& operator=(const TriangleSurfaceIndex&) = delete;

  /// +1 inside, 0 on the surface, -1 outside (ray parity; independent of facet orientation).
  int side(const Vec3& p) const;
  /// Closest point on the surface and the facet it lies on.
  Vec3 closest_point(const Vec3& p, int* facet) const;
  /// Appends the ids of the facets whose distance to p is <= reach.
  void facets_within(const Vec3& p, double reach, std::vector<int>& out) const;
  /// True if some facet is strictly closer to p than `distance` (stops at the first found).
  bool any_facet_closer_than(const Vec3& p, double distance) const;
  /// Whether two facets of non-zero area cross (more than a shared edge or vertex): a surface
  /// that intersects itself, or two closed parts that overlap. Sets f and g to the first pair
  /// found (CGAL::Polygon_mesh_processing::does_self_intersect's search, kept to name them).
  bool find_crossing_facets(int& f, int& g) const;
  /// The frame of every query: points are multiplied by inverse_scale() (a power of two, exact)
  /// before CGAL sees them, and its answers by scale() after.
  double scale() const;
  double inverse_scale() const;
  /// Per facet: whether it has non-zero area (the others are in no query).
  std::vector<char> solid_facets() const;

 private:
  void build(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles);

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fp::detail
