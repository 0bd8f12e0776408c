#include "contact/narrow_phase.hpp"

#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "contact/ellipsoid_gap.hpp"
#include "contact/segment_distance.hpp"
#include "contact/swept_ball.hpp"
#include "core/geometry/convex_polygon.hpp"
#include "core/geometry/triangle_closest_point.hpp"
#include "shapes/ellipsoid_shape.hpp"
#include "shapes/cluster_shape.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/sphere_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace fp {

template <int D>
struct NarrowPhase<D>::FclShape {
  ShapePtr<D> keep_alive;  // the cache key is the address: keeping the shape alive keeps it unique
  /// FCL's geometry, built at the first distance query: a polytope pair that the separating axes
  /// answer never needs it (building an fcl::Convex, topology checks included, cost 14 % of a
  /// 2D polygon run, for drafts tested once and forgotten). In FCL's length unit (fcl_unit()):
  /// the shape scaled by 1 / unit, exactly (a power of two).
  const std::vector<FclPart<D>>& parts(double unit) const {
    if (!parts_built) parts_cache = (unit == 1 ? keep_alive : keep_alive->scaled(1 / unit))->fcl_parts(), parts_built = true;
    return parts_cache;
  }
  mutable std::vector<FclPart<D>> parts_cache;
  mutable bool parts_built = false;
  std::vector<Ball<D>> balls;     // a cluster's members (its pieces); empty for a convex shape
  std::vector<Vec<D>> normals;    // polytopes: facet normals (body frame), separating-axis candidates
  std::vector<Vec<D>> edges;      // polyhedra: edge directions (body frame), triangulated faces' diagonals too
  std::vector<Vec<D>> polytope_edges;  // convex polyhedra: their true edge directions (body frame)
  bool convex_polytope = false;   // a ConvexPolytopeShape: normals and polytope_edges are every separating axis
  std::vector<Vec<D>> vertices;   // polytopes: vertices (body frame), for the separating-axis test
};

