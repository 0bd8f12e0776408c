#pragma once
// Shared helpers of the general-shape contact tests (minimisation solver, narrow phase, solver
// registry). The point of this header is INDEPENDENCE: every gap it computes is long double and
// uses neither contact/narrow_phase.cpp, contact/segment_distance.hpp, FCL nor the shapes'
// support()/hull_balls(); it reads only the shapes' defining parameters (radii, half-lengths,
// members, vertices, semi-axes) and the poses.
//
//  * RefBody: a placed particle as convex pieces in world coordinates (long double):
//      swept   = segment + radius (sphere: a point segment; spherocylinder; each cluster member),
//      polytope = vertices + facets (+ face planes and edges computed here),
//      ellipsoid = centre + rotation + semi-axes,   cylinder = centre + axis + radius + half-height.
//  * ref_gap(A, B): the signed gap, minimum over piece pairs, by methods unlike the solver's:
//      swept-swept    nested golden-section searches over both segment parameters (dense seeds);
//      swept-X        golden-section over the segment parameter of X's signed point distance
//                     (ellipsoid: the Lagrange-multiplier root by bisection; polytope: face planes,
//                     point-triangle distances; cylinder: radial/axial distances);
//      2D otherwise   Minkowski's formula  gap = max_{|u|=1} -(h_A(u) + h_B(-u))  over a dense
//                     set of angles refined by golden section (exact for convex pieces, both signs);
//      3D polytopes   separating axes (face normals, edge cross products) for the depth, vertex-face
//                     and edge-edge distances when apart;
//      3D ellipsoids  Minkowski's formula over a Fibonacci sphere refined by pattern search;
//      3D ellipsoid-polytope/cylinder: the least signed distance of the other piece over the
//                     ellipsoid's surface, sampled through its support map.
//    `exact` tells whether the value is the true signed distance (always when apart; on overlap
//    only for the methods marked exact above); otherwise it has the right sign and is exact to
//    first order in the overlap.
//  * ref_wall_gap: plane (own support function), sphere and cylinder walls (farthest point from
//    the centre / axis as a maximum over directions of the support function).
//  * Problem / construct_problem: fixed bodies placed so that a known position touches them all;
//    check_placements: every returned position touches every body (|gap| <= tol * min sizes),
//    with the configuration printed as C++ ready to paste on failure (style.md habit 10).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "contact/body.hpp"
#include "contact/contact_solver.hpp"
#include "contact/minimisation_solver.hpp"
#include "contact/narrow_phase.hpp"
#include "contact/sphere_contact_solver.hpp"
#include "core/sampling/rng.hpp"
#include "shapes/cluster_shape.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/cylinder_shape.hpp"
#include "shapes/ellipsoid_shape.hpp"
#include "shapes/shape_registry.hpp"
#include "shapes/sphere_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace fp::general_test {

using LD = long double;
template <int D>
using VL = Eigen::Matrix<LD, D, 1>;
template <int D>
using ML = Eigen::Matrix<LD, D, D>;
inline constexpr LD kPiL = 3.141592653589793238462643383279502884L;
inline constexpr LD kInfL = std::numeric_limits<LD>::infinity();

template <int D>
VL<D> ld(const Vec<D>& v) {
  return v.template cast<LD>();
}

// ===================================================================================== searches

