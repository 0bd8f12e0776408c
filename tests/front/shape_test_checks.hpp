#pragma once
// Independent checks of packings of general shapes (tests/front/test_shape_front.cpp). They share
// no code with contact/ (narrow phase, FCL, containment, validation): they read each particle's
// shape parameters (or its surface / support function) and decide overlap and containment by
// themselves:
//  * balls, spherocylinders, clusters ("swept spheres"): exact gaps from long-double point and
//    segment distances;
//  * convex polygons / polyhedra: the separating-axis test (face normals and, in 3D, cross
//    products of edges) over the world vertices of Shape::surface(): exact for polytopes;
//  * everything else (ellipses, ellipsoids, cylinders, mixed pairs): (a) a conservative sampling
//    check, points of each surface (support points in many directions, plus an analytic grid on
//    cylinders) pushed inward by the tolerance must not be inside the other particle, both ways;
//    (b) the support-function separation sep(u) = -h_A(u) - h_B(-u), whose maximum over unit u is
//    the signed distance of two convex bodies (minus the penetration depth when they overlap):
//    sampled and refined, it gives a lower bound of the gap (used for "touches").
// Containment uses the closed-form / brute-force signed distances of front_test_util.hpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "front_test_util.hpp"
#include "shapes/cluster_shape.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/cylinder_shape.hpp"
#include "shapes/ellipsoid_shape.hpp"
#include "shapes/particle.hpp"
#include "shapes/sphere_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace fptest {

using LD = long double;
template <int D>
using VecL = Eigen::Matrix<long double, D, 1>;

template <int D>
VecL<D> to_ld(const Vec<D>& v) {
  return v.template cast<long double>();
}

/// World point of a body-frame point, in long double.
template <int D>
VecL<D> world_ld(const fp::Particle<D>& p, const Vec<D>& body) {
  return to_ld<D>(p.pose.position) + p.pose.rotation.template cast<long double>() * to_ld<D>(body);
}

// ---- swept spheres: balls, spherocylinders and clusters, exactly ---------------------------------

template <int D>
struct SweptSphere {
  VecL<D> a, b;  ///< segment (a == b for a ball)
  LD r;
};

/// The particle as a union of swept spheres, or nothing if it is not a ball, capsule or cluster.
template <int D>
std::optional<std::vector<SweptSphere<D>>> swept_spheres(const fp::Particle<D>& p) {
  const fp::Shape<D>* s = p.shape.get();
  if (const auto* b = dynamic_cast<const fp::SphereShape<D>*>(s)) {
    const VecL<D> c = to_ld<D>(p.pose.position);
    return std::vector<SweptSphere<D>>{{c, c, static_cast<LD>(b->radius())}};
  }
  if (const auto* c = dynamic_cast<const fp::SpherocylinderShape<D>*>(s))
    return std::vector<SweptSphere<D>>{{world_ld(p, c->end_a()), world_ld(p, c->end_b()), static_cast<LD>(c->radius())}};
  if (const auto* c = dynamic_cast<const fp::ClusterShape<D>*>(s)) {
    std::vector<SweptSphere<D>> out;
    for (const auto& m : c->members()) {
      const VecL<D> w = world_ld(p, m.center);
      out.push_back({w, w, static_cast<LD>(m.radius)});
    }
    return out;
  }
  return std::nullopt;
}

template <int D>
LD point_segment_distance(const VecL<D>& x, const VecL<D>& a, const VecL<D>& b) {
  const VecL<D> ab = b - a;
  const LD L2 = ab.squaredNorm();
  LD t = L2 > 0 ? (x - a).dot(ab) / L2 : 0;
  t = std::clamp<LD>(t, 0, 1);
  return (x - (a + t * ab)).norm();
}