namespace {

/// Gap of two balls, gradient for the second.
template <int D>
Gap<D> ball_gap(const Vec<D>& ca, double ra, const Vec<D>& cb, double rb) {
  const Vec<D> d = cb - ca;
  const double n = d.norm();
  return {n - ra - rb, unit_or<D>(d, Vec<D>::UnitX())};
}

/// Gap of two swept balls (paper 004 Eq. 6 in distance form), gradient for the second.
template <int D>
Gap<D> swept_gap(const SweptBall<D>& a, const SweptBall<D>& b, const Vec<D>& ca, const Vec<D>& cb) {
  return swept_ball_gap<D>(SegmentPair<D>(a.along, b.along).closest(a.from, b.from), a.radius, b.radius, cb - ca);
}

template <int D>
SweptBall<D> swept_of(const Particle<D>& p) {
  return *swept_ball<D>(*p.shape, p.pose.rotation, p.pose.position);
}

template <int D>
Gap<D> sphere_sphere(const Particle<D>& a, const Particle<D>& b) {
  return ball_gap<D>(a.pose.position, a.bounding_radius(), b.pose.position, b.bounding_radius());
}

template <int D>
Gap<D> capsule_capsule(const Particle<D>& a, const Particle<D>& b) {
  return swept_gap<D>(swept_of(a), swept_of(b), a.pose.position, b.pose.position);
}

template <int D>
Gap<D> sphere_capsule(const Particle<D>& a, const Particle<D>& b) {
  return swept_gap<D>(swept_of(a), swept_of(b), a.pose.position, b.pose.position);
}

/// Shapes made of balls (clusters, spheres): the least gap over member pairs. A capsule member
/// list is its segment (handled as swept balls).
template <int D>
void pieces_of(const Particle<D>& p, std::vector<SweptBall<D>>& s) {
  s.clear();
  if (std::strcmp(p.shape->kind(), SpherocylinderShape<D>::kKind) == 0) {
    s.push_back(swept_of(p));
    return;
  }
  auto add = [&](const Ball<D>& b) { s.push_back({p.pose.to_world(b.center), Vec<D>::Zero(), b.radius}); };
  if (std::strcmp(p.shape->kind(), ClusterShape<D>::kKind) == 0) {  // its members, without a copy
    for (const Ball<D>& b : static_cast<const ClusterShape<D>&>(*p.shape).members()) add(b);
    return;
  }
  for (const Ball<D>& b : p.shape->hull_balls()) add(b);  // a sphere: one ball
}

template <int D>
Gap<D> ball_union_gap(const Particle<D>& a, const Particle<D>& b) {
  // Reused buffers: a cluster pair's gap is a few microseconds, its allocations were a third of it.
  thread_local std::vector<SweptBall<D>> pa, pb;
  pieces_of(a, pa);
  pieces_of(b, pb);
  Gap<D> best{std::numeric_limits<double>::infinity(), Vec<D>::Zero()};
  for (const SweptBall<D>& u : pa)
    for (const SweptBall<D>& v : pb) {
      const Gap<D> g = swept_gap<D>(u, v, a.pose.position, b.pose.position);
      if (g.value < best.value) best = g;
    }
  return best;
}

/// A convex polytope against a ball (world centre c, radius r): the signed distance from c to the
/// polytope less r, with its gradient for the ball, the unit direction from the polytope's nearest
/// point to c (inside: the outward normal of the least deep face plane, whose distance is the
/// depth: the polytope is the intersection of its half-spaces). Exact to rounding; FCL's GJK took
/// ~5 us for it and its overlap depth needed the separating-axis search.
template <int D>
Gap<D> polytope_ball(const Particle<D>& a, const Vec<D>& c, double r) {
  const auto& poly = static_cast<const ConvexPolytopeShape<D>&>(*a.shape);
  const Vec<D> y = a.pose.to_body(c);
  const auto& normals = poly.plane_normals();
  const auto& offsets = poly.plane_offsets();
  double out = -std::numeric_limits<double>::infinity();
  std::size_t face = 0;
  for (std::size_t k = 0; k < normals.size(); ++k)
    if (const double v = normals[k].dot(y) - offsets[k]; v > out) out = v, face = k;
  if (out <= 0) return {out - r, a.pose.rotation * normals[face]};
  // Outside: the nearest point of the boundary, over its facets (triangles; 2D: edges).
  const auto& v = poly.vertices();
  double d2 = std::numeric_limits<double>::infinity();
  Vec<D> nearest = y;
  for (const auto& f : poly.facets()) {
    Vec<D> q;
    if constexpr (D == 3) {
      q = detail::closest_on_triangle(y, v[static_cast<std::size_t>(f[0])], v[static_cast<std::size_t>(f[1])],
                                      v[static_cast<std::size_t>(f[2])]);
    } else {
      const Vec2 a0 = v[static_cast<std::size_t>(f[0])], e = v[static_cast<std::size_t>(f[1])] - a0;
      q = a0 + std::clamp((y - a0).dot(e) / e.squaredNorm(), 0.0, 1.0) * e;
    }
    if (const double e2 = (y - q).squaredNorm(); e2 < d2) d2 = e2, nearest = q;
  }
  const double d = std::sqrt(d2);
  return {d - r, a.pose.rotation * unit_or<D>(Vec<D>(y - nearest), normals[face])};
}

template <int D>
Gap<D> polytope_sphere(const Particle<D>& a, const Particle<D>& b) {
  return polytope_ball<D>(a, b.pose.position, b.bounding_radius());
}

/// A polytope against a cluster: the least gap over the members.
template <int D>
Gap<D> polytope_cluster(const Particle<D>& a, const Particle<D>& b) {
  Gap<D> best{std::numeric_limits<double>::infinity(), Vec<D>::Zero()};
  for (const Ball<D>& m : static_cast<const ClusterShape<D>&>(*b.shape).members()) {
    const Gap<D> g = polytope_ball<D>(a, b.pose.to_world(m.center), m.radius);
    if (g.value < best.value) best = g;
  }
  return best;
}

/// The 3D transform of a pose (2D: in the z = 0 plane, rotation about z).
template <int D>
fcl::Transform3d transform_of(const Pose<D>& pose) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  if constexpr (D == 2) {
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    R.template topLeftCorner<2, 2>() = pose.rotation;
    t.linear() = R;
    t.translation() = Eigen::Vector3d(pose.position[0], pose.position[1], 0.0);
  } else {
    t.linear() = pose.rotation;
    t.translation() = pose.position;
  }
  return t;
}

template <int D>
fcl::Transform3d part_transform(const Pose<D>& pose, const FclPart<D>& part) {
  fcl::Transform3d local = fcl::Transform3d::Identity();
  local.linear() = part.rotation;
  if constexpr (D == 2) local.translation() = Eigen::Vector3d(part.offset[0], part.offset[1], 0.0);
  else local.translation() = part.offset;
  return transform_of(pose) * local;
}

template <int D>
Vec<D> project(const Eigen::Vector3d& v) {
  if constexpr (D == 2) return Vec2(v[0], v[1]);
  else return v;
}