/// Minimum of f over [lo, hi]: `samples` + 1 equally spaced values, then golden-section search in
/// the two cells around the best one. Exact (to the long-double resolution) for unimodal f.
template <class F>
std::pair<LD, LD> minimise_1d(F&& f, LD lo, LD hi, int samples = 24, int iterations = 100) {
  int best = 0;
  LD best_value = kInfL;
  for (int k = 0; k <= samples; ++k) {
    const LD v = f(lo + (hi - lo) * k / samples);
    if (v < best_value) best_value = v, best = k;
  }
  LD a = lo + (hi - lo) * std::max(0, best - 1) / samples;
  LD b = lo + (hi - lo) * std::min(samples, best + 1) / samples;
  LD best_t = lo + (hi - lo) * best / samples;
  const LD g = (std::sqrt(5.0L) - 1) / 2;
  LD c = b - g * (b - a), d = a + g * (b - a);
  LD fc = f(c), fd = f(d);
  for (int it = 0; it < iterations && b - a > 0; ++it) {
    if (fc <= fd) {
      b = d, d = c, fd = fc;
      c = b - g * (b - a);
      fc = f(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + g * (b - a);
      fd = f(d);
    }
  }
  if (fc < best_value) best_value = fc, best_t = c;
  if (fd < best_value) best_value = fd, best_t = d;
  return {best_t, best_value};
}

/// Optimum of f over the unit circle (f of an angle): dense angles, golden section around the
/// three best separated samples.
template <class F>
LD optimise_circle(F&& f, bool maximise, int samples = 720) {
  const LD s = maximise ? -1 : 1;
  std::vector<std::pair<LD, int>> v(samples);
  for (int k = 0; k < samples; ++k) v[k] = {s * f(2 * kPiL * k / samples), k};
  std::sort(v.begin(), v.end());
  LD best = v[0].first;
  std::vector<int> tried;
  for (const auto& [value, k] : v) {
    if (tried.size() >= 3) break;
    bool near = false;
    for (int t : tried) near |= std::min((k - t + samples) % samples, (t - k + samples) % samples) <= 2;
    if (near) continue;
    tried.push_back(k);
    const LD th = 2 * kPiL * k / samples, dth = 2 * kPiL / samples;
    best = std::min(best, minimise_1d([&](LD t) { return s * f(t); }, th - dth, th + dth, 4, 100).second);
  }
  return s * best;
}

/// Optimum of f over the unit sphere (f of a unit vector): a Fibonacci set of directions, then a
/// pattern search (8 tangent directions, turning each round, step halved on failure) from the
/// three best separated samples. Meant for smooth f or f with convex-type kinks when maximising.
template <class F>
LD optimise_sphere(F&& f, bool maximise, int samples = 1500) {
  const LD s = maximise ? -1 : 1;
  auto g = [&](const VL<3>& u) { return s * f(u); };
  const LD golden_angle = kPiL * (3 - std::sqrt(5.0L));
  std::vector<VL<3>> dirs(samples);
  std::vector<std::pair<LD, int>> v(samples);
  for (int i = 0; i < samples; ++i) {
    const LD z = 1 - (2 * i + 1) / LD(samples), r = std::sqrt(std::max(LD(0), 1 - z * z)), phi = i * golden_angle;
    dirs[i] = VL<3>(r * std::cos(phi), r * std::sin(phi), z);
    v[i] = {g(dirs[i]), i};
  }
  std::sort(v.begin(), v.end());
  const LD spacing = std::sqrt(4 * kPiL / samples);
  LD best = v[0].first;
  std::vector<int> tried;
  for (const auto& [value0, i0] : v) {
    if (tried.size() >= 3) break;
    bool near = false;
    for (int t : tried) near |= (dirs[t] - dirs[i0]).norm() < 3 * spacing;
    if (near) continue;
    tried.push_back(i0);
    VL<3> u = dirs[i0];
    LD fu = value0, h = spacing;
    for (int round = 0; round < 4000 && h > 1e-11L; ++round) {
      const VL<3> a = std::abs(u[0]) < 0.6L ? VL<3>(1, 0, 0) : VL<3>(0, 1, 0);
      const VL<3> e1 = u.cross(a).normalized(), e2 = u.cross(e1);
      VL<3> best_u = u;
      LD best_f = fu;
      for (int k = 0; k < 8; ++k) {
        const LD phi = kPiL / 4 * k + 0.3819L * round;
        const VL<3> w = (u + h * (std::cos(phi) * e1 + std::sin(phi) * e2)).normalized();
        const LD fw = g(w);
        if (fw < best_f) best_f = fw, best_u = w;
      }
      if (best_f < fu) u = best_u, fu = best_f, h *= 1.5L;
      else h *= 0.5L;
    }
    best = std::min(best, fu);
  }
  return s * best;
}

// ============================================================================ placed particles

enum class PieceKind { Swept, Polytope, Ellipsoid, Cylinder };

template <int D>
struct Piece {
  PieceKind kind = PieceKind::Swept;
  // Swept: segment [p0, p1] + radius. Cylinder: p0 = centre, p1 = unit axis.
  VL<D> p0 = VL<D>::Zero(), p1 = VL<D>::Zero();
  LD radius = 0, half_height = 0;
  // Polytope (world frame).
  std::vector<VL<D>> verts;
  std::vector<std::array<int, D>> facets;
  std::vector<VL<D>> normals;  ///< outward, unit, one per facet
  std::vector<LD> offsets;     ///< n . x <= offset inside
  std::vector<std::pair<int, int>> edges;
  // Ellipsoid: centre p0, rotation (body -> world), semi-axes.
  ML<D> rot = ML<D>::Identity();
  VL<D> axes = VL<D>::Zero();
};

template <int D>
struct RefBody {
  std::vector<Piece<D>> pieces;
};

template <int D>
Piece<D> swept_piece(const VL<D>& a, const VL<D>& b, LD r) {
  Piece<D> p;
  p.kind = PieceKind::Swept;
  p.p0 = a;
  p.p1 = b;
  p.radius = r;
  return p;
}

/// The independent description of a placed particle (fails the test on an unknown shape class).
template <int D>
RefBody<D> ref_of(const Particle<D>& p) {
  RefBody<D> body;
  const VL<D> c = ld<D>(p.pose.position);
  const ML<D> R = p.pose.rotation.template cast<LD>();
  auto world = [&](const Vec<D>& x) -> VL<D> { return c + R * ld<D>(x); };
  const Shape<D>* s = p.shape.get();
  if (auto* sp = dynamic_cast<const SphereShape<D>*>(s)) {
    body.pieces.push_back(swept_piece<D>(c, c, sp->radius()));
  } else if (auto* sc = dynamic_cast<const SpherocylinderShape<D>*>(s)) {
    body.pieces.push_back(swept_piece<D>(world(sc->end_a()), world(sc->end_b()), sc->radius()));
  } else if (auto* cl = dynamic_cast<const ClusterShape<D>*>(s)) {
    for (const Ball<D>& b : cl->members()) body.pieces.push_back(swept_piece<D>(world(b.center), world(b.center), b.radius));
  } else if (auto* po = dynamic_cast<const ConvexPolytopeShape<D>*>(s)) {
    Piece<D> q;
    q.kind = PieceKind::Polytope;
    for (const Vec<D>& v : po->vertices()) q.verts.push_back(world(v));
    q.facets = po->facets();
    for (const auto& f : q.facets) {
      VL<D> n;
      if constexpr (D == 2) {
        const VL<2> e = q.verts[f[1]] - q.verts[f[0]];
        n = VL<2>(e.y(), -e.x());
      } else {
        n = (q.verts[f[1]] - q.verts[f[0]]).cross(q.verts[f[2]] - q.verts[f[0]]);
      }
      n.normalize();
      LD h = -kInfL;
      for (const VL<D>& v : q.verts) h = std::max(h, n.dot(v));
      q.normals.push_back(n);
      q.offsets.push_back(h);
      for (int i = 0; i < D; ++i) {
        const int a = f[i], b = f[(i + 1) % D];
        const std::pair<int, int> e(std::min(a, b), std::max(a, b));
        if (std::find(q.edges.begin(), q.edges.end(), e) == q.edges.end()) q.edges.push_back(e);
      }
    }
    body.pieces.push_back(std::move(q));
  } else if (auto* el = dynamic_cast<const EllipsoidShape<D>*>(s)) {
    Piece<D> q;
    q.kind = PieceKind::Ellipsoid;
    q.p0 = c;
    q.rot = R;
    q.axes = ld<D>(el->semi_axes());
    body.pieces.push_back(q);
  } else if (auto* cy = [&]() -> const CylinderShape* {
               if constexpr (D == 3) return dynamic_cast<const CylinderShape*>(s);
               else return nullptr;
             }()) {
    Piece<D> q;
    q.kind = PieceKind::Cylinder;
    q.p0 = c;
    q.p1 = R.col(0);
    q.radius = cy->radius();
    q.half_height = cy->half_height();
    body.pieces.push_back(q);
  } else {
    ADD_FAILURE() << "general_contact_support: no reference for shape kind '" << s->kind() << "'";
  }
  return body;
}

// --------------------------------------------------------------------- support and distances

/// World support point of a piece along u (u need not be unit; u != 0).
template <int D>
VL<D> support(const Piece<D>& p, const VL<D>& u) {
  switch (p.kind) {
    case PieceKind::Swept: return (u.dot(p.p0) >= u.dot(p.p1) ? p.p0 : p.p1) + p.radius * u / u.norm();
    case PieceKind::Polytope: {
      std::size_t best = 0;
      for (std::size_t i = 1; i < p.verts.size(); ++i)
        if (u.dot(p.verts[i]) > u.dot(p.verts[best])) best = i;
      return p.verts[best];
    }
    case PieceKind::Ellipsoid: {
      const VL<D> v = p.rot.transpose() * u;
      const VL<D> av = p.axes.cwiseProduct(v);
      return p.p0 + p.rot * (p.axes.cwiseProduct(av) / av.norm());
    }
    case PieceKind::Cylinder: {
      const VL<D> e = p.p1;
      const LD a = u.dot(e);
      const VL<D> perp = u - a * e;
      VL<D> x = p.p0 + (a >= 0 ? p.half_height : -p.half_height) * e;
      if (perp.norm() > 0) x += p.radius * perp / perp.norm();
      return x;
    }
  }
  return VL<D>::Zero();
}

template <int D>
LD support_value(const Piece<D>& p, const VL<D>& u) {
  return u.dot(support(p, u));
}

/// Distance from x to the segment [a, b] by golden-section search over the parameter (the
/// squared distance is a convex quadratic of it).
template <int D>
LD point_segment_golden(const VL<D>& x, const VL<D>& a, const VL<D>& b) {
  if ((b - a).norm() == 0) return (x - a).norm();
  return minimise_1d([&](LD t) { return (a + t * (b - a) - x).norm(); }, 0, 1, 8, 100).second;
}

/// Distance of two segments: golden section over s of the point-segment distance (convex in s).
template <int D>
LD segment_segment_golden(const VL<D>& p0, const VL<D>& p1, const VL<D>& q0, const VL<D>& q1) {
  if ((p1 - p0).norm() == 0) return point_segment_golden<D>(p0, q0, q1);
  return minimise_1d([&](LD s) { return point_segment_golden<D>(p0 + s * (p1 - p0), q0, q1); }, 0, 1, 16, 100).second;
}

/// Closed-form point-segment distance (clamped projection), for the polytope references.
template <int D>
LD point_segment_cf(const VL<D>& x, const VL<D>& a, const VL<D>& b) {
  const VL<D> d = b - a;
  const LD dd = d.squaredNorm();
  const LD t = dd > 0 ? std::clamp((x - a).dot(d) / dd, LD(0), LD(1)) : LD(0);
  return (a + t * d - x).norm();
}

/// Closed-form segment-segment distance: interior stationary point of the convex quadratic on
/// [0,1]^2 if inside, else the least of the four boundary (point-segment) distances.
template <int D>
LD segment_segment_cf(const VL<D>& p0, const VL<D>& p1, const VL<D>& q0, const VL<D>& q1) {
  LD best = std::min({point_segment_cf<D>(p0, q0, q1), point_segment_cf<D>(p1, q0, q1), point_segment_cf<D>(q0, p0, p1),
                      point_segment_cf<D>(q1, p0, p1)});
  const VL<D> d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const LD a = d1.dot(d1), b = d1.dot(d2), c = d2.dot(d2), e = d1.dot(r), f = d2.dot(r);
  const LD det = a * c - b * b;
  if (det > 1e-24L * a * c) {
    const LD s = (b * f - c * e) / det, t = (a * f - b * e) / det;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) best = std::min(best, (p0 + s * d1 - q0 - t * d2).norm());
  }
  return best;
}

/// Distance from x to the triangle (a, b, c) in 3D: the plane if the projection is inside,
/// else the nearest edge.
inline LD point_triangle(const VL<3>& x, const VL<3>& a, const VL<3>& b, const VL<3>& c) {
  const VL<3> n = (b - a).cross(c - a);
  const LD nn = n.norm();
  if (nn > 0) {
    const VL<3> m = n / nn;
    const VL<3> y = x - (x - a).dot(m) * m;
    if ((b - a).cross(y - a).dot(n) >= 0 && (c - b).cross(y - b).dot(n) >= 0 && (a - c).cross(y - c).dot(n) >= 0)
      return std::abs((x - a).dot(m));
  }
  return std::min({point_segment_cf<3>(x, a, b), point_segment_cf<3>(x, b, c), point_segment_cf<3>(x, c, a)});
}