/// Distance between segments [p1, q1] and [p2, q2] (Ericson, Real-Time Collision Detection 5.1.9),
/// any dimension, degenerate segments allowed.
template <int D>
LD segment_segment_distance(const VecL<D>& p1, const VecL<D>& q1, const VecL<D>& p2, const VecL<D>& q2) {
  const VecL<D> d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const LD a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const LD eps = 1e-30L;
  LD s = 0, t = 0;
  if (a <= eps && e <= eps) return r.norm();
  if (a <= eps) {
    t = std::clamp<LD>(f / e, 0, 1);
  } else {
    const LD c = d1.dot(r);
    if (e <= eps) {
      s = std::clamp<LD>(-c / a, 0, 1);
    } else {
      const LD b = d1.dot(d2), denom = a * e - b * b;
      s = denom > eps * a * e ? std::clamp<LD>((b * f - c * e) / denom, 0, 1) : 0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp<LD>(-c / a, 0, 1);
      } else if (t > 1) {
        t = 1;
        s = std::clamp<LD>((b - c) / a, 0, 1);
      }
    }
  }
  // Polish: the closest points of the two segments, each re-projected on the other once (guards
  // against the parallel case's arbitrary choice; distances only get smaller).
  VecL<D> c1 = p1 + s * d1, c2 = p2 + t * d2;
  LD d = (c1 - c2).norm();
  d = std::min(d, point_segment_distance<D>(p1, p2, q2));
  d = std::min(d, point_segment_distance<D>(q1, p2, q2));
  d = std::min(d, point_segment_distance<D>(p2, p1, q1));
  d = std::min(d, point_segment_distance<D>(q2, p1, q1));
  return d;
}

/// Exact gap between two unions of swept spheres (negative: the deepest member overlap).
template <int D>
LD swept_gap(const std::vector<SweptSphere<D>>& A, const std::vector<SweptSphere<D>>& B) {
  LD g = std::numeric_limits<LD>::infinity();
  for (const auto& x : A)
    for (const auto& y : B) g = std::min(g, segment_segment_distance<D>(x.a, x.b, y.a, y.b) - x.r - y.r);
  return g;
}

// ---- polytopes: separating-axis test ----------------------------------------------------------

template <int D>
struct WorldPolytope {
  std::vector<VecL<D>> vertices;
  std::vector<VecL<D>> normals;  ///< unit face normals (deduplicated up to sign)
  std::vector<VecL<D>> edges;    ///< 3D: unit edge directions (deduplicated up to sign)
};

template <int D>
void add_direction(std::vector<VecL<D>>& dirs, VecL<D> d) {
  const LD n = d.norm();
  if (n < 1e-12L) return;
  d /= n;
  for (const auto& e : dirs)
    if (std::abs(std::abs(e.dot(d)) - 1) < 1e-12L) return;
  dirs.push_back(d);
}

/// World vertices (the surface's), face normals and edges of a polytope particle, or nothing.
template <int D>
std::optional<WorldPolytope<D>> world_polytope(const fp::Particle<D>& p) {
  if (!dynamic_cast<const fp::ConvexPolytopeShape<D>*>(p.shape.get())) return std::nullopt;
  const fp::SurfaceMesh<D> m = p.shape->surface(0);
  WorldPolytope<D> w;
  for (const Vec<D>& v : m.vertices) w.vertices.push_back(world_ld(p, v));
  for (const auto& f : m.facets) {
    if constexpr (D == 2) {
      const VecL<2> e = w.vertices[static_cast<std::size_t>(f[1])] - w.vertices[static_cast<std::size_t>(f[0])];
      add_direction<2>(w.normals, VecL<2>(e.y(), -e.x()));
    } else {
      const VecL<3>& a = w.vertices[static_cast<std::size_t>(f[0])];
      const VecL<3>& b = w.vertices[static_cast<std::size_t>(f[1])];
      const VecL<3>& c = w.vertices[static_cast<std::size_t>(f[2])];
      add_direction<3>(w.normals, (b - a).cross(c - a));
      add_direction<3>(w.edges, b - a);
      add_direction<3>(w.edges, c - b);
      add_direction<3>(w.edges, a - c);
    }
  }
  return w;
}