/// A convex piece through its world-frame support function.
template <int D>
struct ConvexPiece {
  const Particle<D>* particle;
  const Ball<D>* ball;  // a cluster member, or null for the whole (convex) shape
  Vec<D> support(const Vec<D>& u) const {
    if (!ball) return particle->support(u);
    const double n = u.norm();
    return particle->pose.to_world(ball->center) + (n > 0 ? Vec<D>(u * (ball->radius / n)) : Vec<D>::Zero());
  }
};

/// Signed gap of two overlapping convex pieces without EPA (FCL's EPA aborts on some touching
/// polytopes: an assertion in gjk_libccd-inl.h). For convex sets the signed distance is
///   max over unit u of  s(u) = min_{b in B} u.b - max_{a in A} u.a
/// (separating-axis theorem; minus the penetration depth on overlap), and every s(u) is a lower
/// bound. Candidates: the centre line, the given axes (polytope facet normals and edge crosses:
/// exact for polytope pairs), then projected gradient ascent of s on the unit sphere for smooth
/// shapes (the former fixed-point step u <- (a*(u) - b*(u)) / |...| is a descent step on overlap,
/// so it never improved s). The gradient for B's position is the best u.
template <int D>
Gap<D> support_gap(const ConvexPiece<D>& A, const ConvexPiece<D>& B, const Vec<D>& u0, const std::vector<Vec<D>>& axes,
                   bool axes_complete) {
  auto s = [&](const Vec<D>& u) { return u.dot(B.support(-u)) - u.dot(A.support(u)); };
  Vec<D> best_u = unit_or<D>(u0, Vec<D>::UnitX());
  double best = s(best_u);
  for (const Vec<D>& a : axes)
    for (const double sign : {1.0, -1.0}) {
      const Vec<D> u = sign * a;
      const double v = s(u);
      if (v > best) best = v, best_u = u;
    }
  // Projected gradient ascent on the unit sphere: the gradient of s is b*(-u) - a*(u); its
  // tangential part, in steps doubled on success and halved on failure.
  double step = 0.5;
  for (int it = 0; !axes_complete && it < 200 && step > 1e-12; ++it) {
    const Vec<D> g = B.support(-best_u) - A.support(best_u);
    const Vec<D> t = g - g.dot(best_u) * best_u;
    const double n = t.norm();
    if (!(n > 1e-15 * g.norm())) break;
    const Vec<D> u = (best_u + step * t / n).normalized();
    const double v = s(u);
    if (v > best) {
      best = v;
      best_u = u;
      step = std::min(2 * step, 0.5);
    } else {
      step *= 0.5;
    }
  }
  return {best, best_u};
}


/// Exact signed gap of two overlapping convex polytopes by the separating-axis theorem: the
/// largest separation over the candidate axes (facet normals, edge crosses), each axis' extent
/// read off the world vertices directly.
template <int D>
struct AxisSeparation {
  double along;    ///< how far b lies beyond a along u: min_b - max_a of the projections
  double against;  ///< how far b lies beyond a along -u: min_a - max_b
};

/// The separations of two vertex sets along the axis u, both ways.
template <int D>
AxisSeparation<D> separation_along(const std::vector<Vec<D>>& va, const std::vector<Vec<D>>& vb, const Vec<D>& u) {
  double max_a = -std::numeric_limits<double>::infinity(), min_a = std::numeric_limits<double>::infinity();
  double max_b = -std::numeric_limits<double>::infinity(), min_b = std::numeric_limits<double>::infinity();
  for (const Vec<D>& v : va) {
    const double x = u.dot(v);
    max_a = std::max(max_a, x);
    min_a = std::min(min_a, x);
  }
  for (const Vec<D>& v : vb) {
    const double x = u.dot(v);
    max_b = std::max(max_b, x);
    min_b = std::min(min_b, x);
  }
  return {min_b - max_a, min_a - max_b};
}

template <int D>
Gap<D> polytope_sat_gap(const std::vector<Vec<D>>& va, const std::vector<Vec<D>>& vb, const std::vector<Vec<D>>& axes,
                        const Vec<D>& u0) {
  Gap<D> best{-std::numeric_limits<double>::infinity(), unit_or<D>(u0, Vec<D>::UnitX())};
  auto consider = [&](const Vec<D>& u) {
    const AxisSeparation<D> s = separation_along<D>(va, vb, u);
    if (s.along > best.value) best = {s.along, u};                 // b beyond a along u
    if (s.against > best.value) best = {s.against, Vec<D>(-u)};    // along -u
  };
  consider(best.normal);
  for (const Vec<D>& u : axes) consider(u);
  return best;
}