/// Signed distance from x to a polytope piece: max over face planes inside, nearest facet outside.
template <int D>
LD polytope_sd(const Piece<D>& p, const VL<D>& x) {
  LD s = -kInfL;
  for (std::size_t k = 0; k < p.normals.size(); ++k) s = std::max(s, p.normals[k].dot(x) - p.offsets[k]);
  if (s <= 0) return s;
  LD best = kInfL;
  for (const auto& f : p.facets) {
    if constexpr (D == 2) best = std::min(best, point_segment_cf<2>(x, p.verts[f[0]], p.verts[f[1]]));
    else best = std::min(best, point_triangle(x, p.verts[f[0]], p.verts[f[1]], p.verts[f[2]]));
  }
  return best;
}

/// Signed distance from a body-frame point q to the ellipsoid sum (x_i / a_i)^2 <= 1: the
/// nearest point is x_i = a_i^2 q_i / (a_i^2 + t) with t the root of
/// F(t) = sum (a_i q_i / (a_i^2 + t))^2 - 1, found by bisection (t > 0 outside, in (-a_min^2, 0]
/// inside, where F decreases from +inf).
template <int D>
LD ellipsoid_sd_local(const VL<D>& q, const VL<D>& a) {
  auto F = [&](LD t) {
    LD s = 0;
    for (int i = 0; i < D; ++i) s += std::pow(a[i] * q[i] / (a[i] * a[i] + t), 2);
    return s - 1;
  };
  auto nearest = [&](LD t) {
    VL<D> x;
    for (int i = 0; i < D; ++i) x[i] = a[i] * a[i] * q[i] / (a[i] * a[i] + t);
    return x;
  };
  const LD g = F(0);
  if (g == 0) return 0;
  if (g > 0) {
    LD lo = 0, hi = a.maxCoeff() * q.norm() + a.maxCoeff();
    for (int it = 0; it < 200 && hi - lo > 0; ++it) {
      const LD m = (lo + hi) / 2;
      if (m == lo || m == hi) break;
      (F(m) > 0 ? lo : hi) = m;
    }
    return (q - nearest((lo + hi) / 2)).norm();
  }
  const LD amin2 = a.minCoeff() * a.minCoeff();
  LD lo = -amin2, hi = 0;
  const LD probe = -amin2 * (1 - 1e-15L);
  if (F(probe) > 0) {
    for (int it = 0; it < 200; ++it) {
      const LD m = (lo + hi) / 2;
      if (m == lo || m == hi) break;
      (F(m) > 0 ? lo : hi) = m;
    }
    return -(q - nearest((lo + hi) / 2)).norm();
  }
  // Degenerate: q (almost) on the plane of the shortest axes; the nearest point leaves that plane.
  LD off = 0, rest = 0, qg = 0;
  for (int i = 0; i < D; ++i) {
    if (a[i] * a[i] <= amin2 * (1 + 1e-12L)) {
      qg += q[i] * q[i];
      continue;
    }
    const LD xi = a[i] * a[i] * q[i] / (a[i] * a[i] - amin2);
    off += (q[i] - xi) * (q[i] - xi);
    rest += (xi / a[i]) * (xi / a[i]);
  }
  const LD xg = a.minCoeff() * std::sqrt(std::max(LD(0), 1 - rest));
  return -std::sqrt(off + std::pow(xg - std::sqrt(qg), 2));
}

template <int D>
LD ellipsoid_sd(const Piece<D>& p, const VL<D>& x) {
  return ellipsoid_sd_local<D>(p.rot.transpose() * (x - p.p0), p.axes);
}

/// Signed distance from x to a cylinder piece.
template <int D>
LD cylinder_sd(const Piece<D>& p, const VL<D>& x) {
  const VL<D> d = x - p.p0;
  const LD a = d.dot(p.p1);
  const LD rho = (d - a * p.p1).norm();
  const LD da = std::abs(a) - p.half_height, dr = rho - p.radius;
  if (da <= 0 && dr <= 0) return std::max(da, dr);
  return std::hypot(std::max(da, LD(0)), std::max(dr, LD(0)));
}

/// Signed distance from a point to a non-swept piece.
template <int D>
LD point_sd(const Piece<D>& p, const VL<D>& x) {
  switch (p.kind) {
    case PieceKind::Polytope: return polytope_sd<D>(p, x);
    case PieceKind::Ellipsoid: return ellipsoid_sd<D>(p, x);
    case PieceKind::Cylinder: return cylinder_sd<D>(p, x);
    case PieceKind::Swept: return point_segment_golden<D>(x, p.p0, p.p1) - p.radius;
  }
  return 0;
}

struct RefGap {
  LD value = kInfL;
  bool exact = true;  ///< false: on overlap, right sign and first-order magnitude only
  bool supported = true;
};

/// Minkowski's formula: gap = max over unit u of -(h_A(u) + h_B(-u)).
template <int D>
LD minkowski_gap(const Piece<D>& a, const Piece<D>& b) {
  auto sep = [&](const VL<D>& u) { return -support_value<D>(a, u) - support_value<D>(b, VL<D>(-u)); };
  if constexpr (D == 2) return optimise_circle([&](LD t) { return sep(VL<2>(std::cos(t), std::sin(t))); }, true);
  else return optimise_sphere(sep, true);
}

/// 3D convex polytopes: depth by separating axes, distance by vertex-facet and edge-edge pairs.
inline LD polytope_polytope_3d(const Piece<3>& a, const Piece<3>& b) {
  std::vector<VL<3>> axes = a.normals;
  axes.insert(axes.end(), b.normals.begin(), b.normals.end());
  for (const auto& [i, j] : a.edges)
    for (const auto& [k, l] : b.edges) {
      const VL<3> c = (a.verts[j] - a.verts[i]).cross(b.verts[l] - b.verts[k]);
      if (c.norm() > 1e-12L * (a.verts[j] - a.verts[i]).norm() * (b.verts[l] - b.verts[k]).norm()) axes.push_back(c.normalized());
    }
  LD depth = kInfL;
  bool separated = false;
  for (const VL<3>& n : axes) {
    LD amin = kInfL, amax = -kInfL, bmin = kInfL, bmax = -kInfL;
    for (const VL<3>& v : a.verts) amin = std::min(amin, n.dot(v)), amax = std::max(amax, n.dot(v));
    for (const VL<3>& v : b.verts) bmin = std::min(bmin, n.dot(v)), bmax = std::max(bmax, n.dot(v));
    const LD overlap = std::min(amax - bmin, bmax - amin);
    if (overlap < 0) { separated = true; break; }
    depth = std::min(depth, overlap);
  }
  if (!separated) return -depth;
  LD best = kInfL;
  for (const VL<3>& v : a.verts)
    for (const auto& f : b.facets) best = std::min(best, point_triangle(v, b.verts[f[0]], b.verts[f[1]], b.verts[f[2]]));
  for (const VL<3>& v : b.verts)
    for (const auto& f : a.facets) best = std::min(best, point_triangle(v, a.verts[f[0]], a.verts[f[1]], a.verts[f[2]]));
  for (const auto& [i, j] : a.edges)
    for (const auto& [k, l] : b.edges) best = std::min(best, segment_segment_cf<3>(a.verts[i], a.verts[j], b.verts[k], b.verts[l]));
  return best;
}