/// Largest separation of the two vertex sets' projections over the candidate axes (SAT). For
/// convex polytopes: the negative of the penetration depth when they overlap; a lower bound of
/// the distance when they do not.
template <int D>
LD sat_separation(const WorldPolytope<D>& A, const WorldPolytope<D>& B) {
  LD best = -std::numeric_limits<LD>::infinity();
  auto along = [&](const VecL<D>& n) {
    LD amin = std::numeric_limits<LD>::infinity(), amax = -amin, bmin = amin, bmax = -amin;
    for (const auto& v : A.vertices) {
      const LD x = n.dot(v);
      amin = std::min(amin, x);
      amax = std::max(amax, x);
    }
    for (const auto& v : B.vertices) {
      const LD x = n.dot(v);
      bmin = std::min(bmin, x);
      bmax = std::max(bmax, x);
    }
    best = std::max(best, std::max(bmin - amax, amin - bmax));
  };
  for (const auto& n : A.normals) along(n);
  for (const auto& n : B.normals) along(n);
  if constexpr (D == 3)
    for (const auto& ea : A.edges)
      for (const auto& eb : B.edges) {
        VecL<3> n = ea.cross(eb);
        const LD len = n.norm();
        if (len < 1e-9L) continue;
        along(n / len);
      }
  return best;
}

// ---- any convex shapes: support functions and sampling -------------------------------------------

/// Unit directions: n uniform angles (2D) or a Fibonacci sphere of n points (3D), plus the axes.
template <int D>
std::vector<Vec<D>> directions(int n) {
  std::vector<Vec<D>> out;
  for (int k = 0; k < D; ++k) {
    Vec<D> e = Vec<D>::Zero();
    e[k] = 1;
    out.push_back(e);
    out.push_back(-e);
  }
  for (int i = 0; i < n; ++i) {
    if constexpr (D == 2) {
      const double t = 2 * fp::kPi * (i + 0.5) / n;
      out.push_back(Vec2(std::cos(t), std::sin(t)));
    } else {
      const double z = 1 - (2.0 * i + 1) / n, s = std::sqrt(std::max(0.0, 1 - z * z));
      const double phi = i * fp::kPi * (3 - std::sqrt(5.0));
      out.push_back(Vec3(s * std::cos(phi), s * std::sin(phi), z));
    }
  }
  return out;
}

/// A point of the particle's surface with its outward unit normal (world frame).
template <int D>
struct SurfacePoint {
  Vec<D> x, normal;
};

/// Surface samples: support points along `dirs` (normal = the direction), and for cylinders an
/// analytic grid over the caps and the side (support points only reach the rims).
template <int D>
std::vector<SurfacePoint<D>> surface_samples(const fp::Particle<D>& p, const std::vector<Vec<D>>& dirs) {
  std::vector<SurfacePoint<D>> out;
  for (const Vec<D>& u : dirs) out.push_back({p.support(u), u});
  if constexpr (D == 3) {
    if (const auto* c = dynamic_cast<const fp::CylinderShape*>(p.shape.get())) {
      const double r = c->radius(), h = c->half_height();
      const int na = 24, nr = 4, nh = 8;
      for (int i = 0; i < na; ++i) {
        const double t = 2 * fp::kPi * (i + 0.25) / na;
        const Vec3 radial(0, std::cos(t), std::sin(t));
        for (int j = 0; j <= nh; ++j) {  // side
          const double x = -h + 2 * h * j / nh;
          out.push_back({p.pose.to_world(Vec3(x, r * radial.y(), r * radial.z())), p.pose.rotation * radial});
        }
        for (int j = 0; j < nr; ++j) {  // caps
          const double rho = r * j / nr;
          for (double s : {-1.0, 1.0})
            out.push_back({p.pose.to_world(Vec3(s * h, rho * radial.y(), rho * radial.z())), p.pose.rotation * Vec3(s, 0, 0)});
        }
      }
    }
  }
  return out;
}

/// Sampling check of A against B: the largest depth (along the inward normal) at which a surface
/// sample of A, pushed inward by `eps`, is still inside B; 0 if none is. Conservative: it can
/// miss an overlap smaller than the sampling, never report one that is not there.
template <int D>
double sampled_intrusion(const fp::Particle<D>& A, const fp::Particle<D>& B, const std::vector<Vec<D>>& dirs, double eps) {
  double worst = 0;
  for (const SurfacePoint<D>& s : surface_samples(A, dirs)) {
    if (!B.contains(s.x - eps * s.normal)) continue;
    // Inside: how much further inward does it stay inside B (bisection, for the report)?
    double lo = eps, hi = 2 * B.bounding_radius();
    for (int it = 0; it < 40; ++it) {
      const double mid = 0.5 * (lo + hi);
      (B.contains(s.x - mid * s.normal) ? lo : hi) = mid;
    }
    worst = std::max(worst, lo);
  }
  return worst;
}

