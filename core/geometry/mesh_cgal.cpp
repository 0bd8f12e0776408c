// CGAL translation unit 2 of 2: spatial queries on a closed triangle surface (AABB tree,
// Side_of_triangle_mesh) and its self-intersection test. Everything CGAL stays in this file; the interface is mesh_cgal.hpp.
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/exceptions.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/geometry/mesh_cgal.hpp"
#include "core/geometry/triangle_closest_point.hpp"

namespace fp::detail {
namespace {

using K = CGAL::Epick;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
// Triangles cached in the primitives (last Tag_true): no halfedge walk in the hot queries.
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh, CGAL::Default, CGAL::Tag_true, CGAL::Tag_true>;
using Traits = CGAL::AABB_traits<K, Primitive>;
using Tree = CGAL::AABB_tree<Traits>;
using Side = CGAL::Side_of_triangle_mesh<Mesh, K, CGAL::Default, Tree>;

Point to_point(const Vec3& v) { return Point(v.x(), v.y(), v.z()); }
Vec3 to_vec(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

double box_distance2(const Vec3& p, const CGAL::Bbox_3& b) {
  double d2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double x = p[a];
    const double excess = x < b.min(a) ? b.min(a) - x : (x > b.max(a) ? x - b.max(a) : 0.0);
    d2 += excess * excess;
  }
  return d2;
}

/// Squared distance from p to a primitive's (cached) triangle, and the closest point.
double primitive_distance2(const Vec3& p, const Primitive& primitive, const Traits& traits, Vec3* closest = nullptr) {
  const auto& t = primitive.datum(traits.shared_data());
  const Vec3 q = closest_on_triangle(p, to_vec(t[0]), to_vec(t[1]), to_vec(t[2]));
  if (closest) *closest = q;
  return (p - q).squaredNorm();
}

/// Tree traversals below: the query object passed to the tree is a CGAL point, the traits
/// keep the Eigen copy they compute with.

/// Nearest facet: nearer child first, nodes farther than the best so far skipped.
class Nearest {
 public:
  using Priority = double;
  Nearest(const Vec3& p, const Traits& traits) : p_(p), traits_(traits) {}
  bool go_further() const { return true; }
  void intersection(const Point&, const Primitive& primitive) {
    Vec3 q;
    const double d2 = primitive_distance2(p_, primitive, traits_, &q);
    if (d2 < best_d2_) {
      best_d2_ = d2;
      best_ = q;
      face_ = primitive.id();
    }
  }
  template <class Node>
  bool do_intersect(const Point&, const Node& node) const {
    return box_distance2(p_, node.bbox()) < best_d2_;
  }
  template <class Node>
  std::pair<bool, Priority> do_intersect_with_priority(const Point&, const Node& node) const {
    const double d2 = box_distance2(p_, node.bbox());
    return {d2 < best_d2_, -d2};
  }
  const Vec3& closest() const { return best_; }
  Mesh::Face_index face() const { return face_; }

 private:
  Vec3 p_;
  const Traits& traits_;
  double best_d2_ = std::numeric_limits<double>::infinity();
  Vec3 best_ = Vec3::Zero();
  Mesh::Face_index face_;
};

/// Every facet within `reach` (inclusive).
class WithinReach {
 public:
  WithinReach(const Vec3& p, double reach2, const Traits& traits, std::vector<int>& out)
      : p_(p), reach2_(reach2), traits_(traits), out_(out) {}
  bool go_further() const { return true; }
  void intersection(const Point&, const Primitive& primitive) {
    if (primitive_distance2(p_, primitive, traits_) <= reach2_) out_.push_back(static_cast<int>(primitive.id().idx()));
  }
  template <class Node>
  bool do_intersect(const Point&, const Node& node) const {
    return box_distance2(p_, node.bbox()) <= reach2_;
  }

 private:
  Vec3 p_;
  double reach2_;
  const Traits& traits_;
  std::vector<int>& out_;
};

/// Whether some facet is strictly closer than sqrt(limit2); stops at the first one.
class AnyCloser {
 public:
  AnyCloser(const Vec3& p, double limit2, const Traits& traits) : p_(p), limit2_(limit2), traits_(traits) {}
  bool go_further() const { return !found_; }
  void intersection(const Point&, const Primitive& primitive) {
    if (primitive_distance2(p_, primitive, traits_) < limit2_) found_ = true;
  }
  template <class Node>
  bool do_intersect(const Point&, const Node& node) const {
    return box_distance2(p_, node.bbox()) < limit2_;
  }
  bool found() const { return found_; }