/// Signed gap of two convex pieces.
template <int D>
RefGap piece_gap(const Piece<D>& a, const Piece<D>& b) {
  RefGap g;
  if (a.kind == PieceKind::Swept && b.kind == PieceKind::Swept) {
    g.value = segment_segment_golden<D>(a.p0, a.p1, b.p0, b.p1) - a.radius - b.radius;
    g.exact = g.value > -(a.radius + b.radius) * (1 - 1e-9L);  // segments apart: exact
    return g;
  }
  if (a.kind == PieceKind::Swept || b.kind == PieceKind::Swept) {
    const Piece<D>& s = a.kind == PieceKind::Swept ? a : b;
    const Piece<D>& o = a.kind == PieceKind::Swept ? b : a;
    if ((s.p1 - s.p0).norm() == 0) {
      g.value = point_sd<D>(o, s.p0) - s.radius;  // offset body: exact both ways
      return g;
    }
    if constexpr (D == 2) {
      g.value = minkowski_gap<D>(a, b);
      return g;
    }
    g.value = minimise_1d([&](LD t) { return point_sd<D>(o, s.p0 + t * (s.p1 - s.p0)); }, 0, 1, 24, 100).second - s.radius;
    g.exact = g.value >= 0;
    return g;
  }
  if constexpr (D == 2) {
    g.value = minkowski_gap<D>(a, b);
    return g;
  } else {
    if (a.kind == PieceKind::Polytope && b.kind == PieceKind::Polytope) {
      g.value = polytope_polytope_3d(a, b);
      return g;
    }
    if (a.kind == PieceKind::Ellipsoid && b.kind == PieceKind::Ellipsoid) {
      g.value = minkowski_gap<D>(a, b);
      return g;
    }
    if (a.kind == PieceKind::Ellipsoid || b.kind == PieceKind::Ellipsoid) {
      const Piece<D>& e = a.kind == PieceKind::Ellipsoid ? a : b;
      const Piece<D>& o = a.kind == PieceKind::Ellipsoid ? b : a;
      g.value = optimise_sphere([&](const VL<3>& u) { return point_sd<D>(o, support<D>(e, u)); }, false);
      g.exact = g.value >= 0;
      return g;
    }
    g.supported = false;  // polytope-cylinder, cylinder-cylinder: no reference here
    g.value = std::numeric_limits<LD>::quiet_NaN();
    return g;
  }
}

/// Signed gap of two placed particles: the least over their piece pairs.
template <int D>
RefGap ref_gap(const RefBody<D>& a, const RefBody<D>& b) {
  RefGap best;
  for (const Piece<D>& p : a.pieces)
    for (const Piece<D>& q : b.pieces) {
      const RefGap g = piece_gap<D>(p, q);
      if (!g.supported) return g;
      if (g.value < best.value) best = g;
    }
  return best;
}

template <int D>
RefGap ref_gap(const Particle<D>& a, const Particle<D>& b) {
  return ref_gap<D>(ref_of<D>(a), ref_of<D>(b));
}

/// Signed gap between a container wall and a placed particle (particle on the container side).
template <int D>
LD ref_wall_gap(const Wall<D>& w, const RefBody<D>& b) {
  LD best = kInfL;
  const VL<D> P = ld<D>(w.point);
  for (const Piece<D>& p : b.pieces) {
    LD g = 0;
    switch (w.kind) {
      case WallKind::Plane: {
        const VL<D> n = ld<D>(w.normal);
        g = n.dot(support<D>(p, VL<D>(-n)) - P);
        break;
      }
      case WallKind::Sphere: {
        auto far = [&](const VL<D>& u) { return support_value<D>(p, u) - u.dot(P); };
        LD farthest;
        if constexpr (D == 2) farthest = optimise_circle([&](LD t) { return far(VL<2>(std::cos(t), std::sin(t))); }, true);
        else farthest = optimise_sphere(far, true);
        g = LD(w.radius) - farthest;
        break;
      }
      case WallKind::Cylinder: {
        if constexpr (D == 3) {
          const VL<3> ax = ld<3>(w.axis);
          const VL<3> e1 = ax.cross(std::abs(ax[0]) < 0.6L ? VL<3>(1, 0, 0) : VL<3>(0, 1, 0)).normalized(), e2 = ax.cross(e1);
          const LD farthest = optimise_circle(
              [&](LD t) {
                const VL<3> u = std::cos(t) * e1 + std::sin(t) * e2;
                return support_value<3>(p, u) - u.dot(P);
              },
              true);
          g = LD(w.radius) - farthest;
        }
        break;
      }
      case WallKind::Vertex: g = point_sd<D>(p, P); break;
    }
    best = std::min(best, g);
  }
  return best;
}

// ================================================================================ generators

template <int D>
Vec<D> random_unit(Rng& rng) {
  for (;;) {
    Vec<D> v;
    for (int a = 0; a < D; ++a) v[a] = rng.uniform(-1.0, 1.0);
    const double n = v.norm();
    if (n > 0.1 && n <= 1.0) return v / n;
  }
}

/// Uniform random rotation (2D angle; 3D unit quaternion by rejection from the 4-ball).
template <int D>
Mat<D> random_rotation(Rng& rng) {
  if constexpr (D == 2) {
    return rotation_2d(rng.uniform(0, 2 * kPi));
  } else {
    for (;;) {
      Eigen::Vector4d q(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      const double n = q.norm();
      if (n > 0.1 && n <= 1) return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
    }
  }
}

inline double log_uniform(Rng& rng, double lo, double hi) { return lo * std::pow(hi / lo, rng.uniform01()); }

/// What a fixed body or the mobile is. The last three are walls (fixed bodies only).
enum class Kind { Sphere, Capsule, ThinCapsule, Polytope, Ellipsoid, ThinEllipsoid, Cluster, Cylinder, Plane, SphereWall, CylinderWall };

inline const char* kind_name(Kind k) {
  switch (k) {
    case Kind::Sphere: return "sphere";
    case Kind::Capsule: return "capsule";
    case Kind::ThinCapsule: return "thin-capsule";
    case Kind::Polytope: return "polytope";
    case Kind::Ellipsoid: return "ellipsoid";
    case Kind::ThinEllipsoid: return "thin-ellipsoid";
    case Kind::Cluster: return "cluster";
    case Kind::Cylinder: return "cylinder";
    case Kind::Plane: return "plane";
    case Kind::SphereWall: return "sphere-wall";
    case Kind::CylinderWall: return "cylinder-wall";
  }
  return "?";
}

inline bool is_wall(Kind k) { return k == Kind::Plane || k == Kind::SphereWall || k == Kind::CylinderWall; }

/// A prototype of the built-in family registry (circumscribed radius 1).
template <int D>
ShapePtr<D> family_prototype(const std::string& family, const ShapeParameters& p) {
  ParticleTemplateSpec spec;
  spec.family = family;
  spec.parameters = p;
  return ShapeFamilies::builtin().prototype<D>(spec).shape;
}

/// A random shape of the kind with circumscribed radius `size`.
template <int D>
ShapePtr<D> random_shape(Kind k, double size, Rng& rng) {
  ShapeParameters p;
  switch (k) {
    case Kind::Sphere: return std::make_shared<SphereShape<D>>(size);
    case Kind::Capsule: {
      const double ar = rng.uniform(0.3, 0.7);  // width / length
      return std::make_shared<SpherocylinderShape<D>>(size * (1 - ar), size * ar);
    }
    case Kind::ThinCapsule:  // aspect ratio 0.05 (equivalently length / width = 20)
      return std::make_shared<SpherocylinderShape<D>>(size * 0.95, size * 0.05);
    case Kind::Polytope: {
      std::vector<std::vector<double>> pts;
      if constexpr (D == 2) {
        const int n = 3 + static_cast<int>(rng.below(6));
        for (int i = 0; i < n; ++i) {
          const double t = 2 * kPi * (i + rng.uniform(0.1, 0.9)) / n, r = rng.uniform(0.7, 1.0);
          pts.push_back({r * std::cos(t), r * std::sin(t)});
        }
        p.point_lists["vertices"] = pts;
        return family_prototype<D>("polygon", p)->scaled(size);
      } else {
        if (rng.uniform01() < 0.3) {
          const int faces[] = {4, 6, 8, 12, 20};
          p.numbers["platonic"] = faces[rng.below(5)];
        } else {
          const int n = 6 + static_cast<int>(rng.below(9));
          for (int i = 0; i < n; ++i) {
            const Vec3 u = random_unit<3>(rng) * rng.uniform(0.7, 1.0);
            pts.push_back({u.x(), u.y(), u.z()});
          }
          p.point_lists["vertices"] = pts;
        }
        return family_prototype<D>("polyhedron", p)->scaled(size);
      }
    }
    case Kind::ThinEllipsoid:  // semi-axes 1 : 0.05 (aspect ratio 0.05), the middle one between
    case Kind::Ellipsoid: {
      std::vector<double> axes;
      for (int i = 0; i < D; ++i) axes.push_back(rng.uniform(0.4, 1.0));
      if (k == Kind::ThinEllipsoid) {
        axes.assign(static_cast<std::size_t>(D), 1.0);
        axes[static_cast<std::size_t>(D - 1)] = 0.05;
        if (D == 3) axes[1] = std::pow(0.05, rng.uniform01());
      }
      p.lists["axes"] = axes;
      return family_prototype<D>(D == 2 ? "ellipse" : "ellipsoid", p)->scaled(size);
    }
    case Kind::Cluster: {
      // 2-4 overlapping members around the origin, so the reference point lies inside.
      const int n = 2 + static_cast<int>(rng.below(3));
      std::vector<std::vector<double>> centres;
      std::vector<double> radii;
      for (int i = 0; i < n; ++i) {
        const Vec<D> c = random_unit<D>(rng) * rng.uniform(0.2, 0.6);
        std::vector<double> v(c.data(), c.data() + D);
        centres.push_back(v);
        radii.push_back(rng.uniform(0.5, 0.9));
      }
      p.point_lists["centers"] = centres;
      p.lists["radii"] = radii;
      return family_prototype<D>("cluster", p)->scaled(size);
    }
    case Kind::Cylinder: {
      if constexpr (D == 3) {
        p.numbers["aspect_ratio"] = rng.uniform(0.5, 2.0);
        return family_prototype<3>("cylinder", p)->scaled(size);
      }
      break;
    }
    default: break;
  }
  ADD_FAILURE() << "random_shape: " << kind_name(k) << " is not a particle kind in " << D << "D";
  return std::make_shared<SphereShape<D>>(size);
}

// ======================================================================= ready-to-paste output

inline std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

template <int D>
std::string vec_literal(const Vec<D>& v) {
  std::string s = D == 2 ? "fp::Vec2(" : "fp::Vec3(";
  for (int a = 0; a < D; ++a) s += (a ? ", " : "") + num(v[a]);
  return s + ")";
}

template <int D>
std::string mat_literal(const Mat<D>& m) {
  std::string s = "(fp::Mat<" + std::to_string(D) + ">() << ";
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) s += (i + j ? ", " : "") + num(m(i, j));
  return s + ").finished()";
}