/// sep(u) = -h_A(u) - h_B(-u) for unit u (support functions of the world particles).
template <int D>
double support_separation(const fp::Particle<D>& A, const fp::Particle<D>& B, const Vec<D>& u) {
  return -(u.dot(A.support(u)) + (-u).dot(B.support(-u)));
}

/// Refines sep(u) from u by a pattern search on the unit sphere (steps halved down to 1e-12 rad).
template <int D>
double refine_separation(const fp::Particle<D>& A, const fp::Particle<D>& B, Vec<D> u, double best) {
  if constexpr (D == 2) {
    double t = std::atan2(u.y(), u.x());
    for (double step = 0.05; step > 1e-12;) {
      bool improved = false;
      for (double dt : {-step, step}) {
        const double s = support_separation(A, B, Vec2(std::cos(t + dt), std::sin(t + dt)));
        if (s > best) best = s, t += dt, improved = true;
      }
      if (!improved) step *= 0.5;
    }
  } else {
    for (double step = 0.05; step > 1e-12;) {
      bool improved = false;
      Vec3 e1 = std::abs(u.x()) < 0.9 ? Vec3::UnitX().cross(u) : Vec3::UnitY().cross(u);
      e1.normalize();
      const Vec3 e2 = u.cross(e1);
      for (int k = 0; k < 16 && !improved; ++k) {  // 16 tangent directions: ridges are crossed
        const double a = 2 * fp::kPi * k / 16;
        const Vec3 v = (std::cos(step) * u + std::sin(step) * (std::cos(a) * e1 + std::sin(a) * e2)).normalized();
        const double s = support_separation(A, B, v);
        if (s > best) best = s, u = v, improved = true;
      }
      if (!improved) step *= 0.5;
    }
  }
  return best;
}

/// The axes of a cylinder or spherocylinder particle (world), for the candidate normals.
template <int D>
std::optional<Vec<D>> shape_axis(const fp::Particle<D>& p) {
  if constexpr (D == 3)
    if (dynamic_cast<const fp::CylinderShape*>(p.shape.get())) return Vec3(p.pose.rotation.col(0));
  return std::nullopt;
}

/// Max of sep(u) over unit u: sampled (plus the cylinders' axes and their cross product), then
/// the best few refined. A lower bound of the signed distance of two convex bodies (which it
/// equals at the true maximum).
template <int D>
double support_gap_lower_bound(const fp::Particle<D>& A, const fp::Particle<D>& B, const std::vector<Vec<D>>& dirs) {
  std::vector<Vec<D>> cand = dirs;
  const Vec<D> c = B.position() - A.position();
  if (c.norm() > 0) cand.push_back(c.normalized());
  const auto aa = shape_axis(A), ab = shape_axis(B);
  for (const auto& ax : {aa, ab})
    if (ax) {
      cand.push_back(*ax);
      cand.push_back(-*ax);
    }
  if constexpr (D == 3)
    if (aa && ab && aa->cross(*ab).norm() > 1e-9) {
      const Vec3 n = aa->cross(*ab).normalized();
      cand.push_back(n);
      cand.push_back(-n);
    }
  std::vector<std::pair<double, int>> scored;
  for (std::size_t k = 0; k < cand.size(); ++k) scored.push_back({support_separation(A, B, cand[k]), static_cast<int>(k)});
  const std::size_t keep = std::min<std::size_t>(6, scored.size());
  std::partial_sort(scored.begin(), scored.begin() + static_cast<std::ptrdiff_t>(keep), scored.end(),
                    [](const auto& x, const auto& y) { return x.first > y.first; });
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < keep; ++k)
    best = std::max(best, refine_separation(A, B, cand[static_cast<std::size_t>(scored[k].second)], scored[k].first));
  return best;
}

// ---- one pair, any shapes -------------------------------------------------------------------