 private:
  Vec3 p_;
  double limit2_;
  const Traits& traits_;
  bool found_ = false;
};

}  // namespace

struct TriangleSurfaceIndex::Impl {
  // CGAL sees the surface scaled by a power of two to an extent of about 1 (exact): its ray
  // shooting hung on a mesh scaled by 2^60, and a scene scaled by any power of two must behave
  // exactly as at scale 1.
  double scale = 1.0, inv = 1.0;
  Point in(const Vec3& p) const { return to_point(Vec3(p * inv)); }
  Mesh mesh;  ///< face i is facet i (geometry only: the caller may re-orient its facets afterwards)
  std::vector<Mesh::Face_index> solid_faces;  ///< the facets of non-zero area
  Tree tree;  ///< over solid_faces
  std::unique_ptr<Side> side;
};

TriangleSurfaceIndex::TriangleSurfaceIndex(const std::vector<Vec3>& vertices,
                                           const std::vector<std::array<int, 3>>& triangles)
    : impl_(std::make_unique<Impl>()) {
  try {
    build(vertices, triangles);
  } catch (const CGAL::Failure_exception& e) {  // its what() is a page of CGAL internals
    throw std::invalid_argument("a check of the geometry library failed (" + e.expression() + ")");
  }
}

void TriangleSurfaceIndex::build(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles) {
  Impl& m = *impl_;
  double extent = 0.0;
  for (const Vec3& v : vertices) extent = std::max(extent, v.cwiseAbs().maxCoeff());
  if (extent > 0.0 && std::isfinite(extent)) {
    int e = 0;
    std::frexp(extent, &e);
    m.scale = std::ldexp(1.0, e);
    m.inv = std::ldexp(1.0, -e);
  }
  m.mesh.reserve(vertices.size(), 3 * triangles.size() / 2, triangles.size());
  for (const Vec3& v : vertices) m.mesh.add_vertex(m.in(v));
  std::vector<Mesh::Face_index>& solid_faces = m.solid_faces;
  solid_faces.reserve(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& t = triangles[f];
    const Mesh::Face_index fi =
        m.mesh.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]), Mesh::Vertex_index(t[2]));
    if (fi == Mesh::null_face())
      throw std::invalid_argument("facet " + std::to_string(f) + " does not fit a manifold, oriented surface");
    if (!CGAL::collinear(m.in(vertices[t[0]]), m.in(vertices[t[1]]), m.in(vertices[t[2]])))
      solid_faces.push_back(fi);
  }
  if (solid_faces.empty()) throw std::invalid_argument("all facets have zero area");
  m.tree.insert(solid_faces.begin(), solid_faces.end(), m.mesh);
  m.tree.build();  // now, not lazily in a const query; our traversals need no kd-tree hint
  m.tree.do_not_accelerate_distance_queries();
  m.side = std::make_unique<Side>(m.tree);
}

TriangleSurfaceIndex::~TriangleSurfaceIndex() = default;

int TriangleSurfaceIndex::side(const Vec3& p) const {
  switch ((*impl_->side)(impl_->in(p))) {
    case CGAL::ON_BOUNDED_SIDE: return 1;
    case CGAL::ON_BOUNDARY: return 0;
    default: return -1;
  }
}

Vec3 TriangleSurfaceIndex::closest_point(const Vec3& p, int* facet) const {
  const Vec3 q = p * impl_->inv;
  Nearest traits(q, impl_->tree.traits());
  impl_->tree.traversal_with_priority(to_point(q), traits);
  if (facet) *facet = static_cast<int>(traits.face().idx());
  return traits.closest() * impl_->scale;
}

void TriangleSurfaceIndex::facets_within(const Vec3& p, double reach, std::vector<int>& out) const {
  if (!(reach >= 0.0)) return;
  const Vec3 q = p * impl_->inv;
  const double rq = reach * impl_->inv;
  WithinReach traits(q, rq * rq, impl_->tree.traits(), out);
  impl_->tree.traversal(to_point(q), traits);
}

bool TriangleSurfaceIndex::any_facet_closer_than(const Vec3& p, double distance) const {
  if (!(distance > 0.0)) return false;
  const Vec3 q = p * impl_->inv;
  const double dq = distance * impl_->inv;
  AnyCloser traits(q, dq * dq, impl_->tree.traits());
  impl_->tree.traversal(to_point(q), traits);
  return traits.found();
}

double TriangleSurfaceIndex::scale() const { return impl_->scale; }
double TriangleSurfaceIndex::inverse_scale() const { return impl_->inv; }

std::vector<char> TriangleSurfaceIndex::solid_facets() const {
  std::vector<char> solid(impl_->mesh.number_of_faces(), 0);
  for (const Mesh::Face_index f : impl_->solid_faces) solid[f.idx()] = 1;
  return solid;
}

bool TriangleSurfaceIndex::find_crossing_facets(int& f, int& g) const {
  namespace PMP = CGAL::Polygon_mesh_processing;
  // Zero-area facets are left out: PMP counts each as an intersection with itself, and they
  // change neither the inside nor the distances (see the constructor).
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  try {
    PMP::self_intersections(impl_->solid_faces, impl_->mesh, std::back_inserter(pairs), CGAL::parameters::maximum_number(1));
  } catch (const CGAL::Failure_exception& e) {
    throw std::invalid_argument("the self-intersection test failed (" + e.expression() + ")");
  }
  if (pairs.empty()) return false;
  f = static_cast<int>(pairs.front().first.idx());
  g = static_cast<int>(pairs.front().second.idx());
  return true;
}

int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return static_cast<int>(CGAL::orientation(to_point(a), to_point(b), to_point(c), to_point(d)));
}

}  // namespace fp::detail