/// C++ that rebuilds the shape.
template <int D>
std::string shape_literal(const Shape<D>& s) {
  const std::string d = std::to_string(D);
  if (auto* sp = dynamic_cast<const SphereShape<D>*>(&s))
    return "std::make_shared<fp::SphereShape<" + d + ">>(" + num(sp->radius()) + ")";
  if (auto* sc = dynamic_cast<const SpherocylinderShape<D>*>(&s))
    return "std::make_shared<fp::SpherocylinderShape<" + d + ">>(" + num(sc->half_length()) + ", " + num(sc->radius()) + ")";
  if (auto* cl = dynamic_cast<const ClusterShape<D>*>(&s)) {
    std::string m;
    for (const Ball<D>& b : cl->members()) m += (m.empty() ? "" : ", ") + std::string("fp::Ball<") + d + ">{" + vec_literal<D>(b.center) + ", " + num(b.radius) + "}";
    return "std::make_shared<fp::ClusterShape<" + d + ">>(std::vector<fp::Ball<" + d + ">>{" + m + "})";
  }
  if (auto* po = dynamic_cast<const ConvexPolytopeShape<D>*>(&s)) {
    std::string v, f;
    for (const Vec<D>& x : po->vertices()) v += (v.empty() ? "" : ", ") + vec_literal<D>(x);
    for (const auto& a : po->facets()) {
      f += f.empty() ? "{" : ", {";
      for (int i = 0; i < D; ++i) f += (i ? ", " : "") + std::to_string(a[i]);
      f += "}";
    }
    return "std::make_shared<fp::ConvexPolytopeShape<" + d + ">>(std::vector<fp::Vec<" + d + ">>{" + v +
           "}, std::vector<std::array<int, " + d + ">>{" + f + "})";
  }
  if (auto* el = dynamic_cast<const EllipsoidShape<D>*>(&s))
    return "std::make_shared<fp::EllipsoidShape<" + d + ">>(" + vec_literal<D>(el->semi_axes()) + ")";
  if constexpr (D == 3)
    if (auto* cy = dynamic_cast<const CylinderShape*>(&s))
      return "std::make_shared<fp::CylinderShape>(" + num(cy->radius()) + ", " + num(cy->half_height()) + ")";
  return std::string("/* unknown shape ") + s.kind() + " */ nullptr";
}

template <int D>
std::string wall_literal(const Wall<D>& w) {
  const std::string W = "fp::Wall<" + std::to_string(D) + ">::";
  switch (w.kind) {
    case WallKind::Plane: return W + "plane(" + vec_literal<D>(w.point) + ", " + vec_literal<D>(w.normal) + ")";
    case WallKind::Sphere: return W + "sphere(" + vec_literal<D>(w.point) + ", " + num(w.radius) + ")";
    case WallKind::Cylinder:
      return W + "cylinder(" + vec_literal<D>(w.point) + ", " + vec_literal<D>(w.axis) + ", " + num(w.radius) + ")";
    case WallKind::Vertex: return W + "vertex(" + vec_literal<D>(w.point) + ")";
  }
  return "?";
}

// ================================================================================== problems

/// A contact problem that owns what its bodies point to (deques: addresses never move).
template <int D>
struct Problem {
  std::deque<Particle<D>> particles;
  std::deque<Wall<D>> walls;
  std::array<Body<D>, D> fixed;
  ShapePtr<D> mobile_shape;
  Mat<D> mobile_rotation = Mat<D>::Identity();
  Vec<D> known = Vec<D>::Zero();  ///< a position touching every body (constructed), if has_known
  bool has_known = false;

  Problem() = default;
  Problem(const Problem& o) { *this = o; }
  Problem& operator=(const Problem& o) {
    if (this == &o) return *this;
    particles = o.particles;
    walls = o.walls;
    mobile_shape = o.mobile_shape;
    mobile_rotation = o.mobile_rotation;
    known = o.known;
    has_known = o.has_known;
    // Re-point the bodies at our own copies, in the same order.
    std::size_t ip = 0, iw = 0;
    for (int i = 0; i < D; ++i) {
      fixed[i] = o.fixed[i];
      if (o.fixed[i].is_wall()) fixed[i].wall = &walls[iw++];
      else if (o.fixed[i].shaped) fixed[i].shaped = &particles[ip++];
    }
    return *this;
  }

  std::span<const Body<D>> span() const { return {fixed.data(), static_cast<std::size_t>(D)}; }
  Mobile<D> mobile() const { return Mobile<D>::of_shape(mobile_shape, mobile_rotation); }
  Particle<D> mobile_at(const Vec<D>& x) const {
    Particle<D> p;
    p.shape = mobile_shape;
    p.pose.rotation = mobile_rotation;
    p.pose.position = x;
    return p;
  }
  void set_particle(int i, const Particle<D>& p) {
    particles.push_back(p);
    fixed[i] = Body<D>::of_particle(particles.back(), i);
  }
  void set_wall(int i, const Wall<D>& w) {
    walls.push_back(w);
    fixed[i] = Body<D>::of_wall(walls.back());
  }
  /// The same problem translated by t.
  Problem translated(const Vec<D>& t) const {
    Problem q = *this;
    for (auto& p : q.particles) p.pose.position += t;
    for (auto& w : q.walls) w.point += t;
    for (int i = 0; i < D; ++i)
      if (!q.fixed[i].is_wall()) q.fixed[i].center += t;  // walls carry no centre
    q.known += t;
    return q;
  }

  /// C++ statements that rebuild the problem; they end with the replay call.
  std::string literal() const {
    const std::string d = std::to_string(D);
    std::string s = "\n// ---- failing configuration, ready to paste ----\nfp::general_test::Problem<" + d + "> pb;\n";
    for (int i = 0; i < D; ++i) {
      const Body<D>& b = fixed[i];
      if (b.is_wall()) {
        s += "pb.set_wall(" + std::to_string(i) + ", " + wall_literal<D>(*b.wall) + ");\n";
      } else if (b.shaped) {
        s += "{ fp::Particle<" + d + "> p; p.shape = " + shape_literal<D>(*b.shaped->shape) + ";\n  p.pose.position = " +
             vec_literal<D>(b.shaped->pose.position) + ";\n  p.pose.rotation = " + mat_literal<D>(b.shaped->pose.rotation) +
             ";\n  pb.set_particle(" + std::to_string(i) + ", p); }\n";
      } else {
        s += "pb.fixed[" + std::to_string(i) + "] = fp::Body<" + d + ">::sphere(" + vec_literal<D>(b.center) + ", " + num(b.radius) + ");\n";
      }
    }
    s += "pb.mobile_shape = " + shape_literal<D>(*mobile_shape) + ";\npb.mobile_rotation = " + mat_literal<D>(mobile_rotation) + ";\n";
    s += "EXPECT_TRUE(fp::general_test::check_solve<" + d + ">(pb, fp::MinimisationOptions{}));\n";
    return s;
  }
};