struct PairCheck {
  double gap_lower = 0;    ///< a lower bound of the gap (exact for swept spheres and, if < 0, polytopes)
  double intrusion = 0;    ///< sampling check: deepest sample of one inside the other (0 if exact methods apply)
  /// False for pairs with a cylinder: sep(u) has ridges (rims, cap edges) where the pattern
  /// search stalls (measured: -3e-4 R from 600 directions on a touching pair, -3e-6 R from 4e5);
  /// their overlap is then judged by the sampling check alone.
  bool tight = true;
  const char* method = "";
};

template <int D>
PairCheck check_pair(const fp::Particle<D>& A, const fp::Particle<D>& B, const std::vector<Vec<D>>& dirs, double eps) {
  PairCheck c;
  const auto sa = swept_spheres(A), sb = swept_spheres(B);
  if (sa && sb) {
    c.gap_lower = static_cast<double>(swept_gap<D>(*sa, *sb));
    c.method = "swept spheres";
    return c;
  }
  const auto pa = world_polytope(A), pb = world_polytope(B);
  if (pa && pb) {
    c.gap_lower = static_cast<double>(sat_separation<D>(*pa, *pb));
    c.method = "separating axes";
    return c;
  }
  c.method = "sampling + support separation";
  c.intrusion = std::max(sampled_intrusion(A, B, dirs, eps), sampled_intrusion(B, A, dirs, eps));
  c.gap_lower = support_gap_lower_bound(A, B, dirs);
  c.tight = !shape_axis(A) && !shape_axis(B);
  return c;
}

// ---- a whole packing --------------------------------------------------------------------------

struct ShapeOverlapReport {
  double max_overlap_rel = 0;     ///< max over pairs of -gap_lower / min(Ri, Rj) (0 if none overlap)
  double max_intrusion_rel = 0;   ///< max sampled intrusion / min(Ri, Rj)
  double max_loose_overlap_rel = 0;  ///< same as max_overlap_rel over the pairs whose bound is not tight (cylinders)
  int worst_i = -1, worst_j = -1;
  std::size_t pairs = 0;          ///< pairs whose circumscribed spheres meet
  std::vector<double> nearest_gap_rel;  ///< per particle: least gap_lower / own R over its close pairs (+inf if none)
};

/// Every pair whose circumscribed spheres come within `margin_rel` R of each other.
template <int D>
ShapeOverlapReport shape_overlaps(const fp::ShapePacking<D>& P, double eps_rel, int n_dirs = D == 2 ? 360 : 600,
                                  double margin_rel = 1e-3) {
  ShapeOverlapReport rep;
  const auto& ps = P.particles;
  const std::vector<Vec<D>> dirs = directions<D>(n_dirs);
  rep.nearest_gap_rel.assign(ps.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < ps.size(); ++i)
    for (std::size_t j = i + 1; j < ps.size(); ++j) {
      const double Ri = ps[i].bounding_radius(), Rj = ps[j].bounding_radius();
      const double d = (ps[i].position() - ps[j].position()).norm();
      if (d > (Ri + Rj) * (1 + margin_rel)) continue;
      ++rep.pairs;
      const double rmin = std::min(Ri, Rj);
      const PairCheck c = check_pair(ps[i], ps[j], dirs, eps_rel * rmin);
      if (!c.tight) {
        rep.max_loose_overlap_rel = std::max(rep.max_loose_overlap_rel, -c.gap_lower / rmin);
      } else if (-c.gap_lower / rmin > rep.max_overlap_rel) {
        rep.max_overlap_rel = -c.gap_lower / rmin;
        rep.worst_i = static_cast<int>(i);
        rep.worst_j = static_cast<int>(j);
      }
      rep.max_intrusion_rel = std::max(rep.max_intrusion_rel, c.intrusion / rmin);
      rep.nearest_gap_rel[i] = std::min(rep.nearest_gap_rel[i], c.gap_lower / Ri);
      rep.nearest_gap_rel[j] = std::min(rep.nearest_gap_rel[j], c.gap_lower / Rj);
    }
  return rep;
}