/// Makes a lower bound g of the gap of two overlapping (or barely apart) convex FCL pieces
/// tight. support_gap's ascent stalls on ridges of s(u) (a polytope's edge or vertex against a
/// curved piece), and GJK alone cannot tell a slight overlap from a touch. So b is pulled out
/// along g's normal u until GJK is reliable (apart by more than `near`): the gap is convex in b's
/// position, so gap >= d_m - m (n_m . u), tight to O(m^2 curvature sin^2(angle(u, normal))).
/// Repeated along the normal found; the last pass (pulled along the best normal) is used: GJK's
/// nearest-point direction carries ~1e-4 of angular error on curved shapes, which spoils the
/// bound of a pull far off the normal.
template <int D>
void tighten_by_pulls(const fcl::CollisionGeometryd* ga, const fcl::Transform3d& ta, const fcl::CollisionGeometryd* gb,
                      const fcl::Transform3d& tb, const fcl::DistanceRequestd& request, double size, double near,
                      Gap<D>& g, std::uint64_t& queries) {
  Vec<D> dir = g.normal;
  double m = std::max(0.0, -g.value) + 1e-4 * size;
  Gap<D> pulled_gap;
  bool pulled_ok = false;
  for (int pass = 0, tries = 0; pass < 3 && tries < 12; ++tries) {
    fcl::Transform3d moved = tb;
    if constexpr (D == 2) moved.translation() += Eigen::Vector3d(m * dir[0], m * dir[1], 0.0);
    else moved.translation() += m * dir;
    fcl::DistanceResultd pulled;
    ++queries;
    fcl::distance(ga, ta, gb, moved, request, pulled);
    if (!(pulled.min_distance > near)) {  // still overlapping along dir: pull further
      m *= 2;
      continue;
    }
    const Vec<D> n = unit_or<D>(project<D>(pulled.nearest_points[1] - pulled.nearest_points[0]), dir);
    pulled_gap = {pulled.min_distance - m * n.dot(dir), n};
    pulled_ok = true;
    dir = n;
    m = std::max(0.0, -pulled_gap.value) + 1e-4 * size;
    ++pass;
  }
  if (pulled_ok && pulled_gap.value > g.value) g = pulled_gap;  // s(u) is a strict lower bound
}

/// Ellipsoids (ellipses) against ellipsoids and balls: Newton on the support functions
/// (contact/ellipsoid_gap.hpp) instead of FCL's GJK.
template <int D>
SmoothConvexBody<D> smooth_body(const Particle<D>& p) {
  return smooth_convex_body<D>(*p.shape, p.pose.rotation, p.pose.position);
}

template <int D>
Gap<D> smooth_gap(const Particle<D>& a, const Particle<D>& b) {
  return smooth_convex_gap<D>(smooth_body(a), smooth_body(b));
}

/// An ellipsoid with an ellipsoid or a sphere: the pairs registered for smooth_gap.
template <int D>
bool smooth_pair(const Particle<D>& a, const Particle<D>& b) {
  const bool ea = std::strcmp(a.shape->kind(), EllipsoidShape<D>::kKind) == 0;
  const bool eb = std::strcmp(b.shape->kind(), EllipsoidShape<D>::kKind) == 0;
  return (ea && (eb || std::strcmp(b.shape->kind(), SphereShape<D>::kKind) == 0)) ||
         (eb && std::strcmp(a.shape->kind(), SphereShape<D>::kKind) == 0);
}

bool is_ball_made(const char* kind) {
  const std::string k = kind;
  return k == "sphere" || k == "cluster" || k == "spherocylinder";
}

}  // namespace

template <int D>
NarrowPhase<D>::NarrowPhase() {
  add_pair("sphere", "sphere", sphere_sphere<D>);
  add_pair("spherocylinder", "spherocylinder", capsule_capsule<D>);
  add_pair("sphere", "spherocylinder", sphere_capsule<D>);
  add_pair("cluster", "cluster", ball_union_gap<D>);
  add_pair("cluster", "sphere", ball_union_gap<D>);
  add_pair("cluster", "spherocylinder", ball_union_gap<D>);
  add_pair(EllipsoidShape<D>::kKind, EllipsoidShape<D>::kKind, smooth_gap<D>);
  add_pair("sphere", EllipsoidShape<D>::kKind, smooth_gap<D>);
  add_pair(ConvexPolytopeShape<D>::kKind, SphereShape<D>::kKind, polytope_sphere<D>);
  add_pair(ConvexPolytopeShape<D>::kKind, ClusterShape<D>::kKind, polytope_cluster<D>);
}

template <int D>
NarrowPhase<D>::~NarrowPhase() = default;

template <int D>
void NarrowPhase<D>::forget(const Shape<D>* s) const {
  cache_.erase(s);
}