/// Size the gap tolerance of body i is relative to (circumscribed radii; walls: the mobile's).
template <int D>
double tolerance_size(const Body<D>& b, double r_mob) {
  return b.is_wall() ? r_mob : std::min(r_mob, b.radius);
}

/// Independent signed gap of body b and the mobile at x.
template <int D>
RefGap ref_body_gap(const Problem<D>& pb, const Body<D>& b, const RefBody<D>& mob) {
  if (b.is_wall()) return RefGap{ref_wall_gap<D>(*b.wall, mob), true, true};
  if (b.shaped) return ref_gap<D>(ref_of<D>(*b.shaped), mob);
  RefBody<D> s;
  s.pieces.push_back(swept_piece<D>(ld<D>(b.center), ld<D>(b.center), b.radius));
  (void)pb;
  return ref_gap<D>(s, mob);
}

/// Largest |gap| / (gap_tolerance * size) over the positions and bodies (<= 1 means valid).
struct CheckResult {
  double worst = 0;
};

/// Every position touches every fixed body: |independent gap| <= gap_tolerance * min(sizes).
template <int D>
::testing::AssertionResult check_placements(const Problem<D>& pb, std::span<const Placement<D>> out, double gap_tolerance,
                                            CheckResult* res = nullptr) {
  const double r_mob = pb.mobile_shape->bounding_radius();
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (!out[k].position.allFinite())
      return ::testing::AssertionFailure() << "solution " << k << " is not finite" << pb.literal();
    const RefBody<D> mob = ref_of<D>(pb.mobile_at(out[k].position));
    for (int i = 0; i < D; ++i) {
      const RefGap g = ref_body_gap<D>(pb, pb.fixed[i], mob);
      if (!g.supported) return ::testing::AssertionFailure() << "no independent reference for body " << i << pb.literal();
      const double tol = gap_tolerance * tolerance_size<D>(pb.fixed[i], r_mob);
      const double rel = static_cast<double>(std::abs(g.value)) / tol;
      if (res) res->worst = std::max(res->worst, rel);
      if (!(rel <= 1))
        return ::testing::AssertionFailure() << "solution " << k << " = " << vec_literal<D>(out[k].position)
                                             << " has independent gap " << static_cast<double>(g.value) << " to body " << i
                                             << " (tolerance " << tol << ")" << pb.literal();
    }
  }
  return ::testing::AssertionSuccess();
}

/// Replay entry point of Problem::literal(): solve and check every position.
template <int D>
::testing::AssertionResult check_solve(const Problem<D>& pb, const MinimisationOptions& opt) {
  NarrowPhase<D> np;
  MinimisationSolver<D> solver(np, opt);
  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> out;
  const int n = solver.solve(pb.span(), pb.mobile(), out);
  return check_placements<D>(pb, std::span<const Placement<D>>(out.data(), n), opt.gap_tolerance);
}

/// Position t along d (from x) where the gap f(t) crosses zero, by bisection; f(lo) < 0 < f(hi).
template <class F>
double bisect_zero(F&& f, double lo, double hi) {
  for (int it = 0; it < 200; ++it) {
    const double m = 0.5 * (lo + hi);
    if (m <= lo || m >= hi) break;
    (f(m) < 0 ? lo : hi) = m;
  }
  return 0.5 * (lo + hi);
}

/// Places body i of `kind` (circumscribed radius `size`) touching the mobile at pb.known from
/// direction d (the body's reference point on the ray pb.known + t d). Returns false if the
/// construction fails (e.g. a reference point outside its shape).
template <int D>
bool place_touching(Problem<D>& pb, const NarrowPhase<D>& np, int i, Kind kind, double size, const Vec<D>& d, Rng& rng) {
  const Particle<D> mob = pb.mobile_at(pb.known);
  const double r_mob = pb.mobile_shape->bounding_radius();
  switch (kind) {
    case Kind::Plane: {
      const Vec<D> x = mob.support(d);
      pb.set_wall(i, Wall<D>::plane(x, -d));
      return true;
    }
    case Kind::SphereWall:
    case Kind::CylinderWall: {
      if (D == 2 && kind == Kind::CylinderWall) return false;
      const double R = r_mob + size;
      Vec<D> axis = Vec<D>::Zero();
      if constexpr (D == 3) {
        axis = random_unit<3>(rng);
        axis = (axis - axis.dot(d) * d).normalized();
      }
      auto wall_at = [&](double t) {
        const Vec<D> c = pb.known - t * d;
        return kind == Kind::SphereWall ? Wall<D>::sphere(c, R) : Wall<D>::cylinder(c, axis, R);
      };
      auto f = [&](double t) { return -np.gap(wall_at(t), mob).value; };  // < 0 while the mobile is inside
      if (!(f(0) < 0) || !(f(R + r_mob) > 0)) return false;
      pb.set_wall(i, wall_at(bisect_zero(f, 0, R + r_mob)));
      return true;
    }
    default: {
      Particle<D> p;
      p.shape = random_shape<D>(kind, size, rng);
      p.pose.rotation = random_rotation<D>(rng);
      auto at = [&](double t) {
        Particle<D> q = p;
        q.pose.position = pb.known + t * d;
        return q;
      };
      auto f = [&](double t) { return np.gap(at(t), mob).value; };
      const double far = 1.01 * (size + r_mob);
      if (!(f(0) < 0) || !(f(far) > 0)) return false;
      p = at(bisect_zero(f, 0, far));
      pb.set_particle(i, p);
      return true;
    }
  }
}

/// Sizes and spread of a constructed problem.
struct Sizes {
  double mobile = 1;
  std::vector<double> fixed;  ///< per body (default 1); each jittered by a log-uniform factor
  double jitter = 1.4;        ///< sizes times [1/jitter, jitter]
  double min_angle_deg = 50;  ///< least angle between the contact directions
  /// Let the fixed particles overlap each other (a tiny mobile cannot touch three big particles
  /// that do not: the contact problem itself does not care).
  bool allow_fixed_overlap = false;
};

/// A problem whose bodies of the given kinds all touch the mobile at a known position (random in
/// [-5, 5]^D), from directions at least min_angle apart and (3D) not nearly coplanar, with the
/// particles not overlapping each other. Returns false if no such problem was found.
template <int D>
bool construct_problem(Problem<D>& pb, const NarrowPhase<D>& np, Kind mobile, const std::array<Kind, D>& fixed,
                       const Sizes& sz, Rng& rng) {
  for (int attempt = 0; attempt < 50; ++attempt) {
    pb = Problem<D>();
    pb.mobile_shape = random_shape<D>(mobile, sz.mobile * log_uniform(rng, 1 / sz.jitter, sz.jitter), rng);
    pb.mobile_rotation = random_rotation<D>(rng);
    for (int a = 0; a < D; ++a) pb.known[a] = rng.uniform(-5, 5);
    pb.has_known = true;
    std::array<Vec<D>, D> dirs;
    bool spread = true;
    for (int i = 0; i < D; ++i) {
      dirs[i] = random_unit<D>(rng);
      for (int j = 0; j < i; ++j) spread &= dirs[i].dot(dirs[j]) < std::cos(sz.min_angle_deg * kPi / 180);
    }
    if constexpr (D == 3) spread &= std::abs(dirs[0].dot(dirs[1].cross(dirs[2]))) > 0.2;
    if (!spread) continue;
    bool ok = true;
    for (int i = 0; i < D && ok; ++i) {
      const double s = (i < static_cast<int>(sz.fixed.size()) ? sz.fixed[i] : 1.0) * log_uniform(rng, 1 / sz.jitter, sz.jitter);
      ok = place_touching<D>(pb, np, i, fixed[i], s, dirs[i], rng);
    }
    if (!ok) continue;
    for (int i = 0; i < D && ok && !sz.allow_fixed_overlap; ++i)
      for (int j = i + 1; j < D && ok; ++j)
        if (pb.fixed[i].shaped && pb.fixed[j].shaped) ok = np.gap(*pb.fixed[i].shaped, *pb.fixed[j].shaped).value > 0;
    if (ok) return true;
  }
  return false;
}

/// A mobile sphere given by its radius only (no shape: the sphere fast path's form).
template <int D>
Mobile<D> plain_sphere(double r) {
  Mobile<D> m;
  m.radius = r;
  return m;
}