/// Is the world point x inside the particle deeper than eps? Exact for swept spheres; for the
/// other (convex) shapes: the 2D points x +- sqrt(D) eps e_k are all contained.
template <int D>
bool strictly_inside(const fp::Particle<D>& p, const Vec<D>& x, double eps) {
  if ((x - p.position()).norm() > p.bounding_radius() + eps) return false;
  if (const auto s = swept_spheres(p)) {
    for (const auto& m : *s)
      if (m.r - point_segment_distance<D>(to_ld<D>(x), m.a, m.b) > eps) return true;
    return false;
  }
  const double h = std::sqrt(double(D)) * eps;
  for (int k = 0; k < D; ++k)
    for (double s : {-h, h}) {
      Vec<D> y = x;
      y[k] += s;
      if (!p.contains(y)) return false;
    }
  return true;
}

template <int D>
struct ShapeContainmentReport {
  double max_outside_rel = -std::numeric_limits<double>::infinity();  ///< max (sd of a sample) / R
  int worst = -1;
  std::size_t boundary_points_inside = 0;  ///< container boundary samples strictly inside a particle
  int worst_boundary_particle = -1;
  Vec<D> worst_boundary_point = Vec<D>::Zero();   ///< one boundary point found inside that particle
  std::vector<double> wall_gap_rel;        ///< per particle: -max sd over its samples / R (>= 0 inside)
};

/// Every particle against the container's (independent) signed distance: support points along
/// many directions and along the walls' normals, and the hull balls (sd(centre) + radius). For a
/// non-convex container, `boundary_points` (its vertices and points along its edges) must not
/// be strictly inside any particle.
template <int D>
ShapeContainmentReport<D> shape_containment(const fp::ShapePacking<D>& P, const SignedDistance<D>& sd,
                                         const std::vector<Vec<D>>& wall_normals, const std::vector<Vec<D>>& boundary_points,
                                         double eps_rel, int n_dirs = D == 2 ? 360 : 600) {
  ShapeContainmentReport<D> rep;
  std::vector<Vec<D>> dirs = directions<D>(n_dirs);
  for (const Vec<D>& n : wall_normals) {
    dirs.push_back(n.normalized());
    dirs.push_back(-n.normalized());
  }
  const auto& ps = P.particles;
  rep.wall_gap_rel.assign(ps.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const fp::Particle<D>& p = ps[i];
    const double R = p.bounding_radius();
    double most = -std::numeric_limits<double>::infinity();
    for (const SurfacePoint<D>& s : surface_samples(p, dirs)) most = std::max(most, sd(s.x, P.origin));
    // Hull balls of swept-sphere shapes and polytopes are exact (their members, their vertices);
    // an ellipsoid's or a cylinder's are points of a circumscribing polytope, up to 0.5 % outside
    // the shape, and the packer lets the shape itself touch a wall of a box or a convex polygon:
    // their surface samples above (support points along the walls' normals among them) decide.
    const bool circumscribing = dynamic_cast<const fp::EllipsoidShape<D>*>(p.shape.get()) != nullptr;
    bool cylinder = false;
    if constexpr (D == 3) cylinder = dynamic_cast<const fp::CylinderShape*>(p.shape.get()) != nullptr;
    if (!circumscribing && !cylinder)
      for (const fp::Ball<D>& b : p.shape->hull_balls()) most = std::max(most, sd(p.pose.to_world(b.center), P.origin) + b.radius);
    if (most / R > rep.max_outside_rel) {
      rep.max_outside_rel = most / R;
      rep.worst = static_cast<int>(i);
    }
    rep.wall_gap_rel[i] = -most / R;
    for (const Vec<D>& x : boundary_points)
      if (strictly_inside(p, Vec<D>(x - P.origin), eps_rel * R)) {  // boundary points are absolute
        ++rep.boundary_points_inside;
        rep.worst_boundary_particle = static_cast<int>(i);
        rep.worst_boundary_point = x;
      }
  }
  return rep;
}

/// Points along the segments (a, b) (n per segment, end points included).
template <int D>
std::vector<Vec<D>> points_along(const std::vector<std::pair<Vec<D>, Vec<D>>>& segments, int n) {
  std::vector<Vec<D>> out;
  for (const auto& [a, b] : segments)
    for (int k = 0; k <= n; ++k) out.push_back(a + (b - a) * (double(k) / n));
  return out;
}

}  // namespace fptest