template <int D>
void NarrowPhase<D>::clear_cache() const {
  cache_.clear();
  unit_ = 0;  // no geometry left in the old unit
}

template <int D>
void NarrowPhase<D>::add_pair(const std::string& kind_a, const std::string& kind_b, PairGap gap) {
  memo_.clear();
  pairs_[{kind_a, kind_b}] = gap;
  if (kind_a != kind_b)
    pairs_[{kind_b, kind_a}] = [gap](const Particle<D>& a, const Particle<D>& b) {
      Gap<D> g = gap(b, a);  // gradient for a: flip it to get the one for b
      g.normal = -g.normal;
      return g;
    };
}

template <int D>
const typename NarrowPhase<D>::PairGap* NarrowPhase<D>::pair_of(const char* kind_a, const char* kind_b) const {
  for (const Memo& m : memo_)
    if (m.a == kind_a && m.b == kind_b) return m.gap;
  const auto it = pairs_.find({kind_a, kind_b});
  const PairGap* g = it == pairs_.end() ? nullptr : &it->second;
  memo_.push_back({kind_a, kind_b, g});
  return g;
}

namespace {
/// Both of the polytope kind (checked before fcl_of, which would build FCL geometry for shapes
/// whose gaps are all analytic).
template <int D>
bool polytope_kinds(const Particle<D>& a, const Particle<D>& b) {
  return std::strcmp(a.shape->kind(), ConvexPolytopeShape<D>::kKind) == 0 && std::strcmp(b.shape->kind(), ConvexPolytopeShape<D>::kKind) == 0;
}
}  // namespace

template <int D>
Gap<D> NarrowPhase<D>::gap(const Particle<D>& a, const Particle<D>& b) const {
  if (const PairGap* g = pair_of(a.shape->kind(), b.shape->kind())) return (*g)(a, b);
  if constexpr (D == 2)
    if (polytope_kinds(a, b)) {
      const FclShape& fa = fcl_of(a.shape);
      const FclShape& fb = fcl_of(b.shape);
      if (fa.convex_polytope && fb.convex_polytope) return polygon_gap(a, fa, b, fb);
    }
  return fcl_gap(a, b);
}

template <int D>
Gap<D> NarrowPhase<D>::polygon_gap(const Particle<D>& a, const FclShape& fa, const Particle<D>& b, const FclShape& fb) const {
  if constexpr (D == 2) {
    // Vertices relative to a's position (their digits kept far from the origin), in order.
    world_a_.clear(), world_b_.clear(), axes_scratch_.clear();
    const Vec2 offset = b.pose.position - a.pose.position;
    for (const Vec2& v : fa.vertices) world_a_.push_back(a.pose.rotation * v);
    for (const Vec2& v : fb.vertices) world_b_.push_back(offset + b.pose.rotation * v);
    for (const Vec2& n : fa.normals) axes_scratch_.push_back(a.pose.rotation * n);
    for (const Vec2& n : fb.normals) axes_scratch_.push_back(b.pose.rotation * n);
    // The edge normals are every separating axis: the largest separation is the gap on overlap
    // (minus the penetration depth), and apart polygons are as far as their nearest points.
    const Gap<2> sat = polytope_sat_gap<2>(world_a_, world_b_, axes_scratch_, offset);
    if (sat.value <= 0) return sat;
    Vec2 on_a, on_b;
    const double d = convex_polygon::apart_nearest(world_a_, world_b_, on_a, on_b);
    return {d, unit_or<2>(Vec2(on_b - on_a), sat.normal)};
  } else {
    (void)a, (void)fa, (void)b, (void)fb;
    return {};
  }
}

template <int D>
double NarrowPhase<D>::polytope_separation(const Particle<D>& a, const FclShape& fa, const Particle<D>& b, const FclShape& fb,
                                           double enough, bool edges) const {
  // Vertices relative to a's position: the projections keep their digits far from the origin.
  world_a_.clear(), world_b_.clear();
  const Vec<D> offset = b.pose.position - a.pose.position;
  for (const Vec<D>& v : fa.vertices) world_a_.push_back(a.pose.rotation * v);
  for (const Vec<D>& v : fb.vertices) world_b_.push_back(offset + b.pose.rotation * v);
  double best = -std::numeric_limits<double>::infinity();
  // s(u) along u and -u: how far b lies beyond a (or a beyond b) along the axis.
  const auto separation = [&](const Vec<D>& u) {
    const AxisSeparation<D> s = separation_along<D>(world_a_, world_b_, u);
    best = std::max({best, s.along, s.against});
    return best > enough;
  };
  if (separation(unit_or<D>(offset, Vec<D>::UnitX()))) return best;
  for (const Vec<D>& n : fa.normals)
    if (separation(a.pose.rotation * n)) return best;
  for (const Vec<D>& n : fb.normals)
    if (separation(b.pose.rotation * n)) return best;
  if constexpr (D == 3) {
    if (!edges) return best;
    for (const Vec3& ea : fa.polytope_edges)
      for (const Vec3& eb : fb.polytope_edges) {
        const Vec3 n = (a.pose.rotation * ea).cross(b.pose.rotation * eb);
        if (n.squaredNorm() > 1e-20 && separation(n.normalized())) return best;
      }
  }
  return best;
}