/// Index of the position closest to x and its distance (-1 if none).
template <int D>
std::pair<int, double> closest(std::span<const Placement<D>> out, const Vec<D>& x) {
  int best = -1;
  double bd = 0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double d = (out[k].position - x).norm();
    if (best < 0 || d < bd) best = static_cast<int>(k), bd = d;
  }
  return {best, bd};
}

// ======================================================================= 2D brute force

/// The boundary of W = P (+) (-M): the positions of the mobile M's reference point where M
/// touches the convex fixed particle P. Its point with outward normal u is s_P(u) - s_M(-u) (own
/// long-double supports), so a dense set of angles traces it exactly (chords within 3e-7 R).
struct Contour {
  std::vector<Vec2> v;  ///< counter-clockwise
  Vec2 c;               ///< an interior point
  std::vector<double> angle;
  int start = 0;  ///< index of the vertex with the least angle about c

  /// Signed distance-like value: > 0 inside (the mobile overlaps P), < 0 outside.
  double inside(const Vec2& x) const {
    const int n = static_cast<int>(v.size());
    const double a = std::atan2(x.y() - c.y(), x.x() - c.x());
    // Binary search over the angles, rotated to start at `start`.
    int lo = 0, hi = n;
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      (angle[(start + mid) % n] <= a ? lo : hi) = mid;
    }
    int k = (start + lo) % n;
    if (a < angle[start]) k = (start + n - 1) % n;
    const Vec2 p = v[k], q = v[(k + 1) % n];
    const Vec2 e = q - p;
    return (e.x() * (x.y() - p.y()) - e.y() * (x.x() - p.x())) / e.norm();
  }
};

inline Contour contour_of(const Piece<2>& P, const Piece<2>& M, int samples) {
  Contour c;
  std::vector<Vec2> raw;
  for (int k = 0; k < samples; ++k) {
    const LD t = 2 * kPiL * k / samples;
    const VL<2> u(std::cos(t), std::sin(t));
    const VL<2> w = support<2>(P, u) - support<2>(M, VL<2>(-u));
    const Vec2 x(static_cast<double>(w[0]), static_cast<double>(w[1]));
    if (raw.empty() || (x - raw.back()).norm() > 1e-12) raw.push_back(x);
  }
  while (raw.size() > 1 && (raw.front() - raw.back()).norm() <= 1e-12) raw.pop_back();
  // Split long chords (flat sides) so that a contour crossing twice within one side is seen.
  double perimeter = 0;
  for (std::size_t k = 0; k < raw.size(); ++k) perimeter += (raw[(k + 1) % raw.size()] - raw[k]).norm();
  const double step = perimeter / samples;
  for (std::size_t k = 0; k < raw.size(); ++k) {
    const Vec2 p = raw[k], q = raw[(k + 1) % raw.size()];
    const int pieces = std::max(1, static_cast<int>(std::ceil((q - p).norm() / step)));
    for (int j = 0; j < pieces; ++j) c.v.push_back(p + (q - p) * (double(j) / pieces));
  }
  c.c = Vec2::Zero();
  for (const Vec2& x : c.v) c.c += x / static_cast<double>(c.v.size());
  for (const Vec2& x : c.v) c.angle.push_back(std::atan2(x.y() - c.c.y(), x.x() - c.c.x()));
  c.start = static_cast<int>(std::min_element(c.angle.begin(), c.angle.end()) - c.angle.begin());
  return c;
}

/// The common zeros of ω1 and ω2: where contour 1 enters or leaves W2 (sign changes of the
/// inside value along contour 1, located by bisection on the chord).
inline std::vector<Vec2> crossings(const Contour& c1, const Contour& c2, double& least_angle_deg) {
  std::vector<Vec2> out;
  least_angle_deg = 180;
  const int n = static_cast<int>(c1.v.size());
  double prev = c2.inside(c1.v[0]);
  for (int k = 1; k <= n; ++k) {
    const Vec2 p = c1.v[k - 1], q = c1.v[k % n];
    const double cur = c2.inside(q);
    if ((prev > 0) != (cur > 0)) {
      double lo = 0, hi = 1;
      const bool lo_inside = prev > 0;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        ((c2.inside(p + mid * (q - p)) > 0) == lo_inside ? lo : hi) = mid;
      }
      const Vec2 x = p + 0.5 * (lo + hi) * (q - p);
      out.push_back(x);
      // Crossing angle: contour 1's chord against contour 2's tangent there (finite difference
      // of the inside value across the chord, relative to the chord length).
      const double slope = std::abs(cur - prev) / (q - p).norm();  // = |sin(angle)|
      least_angle_deg = std::min(least_angle_deg, std::asin(std::min(1.0, slope)) * 180 / kPi);
    }
    prev = cur;
  }
  return out;
}

/// A 2D problem of two fixed convex particles of the given kinds at a random gap (0 to 1.5 mobile
/// diameters, as neighbours on a front are) and a mobile of the given kind. False if the
/// construction failed.
inline bool gapped_pair_problem(Problem<2>& pb, const NarrowPhase<2>& np, Kind fixed1, Kind fixed2, Kind mobile, Rng& rng) {
  pb = Problem<2>();
  Particle<2> p1, p2;
  p1.shape = random_shape<2>(fixed1, log_uniform(rng, 0.7, 1.4), rng);
  p1.pose.rotation = random_rotation<2>(rng);
  p2.shape = random_shape<2>(fixed2, log_uniform(rng, 0.7, 1.4), rng);
  p2.pose.rotation = random_rotation<2>(rng);
  pb.mobile_shape = random_shape<2>(mobile, log_uniform(rng, 0.5, 1.5), rng);
  pb.mobile_rotation = random_rotation<2>(rng);
  const double target = rng.uniform(0, 1.5) * 2 * pb.mobile_shape->bounding_radius();
  const Vec2 d = random_unit<2>(rng);
  auto f = [&](double t) {
    p2.pose.position = t * d;
    return np.gap(p1, p2).value - target;
  };
  const double far = 2 * (p1.bounding_radius() + p2.bounding_radius()) + target;
  if (!(f(0) < 0) || !(f(far) > 0)) return false;
  p2.pose.position = bisect_zero(f, 0, far) * d;
  pb.set_particle(0, p1);
  pb.set_particle(1, p2);
  return true;
}

/// Every position of the (convex) mobile touching both (convex) fixed particles of `pb`: the
/// crossings of the two touching contours; `least_angle_deg` is the least crossing angle.
inline std::vector<Vec2> brute_force_crossings(const Problem<2>& pb, double& least_angle_deg) {
  const Piece<2> M = ref_of<2>(pb.mobile_at(Vec2::Zero())).pieces[0];
  const Contour c1 = contour_of(ref_of<2>(pb.particles[0]).pieces[0], M, 4096);
  const Contour c2 = contour_of(ref_of<2>(pb.particles[1]).pieces[0], M, 4096);
  return crossings(c1, c2, least_angle_deg);
}

/// Counters of a batch of constructed problems.
struct Tally {
  int built = 0;          ///< problems constructed
  int with_solution = 0;  ///< problems with at least one position returned
  int solutions = 0;      ///< positions returned (every one checked)
  int known_found = 0;    ///< problems whose constructed position was among them
  int known_on_stretch = 0;  ///< ... or between two of them on a straight stretch of positions
                             ///< (a flat side sliding on a flat side: a continuum of solutions)
  int known_inexact = 0;     ///< ... or not found, but the constructed position is no solution at
                             ///< the tolerance (its construction by bisection is accurate to about
                             ///< 1e-10 of the mobile: beyond `tol` of a body 100 times smaller)
  double worst = 0;       ///< largest |independent gap| / tolerance (<= 1)
  double known_recall() const { return built ? double(known_found) / built : 0; }
  double solved() const { return built ? double(with_solution) / built : 0; }
};

