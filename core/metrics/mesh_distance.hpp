#pragma once
// The validator's own signed distance to a closed triangle surface, written apart from the mesh
// container (which answers with CGAL's AABB tree and ray shooting):
//  * distance: exact point-triangle distances (point_triangle.hpp) over the triangles of a
//    uniform grid of its own, each triangle listed in every cell its bounding box meets;
//  * sign near the surface: the angle-weighted pseudo-normal of the nearest feature (Baerentzen &
//    Aanaes 2005: for a closed, consistently oriented surface, (p - q) . n of the nearest point q
//    on face, edge or vertex has the sign of the side of p), so a point 1e-12 off a face, edge or
//    vertex, convex or reflex, gets its side right;
//  * sign far from it: the winding number of a ray along +x through one row of cells, each
//    triangle's projection tested with symbolic perturbation so that a ray through an edge or a
//    vertex is counted once (edges are evaluated in one canonical order, so the two triangles
//    sharing one agree bit for bit).
#include <array>
#include <limits>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

class MeshDistance {
 public:
  /// A closed, manifold surface whose triangles are oriented with outward normals (what
  /// MeshContainer guarantees). Throws std::invalid_argument for an empty surface or an index out
  /// of range.
  MeshDistance(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> triangles);

  /// Signed distance from p to the surface, < 0 inside. Exact to rounding when p is outside or
  /// within `reach` of the surface; an inside point farther than `reach` gets -reach (the search
  /// stops there: what a ball of radius reach needs).
  double signed_distance(const Vec3& p, double reach = std::numeric_limits<double>::infinity()) const;
  /// p inside the closed surface, by the ray's winding number alone (points on the surface
  /// may go either way).
  bool inside_by_ray(const Vec3& p) const;
  /// Unsigned distance by brute force over every triangle (the reference of the grid search).
  double distance_brute_force(const Vec3& p) const;

  std::size_t num_triangles() const { return tri_.size(); }
  std::array<int, 3> grid_cells() const { return n_; }

 private:
  struct Nearest {
    double distance = std::numeric_limits<double>::infinity();
    int triangle = -1;
    Vec3 point = Vec3::Zero();
    int feature_kind = 0, feature_index = 0;
  };
  void consider(const Vec3& p, int t, Nearest& best) const;
  double sign_of(const Vec3& p, const Nearest& best) const;
  int cell_coord(double x, int axis) const;

  std::vector<Vec3> v_;
  std::vector<std::array<int, 3>> tri_;
  std::vector<Vec3> face_normal_;                  // unit outward (zero for a zero-area triangle)
  std::vector<std::array<int, 3>> tri_edge_;       // global edge id of edge k (vertex k to k + 1)
  std::vector<Vec3> edge_normal_, vertex_normal_;  // pseudo-normals (unnormalised)
  Vec3 lo_ = Vec3::Zero();
  double h_ = 1.0;
  std::array<int, 3> n_{1, 1, 1};
  std::vector<int> cell_start_, cell_items_;  // triangles of cell c: cell_items_[cell_start_[c] .. cell_start_[c + 1])
};

}  // namespace fp