template <int D>
bool NarrowPhase<D>::overlap_beyond(const Particle<D>& a, const Particle<D>& b, double allowed) const {
  // The signed gap is at most that of the two inscribed balls (inside the shapes), and every gap
  // below is at most the true one (exact, or a separating-axis bound) but a cluster's, on overlap
  // the deepest member pair's: a deep overlap of the inscribed balls answers without computing it.
  const bool clusters = std::strcmp(a.shape->kind(), ClusterShape<D>::kKind) == 0 || std::strcmp(b.shape->kind(), ClusterShape<D>::kKind) == 0;
  if (!clusters && (b.pose.position - a.pose.position).norm() - a.shape->inscribed_radius() - b.shape->inscribed_radius() < -allowed)
    return true;
  if (polytope_kinds(a, b)) {
    const FclShape& fa = fcl_of(a.shape);
    const FclShape& fb = fcl_of(b.shape);
    if (fa.convex_polytope && fb.convex_polytope) return !(polytope_separation(a, fa, b, fb, -allowed, true) >= -allowed);
  }
  if (smooth_pair(a, b)) return smooth_convex_overlap_beyond<D>(smooth_body(a), smooth_body(b), allowed);
  return gap(a, b).value < -allowed;
}

template <int D>
bool NarrowPhase<D>::gap_exceeds(const Particle<D>& a, const Particle<D>& b, double d) const {
  // The gap is at most the signed distance of the two inscribed balls (inside the shapes): close
  // pairs, most of the front's questions, are answered without a distance query.
  const double balls = (b.pose.position - a.pose.position).norm() - a.shape->inscribed_radius() - b.shape->inscribed_radius();
  if (balls <= d) return false;
  // Face normals only: apart polytopes are usually separated best by one, and the bound need
  // not be tight (the distance query decides the rest).
  if (polytope_kinds(a, b)) {
    const FclShape& fa = fcl_of(a.shape);
    const FclShape& fb = fcl_of(b.shape);
    if (fa.convex_polytope && fb.convex_polytope) {
      const double s = polytope_separation(a, fa, b, fb, d, false);
      if (s > d) return true;
      if constexpr (D == 2) {
        // Every separating axis was tried (a polygon's edge normals are all of them): s <= 0 is
        // an overlap or a touch, s > 0 apart, where the vertex-edge distance is exact (FCL's
        // GJK on the prisms cost 5 % of a polygon packing here).
        if (s <= 0 && d >= 0) return false;
        // polytope_separation left the vertices, relative to a's position, in world_a_ and
        // world_b_, in order (ConvexPolytopeShape<2>: edges (i, i + 1)).
        if (s > 0) return convex_polygon::apart_distance(world_a_, world_b_) > d;
      }
    }
  }
  return gap(a, b).value > d;
}