/// Builds `trials` problems whose bodies of the given kinds touch the mobile at a known position,
/// solves each with `solver` and checks every returned position independently: |gap| <= `tol` x
/// the smaller size. The known position counts as found within `known_within` x the mobile's size.
template <int D>
Tally run_constructed_with(const ContactSolver<D>& solver, const char* name, Kind mobile, const std::array<Kind, D>& fixed,
                           int trials, std::uint64_t seed, double tol, double known_within, const Sizes& sizes = Sizes{}) {
  NarrowPhase<D> np;
  Rng rng(seed);
  Tally t;
  for (int trial = 0; trial < trials; ++trial) {
    Problem<D> pb;
    if (!construct_problem<D>(pb, np, mobile, fixed, sizes, rng)) continue;
    ++t.built;
    std::array<Placement<D>, ContactSolver<D>::kMaxCandidates> out;
    const int n = solver.solve(pb.span(), pb.mobile(), out);
    const std::span<const Placement<D>> got(out.data(), static_cast<std::size_t>(n));
    CheckResult cr;
    EXPECT_TRUE(check_placements<D>(pb, got, tol, &cr)) << name << " trial " << trial;
    t.worst = std::max(t.worst, cr.worst);
    t.solutions += n;
    t.with_solution += n > 0;
    const double within = known_within * pb.mobile_shape->bounding_radius();
    const auto [k, dist] = closest<D>(got, pb.known);
    if (k >= 0 && dist <= within) {
      ++t.known_found;
      continue;
    }
    bool on_stretch = false;
    for (int a = 0; a < n && !on_stretch; ++a)
      for (int b = a + 1; b < n && !on_stretch; ++b) {
        const Vec<D> p = got[a].position, d = got[b].position - p;
        const double s = std::clamp((pb.known - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
        on_stretch = (p + s * d - pb.known).norm() <= within;
      }
    t.known_on_stretch += on_stretch;
    if (!on_stretch) {
      const Placement<D> known{pb.known};
      t.known_inexact += !check_placements<D>(pb, std::span<const Placement<D>>(&known, 1), tol);
    }
  }
  EXPECT_GE(t.built, trials * 9 / 10) << name << ": the construction failed too often";
  return t;
}

/// One line of the printed table of run_constructed_with.
template <int D>
void print_tally(const char* name, const Tally& t) {
  std::printf("  %dD %-36s %3d problems, %3d solved, %4d positions, known found %5.1f %% (+%d on a stretch, %d inexact), "
              "worst |gap|/tol %.2g\n",
              D, name, t.built, t.with_solution, t.solutions, 100 * t.known_recall(), t.known_on_stretch, t.known_inexact, t.worst);
}

/// Kinds of a constructed problem, drawn per trial (a closed-form solver's tests draw from the
/// kinds it takes).
template <int D>
using KindDraw = std::function<void(Rng&, Kind& mobile, std::array<Kind, D>& fixed)>;

/// A closed-form solver against the minimisation on `trials` constructed problems: every position
/// the minimisation returns must be one of the solver's, within 1e-3 of the size (the
/// minimisation stops at gaps of 1e-6 of the size: where the wrappers cross at a grazing angle its
/// position lies up to ~1e-6 / sin(angle) away). Returns how many were not (printed); and the
/// closed-form solver must find at least as many positions in all.
template <int D>
int missed_minimisation_positions(const ContactSolver<D>& solver, const char* name, const KindDraw<D>& kinds, int trials,
                                  std::uint64_t seed) {
  NarrowPhase<D> np;
  const MinimisationSolver<D> minimisation(np, MinimisationOptions{});
  Rng rng(seed);
  int built = 0, by_solver = 0, by_minimisation = 0, missed = 0;
  for (int trial = 0; trial < trials; ++trial) {
    Problem<D> pb;
    Kind mobile;
    std::array<Kind, D> fixed;
    kinds(rng, mobile, fixed);
    if (!construct_problem<D>(pb, np, mobile, fixed, Sizes{}, rng)) continue;
    ++built;
    std::array<Placement<D>, ContactSolver<D>::kMaxCandidates> w, m;
    const int nw = solver.solve(pb.span(), pb.mobile(), w);
    const int nm = minimisation.solve(pb.span(), pb.mobile(), m);
    by_solver += nw, by_minimisation += nm;
    const std::span<const Placement<D>> got(w.data(), static_cast<std::size_t>(nw));
    for (int k = 0; k < nm; ++k)
      if (closest<D>(got, m[k].position).second > 1e-3 * pb.mobile_shape->bounding_radius()) {
        ++missed;
        std::printf("  %s trial %d: minimisation position %s is none of the solver's%s", name, trial,
                    vec_literal<D>(m[k].position).c_str(), pb.literal().c_str());
      }
  }
  std::printf("  %dD %s: %d problems; minimisation %d positions, the solver %d; %d minimisation positions not among them\n", D,
              name, built, by_minimisation, by_solver, missed);
  EXPECT_GE(built, trials * 9 / 10) << name;
  EXPECT_GE(by_solver, by_minimisation) << name;
  return missed;
}

/// The same problems shifted by 1e6 on every axis: the solver returns as many positions, valid
/// to `tol`, the same ones shifted (up to the rounding of the inputs at 1e6, 1.2e-10, amplified by
/// grazing crossings: within 1e-7 of the size).
template <int D>
void expect_same_when_shifted(const ContactSolver<D>& solver, Kind mobile, const std::array<Kind, D>& fixed, double tol,
                              std::uint64_t seed) {
  NarrowPhase<D> np;
  Rng rng(seed);
  int compared = 0;
  for (int trial = 0; trial < 30; ++trial) {
    Problem<D> pb;
    if (!construct_problem<D>(pb, np, mobile, fixed, Sizes{}, rng)) continue;
    const Vec<D> shift = Vec<D>::Constant(1e6);
    const Problem<D> far = pb.translated(shift);
    std::array<Placement<D>, ContactSolver<D>::kMaxCandidates> a, b;
    const int na = solver.solve(pb.span(), pb.mobile(), a);
    const int nb = solver.solve(far.span(), far.mobile(), b);
    const std::span<const Placement<D>> shifted(b.data(), static_cast<std::size_t>(nb));
    EXPECT_TRUE(check_placements<D>(far, shifted, tol)) << "trial " << trial;
    ASSERT_EQ(na, nb) << "trial " << trial << far.literal();
    for (int k = 0; k < na; ++k)
      EXPECT_LE(closest<D>(shifted, a[k].position + shift).second, 1e-7 * pb.mobile_shape->bounding_radius()) << "trial " << trial;
    ++compared;
  }
  EXPECT_GE(compared, 27);
}

/// Sphere problems (spheres, every third with a plane wall): `solver` returns the positions of
/// the analytic sphere solver, as many and each within 1e-9 of the mobile's size.
template <int D>
void expect_analytic_positions_for_spheres(const ContactSolver<D>& solver, int trials, std::uint64_t seed) {
  NarrowPhase<D> np;
  const SphereContactSolver<D> analytic;
  Rng rng(seed);
  int compared = 0;
  for (int trial = 0; trial < trials; ++trial) {
    Problem<D> pb;
    std::array<Kind, D> kinds;
    kinds.fill(Kind::Sphere);
    if (trial % 3 == 0) kinds[0] = Kind::Plane;
    if (!construct_problem<D>(pb, np, Kind::Sphere, kinds, Sizes{}, rng)) continue;
    std::array<Placement<D>, ContactSolver<D>::kMaxCandidates> w, a;
    const int nw = solver.solve(pb.span(), pb.mobile(), w);
    const int na = analytic.solve(pb.span(), pb.mobile(), std::span<Placement<D>>(a.data(), ContactSolver<D>::kMaxSolutions));
    ASSERT_EQ(nw, na) << "trial " << trial << pb.literal();
    for (int k = 0; k < na; ++k)
      EXPECT_LE(closest<D>(std::span<const Placement<D>>(w.data(), static_cast<std::size_t>(nw)), a[k].position).second,
                1e-9 * pb.mobile_shape->bounding_radius());
    ++compared;
  }
  EXPECT_GE(compared, trials * 9 / 10);
}

/// Problems built as usual, then the last fixed body moved `away` on every axis: no position can
/// touch every body, and the solver returns none. At least `min_tried` problems are built.
template <int D>
void expect_nothing_when_one_is_far(const ContactSolver<D>& solver, Kind mobile, const std::array<Kind, D>& fixed, double away,
                                    int trials, int min_tried, std::uint64_t seed) {
  NarrowPhase<D> np;
  Rng rng(seed);
  int tried = 0;
  for (int trial = 0; trial < trials; ++trial) {
    Problem<D> pb;
    if (!construct_problem<D>(pb, np, mobile, fixed, Sizes{}, rng)) continue;
    Particle<D> p = *pb.fixed[D - 1].shaped;
    p.pose.position += Vec<D>::Constant(away);
    pb.set_particle(D - 1, p);
    std::array<Placement<D>, ContactSolver<D>::kMaxCandidates> out;
    EXPECT_EQ(solver.solve(pb.span(), pb.mobile(), out), 0) << "trial " << trial;
    ++tried;
  }
  EXPECT_GE(tried, min_tried);
}

}  // namespace fp::general_test