template <int D>
const typename NarrowPhase<D>::FclShape& NarrowPhase<D>::fcl_of(const ShapePtr<D>& s) const {
  auto& slot = cache_[s.get()];
  if (!slot) {
    slot = std::make_unique<FclShape>();
    slot->keep_alive = s;
    const std::string kind = s->kind();
    if (kind == "cluster") slot->balls = s->hull_balls();
    if (kind == "polygon" || kind == "polyhedron" || kind == "facet") {
      const auto* poly = dynamic_cast<const ConvexPolytopeShape<D>*>(s.get());
      // A polytope's (facet's) hull balls are its vertices, and its surface its facets: read
      // from the polytope without copies (every draft tested for overlap comes here once).
      if (poly) {
        slot->vertices = poly->vertices();
      } else {
        for (const Ball<D>& v : s->hull_balls()) slot->vertices.push_back(v.center);
      }
      // Directions up to sign, each once (a triangulated cube has 3 face normals, not 12).
      auto add_unique = [](std::vector<Vec<D>>& list, const Vec<D>& v) {
        for (const Vec<D>& w : list)
          if (std::abs(std::abs(w.dot(v)) - 1) < 1e-12) return;
        list.push_back(v);
      };
      slot->convex_polytope = poly != nullptr;
      if constexpr (D == 3)
        if (poly)
          for (const auto& e : poly->edges())
            add_unique(slot->polytope_edges,
                       Vec3(poly->vertices()[static_cast<std::size_t>(e.b)] - poly->vertices()[static_cast<std::size_t>(e.a)]).normalized());
      const SurfaceMesh<D> facet_surface = poly ? SurfaceMesh<D>{} : s->surface(0);
      const std::vector<Vec<D>>& mesh_vertices = poly ? poly->vertices() : facet_surface.vertices;
      const std::vector<std::array<int, D>>& mesh_facets = poly ? poly->facets() : facet_surface.facets;
      for (const auto& f : mesh_facets) {
        if constexpr (D == 2) {
          const Vec2 e = mesh_vertices[static_cast<std::size_t>(f[1])] - mesh_vertices[static_cast<std::size_t>(f[0])];
          add_unique(slot->normals, Vec2(e.y(), -e.x()).normalized());
        } else {
          const Vec3& a = mesh_vertices[static_cast<std::size_t>(f[0])];
          const Vec3& b = mesh_vertices[static_cast<std::size_t>(f[1])];
          const Vec3& c = mesh_vertices[static_cast<std::size_t>(f[2])];
          add_unique(slot->normals, (b - a).cross(c - a).normalized());
          for (const Vec3& e : {Vec3(b - a), Vec3(c - b), Vec3(a - c)}) add_unique(slot->edges, e.normalized());
        }
      }
    }
  }
  return *slot;
}

template <int D>
double NarrowPhase<D>::fcl_unit(double size) const {
  if (!(unit_ > 0)) {
    // libccd's tolerances are absolute: a scene of size 2^-60 had its overlaps pass as contacts
    // (measured: 20 cylinders, 22 overlapping pairs, reported as none). Far from unit size, FCL
    // gets lengths scaled by a power of two (exact); near it, none (the same numbers as ever).
    const bool near_unit = size >= std::ldexp(1.0, -16) && size <= std::ldexp(1.0, 16);
    unit_ = near_unit || !(size > 0) || !std::isfinite(size) ? 1.0 : std::ldexp(1.0, std::ilogb(size));
  }
  return unit_;
}

template <int D>
Gap<D> NarrowPhase<D>::fcl_gap(const Particle<D>& a, const Particle<D>& b) const {
  const FclShape& fa = fcl_of(a.shape);
  const FclShape& fb = fcl_of(b.shape);
  fcl::DistanceRequestd request;
  request.enable_nearest_points = true;
  request.enable_signed_distance = false;  // GJK only: exact when apart; overlaps go to support_gap
  request.gjk_solver_type = fcl::GST_LIBCCD;
  // FCL's default GJK tolerance (1e-6, absolute) leaves curved shapes 1e-5 off: far coarser
  // than the contact tolerance. Relative to the pair's size instead.
  // Length scale: the smaller size (a vertex wall is a particle of radius 0: the other one's).
  const double ra = a.bounding_radius(), rb = b.bounding_radius();
  const double size = ra > 0 && rb > 0 ? std::min(ra, rb) : std::max(ra, rb);
  // FCL works in its own length unit (scaled lengths: `inv`), where the pair is about unit size.
  const double unit = fcl_unit(std::max(ra, rb)), inv = 1 / unit;
  request.distance_tolerance = 1e-10 * size * inv;  // 1e-8: GJK errors up to 3e-4 of the size on curved pairs (measured)
  // GJK in distance mode reports a tiny positive distance (~1e-16), not an overlap, when curved
  // shapes overlap slightly: its simplex converges onto the origin without enclosing it (always
  // for 2D shapes embedded in z = 0 whose support points stay in that plane). Distances this
  // small go to the overlap path below, which handles both signs.
  const double near = 1e-6 * size;
  // Separating-axis candidates of a polytope pair, in the world frame.
  std::vector<Vec<D>>& axes = axes_scratch_;
  axes.clear();
  auto add_axes = [&](const Particle<D>& p, const FclShape& f) {
    for (const Vec<D>& n : f.normals) axes.push_back(p.pose.rotation * n);
  };
  auto add_edge_crosses = [&] {
    if constexpr (D == 3) {
      for (const Vec3& ea : fa.edges)
        for (const Vec3& eb : fb.edges) {
          const Vec3 n = (a.pose.rotation * ea).cross(b.pose.rotation * eb);
          if (n.squaredNorm() > 1e-20) axes.push_back(n.normalized());
        }
    }
  };
  Gap<D> best{std::numeric_limits<double>::infinity(), Vec<D>::Zero()};
  const std::vector<FclPart<D>>& parts_a = fa.parts(unit);
  const std::vector<FclPart<D>>& parts_b = fb.parts(unit);
  Pose<D> pose_a = a.pose, pose_b = b.pose;  // in FCL's unit
  pose_a.position *= inv, pose_b.position *= inv;
  for (std::size_t i = 0; i < parts_a.size(); ++i)
    for (std::size_t j = 0; j < parts_b.size(); ++j) {
      const FclPart<D>& pa = parts_a[i];
      const FclPart<D>& pb = parts_b[j];
      fcl::DistanceResultd result;
      ++fcl_queries_;
      const fcl::Transform3d ta = part_transform(pose_a, pa), tb = part_transform(pose_b, pb);
      fcl::distance(pa.geometry.get(), ta, pb.geometry.get(), tb, request, result);
      Gap<D> g;
      if (result.min_distance * unit > near) {
        // Nearest points are in the world frame: b's point minus a's is the outward direction.
        g.value = result.min_distance * unit;
        g.normal = unit_or<D>(project<D>(result.nearest_points[1] - result.nearest_points[0]),
                              Vec<D>(b.pose.position - a.pose.position));
      } else {
        if (axes.empty()) {  // one side may be a polytope: its facet normals are good candidates
          add_axes(a, fa);
          add_axes(b, fb);
          add_edge_crosses();
        }
        if (!fa.vertices.empty() && !fb.vertices.empty()) {
          // Two polytopes: facet normals and edge crosses are every candidate axis (exact SAT).
          // (Used only on overlap: as ω when apart its switching axes tripled the minimiser's
          // evaluations against GJK's smooth distance, measured on cubes.)
          std::vector<Vec<D>>& wa = world_a_;
          std::vector<Vec<D>>& wb = world_b_;
          wa.clear();
          wb.clear();
          for (const Vec<D>& v : fa.vertices) wa.push_back(a.pose.to_world(v));
          for (const Vec<D>& v : fb.vertices) wb.push_back(b.pose.to_world(v));
          g = polytope_sat_gap<D>(wa, wb, axes, b.pose.position - a.pose.position);
        } else {
          const ConvexPiece<D> A{&a, fa.balls.empty() ? nullptr : &fa.balls[i]};
          const ConvexPiece<D> B{&b, fb.balls.empty() ? nullptr : &fb.balls[j]};
          g = support_gap<D>(A, B, b.pose.position - a.pose.position, axes, false);
          Gap<D> scaled{g.value * inv, g.normal};  // FCL's unit, and back
          tighten_by_pulls<D>(pa.geometry.get(), ta, pb.geometry.get(), tb, request, size * inv, near * inv, scaled, fcl_queries_);
          g = {scaled.value * unit, scaled.normal};
        }
      }
      if (g.value < best.value) best = g;
    }
  return best;
}

template <int D>
Gap<D> NarrowPhase<D>::gap(const Wall<D>& w, const Particle<D>& b) const {
  switch (w.kind) {
    case WallKind::Plane: {
      const Vec<D> x = b.support(-w.normal);
      return {w.normal.dot(x - w.point), w.normal};
    }
    case WallKind::Sphere:
    case WallKind::Cylinder: {
      // The particle inside a sphere (cylinder): its farthest point from the centre (axis) sits
      // on a hull ball, where a convex function of position peaks.
      Gap<D> best{std::numeric_limits<double>::infinity(), Vec<D>::Zero()};
      for (const Ball<D>& ball : b.shape->hull_balls()) {
        const Vec<D> c = b.pose.to_world(ball.center);
        Vec<D> d = c - w.point;
        if (w.kind == WallKind::Cylinder) d -= d.dot(w.axis) * w.axis;
        const double g = w.radius - d.norm() - ball.radius;
        if (g < best.value) best = {g, unit_or<D>(Vec<D>(-d), Vec<D>(w.point - b.pose.position))};
      }
      return best;
    }
    case WallKind::Vertex: {
      if (is_ball_made(b.shape->kind())) {
        Particle<D> point;
        point.shape = std::make_shared<SphereShape<D>>(0.0);
        point.pose.position = w.point;
        return ball_union_gap<D>(point, b);
      }
      Particle<D> point;
      point.shape = std::make_shared<SphereShape<D>>(0.0);
      point.pose.position = w.point;
      const Gap<D> g = fcl_gap(point, b);
      cache_.erase(point.shape.get());
      return g;
    }
  }
  return {};
}

template class NarrowPhase<2>;
template class NarrowPhase<3>;

}  // namespace fp
