#pragma once
// Shared helpers of the contact-solver tests:
//  * gap_ld: the signed gap of a ball against a body, computed independently in long double;
//  * config_literal: a configuration printed as C++ ready to paste into a test (style.md habit 10);
//  * check_tangent: every returned position touches every body (|gap| <= tol * min(r, r_body));
//  * reference_solutions: an independent long-double solver of the same problem (trilateration
//    for sphere/plane loci, a companion-matrix quartic for a cylinder locus) that also says when a
//    configuration is too close to a degeneracy for its count to be compared;
//  * add_tangent_body / run_constructed: bodies of every kind touching a known ball, solved in
//    every order and checked against all of the above.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "contact/sphere_contact_solver.hpp"
#include "core/sampling/rng.hpp"

namespace fp::contact_test {

using LD = long double;
template <int D>
using VecL = Eigen::Matrix<LD, D, 1>;

/// Tangency tolerance of the tests: 10x the solver's own (the output is rounded to double
/// after the solver verified it in its local frame).
inline constexpr double kGapTol = 1e-9;

template <int D>
VecL<D> ld(const Vec<D>& v) {
  return v.template cast<LD>();
}

/// Length the gap tolerance is relative to: min(r, r_i) for a particle, r for a wall.
template <int D>
double body_size(const Body<D>& b, double r) {
  return b.is_wall() ? r : std::min(r, b.radius);
}

/// Signed gap (0 = tangent, < 0 = overlap) in long double, written from the definitions and not
/// from Wall::gap (the two are compared in a test of their own).
template <int D>
LD gap_ld(const Body<D>& b, const Vec<D>& x, double r) {
  const VecL<D> X = ld<D>(x);
  const LD R = r;
  if (!b.is_wall()) return (X - ld<D>(b.center)).norm() - LD(b.radius) - R;
  const Wall<D>& w = *b.wall;
  const VecL<D> d = X - ld<D>(w.point);
  switch (w.kind) {
    case WallKind::Plane: return ld<D>(w.normal).dot(d) - R;
    case WallKind::Sphere: return LD(w.radius) - d.norm() - R;
    case WallKind::Cylinder: {
      const VecL<D> a = ld<D>(w.axis);
      return LD(w.radius) - (d - d.dot(a) * a).norm() - R;
    }
    case WallKind::Vertex: return d.norm() - R;
  }
  return 0;
}

// ---- ready-to-paste literals ----

template <int D>
std::string vec_literal(const Vec<D>& v) {
  char buf[160];
  if constexpr (D == 2) std::snprintf(buf, sizeof buf, "fp::Vec2(%.17g, %.17g)", v[0], v[1]);
  else std::snprintf(buf, sizeof buf, "fp::Vec3(%.17g, %.17g, %.17g)", v[0], v[1], v[2]);
  return buf;
}

inline std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
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

/// The configuration as C++ statements: paste them into a TEST and call
/// EXPECT_TRUE(fp::contact_test::check_solve<D>(fixed, r));
template <int D>
std::string config_literal(std::span<const Body<D>> fixed, double r) {
  const std::string d = std::to_string(D);
  std::string walls, bodies;
  int nw = 0;
  for (const Body<D>& b : fixed) {
    if (!bodies.empty()) bodies += ",\n    ";
    if (b.is_wall()) {
      if (nw > 0) walls += ",\n    ";
      walls += wall_literal<D>(*b.wall);
      bodies += "fp::Body<" + d + ">::of_wall(walls[" + std::to_string(nw++) + "])";
    } else {
      bodies += "fp::Body<" + d + ">::sphere(" + vec_literal<D>(b.center) + ", " + num(b.radius) + ")";
    }
  }
  std::string s = "\n// ---- failing configuration, ready to paste ----\n";
  s += "const std::vector<fp::Wall<" + d + ">> walls = {\n    " + walls + "};\n";
  s += "const std::array<fp::Body<" + d + ">, " + d + "> fixed = {\n    " + bodies + "};\n";
  s += "const double r = " + num(r) + ";\n";
  s += "EXPECT_TRUE(fp::contact_test::check_solve<" + d + ">(fixed, r));\n";
  return s;
}

// ---- checks ----

/// Every position touches every body within kGapTol * min(r, r_body), and lies inside concave walls.
template <int D>
::testing::AssertionResult check_tangent(std::span<const Body<D>> fixed, double r,
                                         std::span<const Placement<D>> out) {
  for (std::size_t k = 0; k < out.size(); ++k) {
    for (std::size_t i = 0; i < fixed.size(); ++i) {
      const LD g = gap_ld<D>(fixed[i], out[k].position, r);
      const double tol = kGapTol * body_size<D>(fixed[i], r);
      if (!(std::abs(g) <= tol))
        return ::testing::AssertionFailure()
               << "solution " << k << " = " << vec_literal<D>(out[k].position) << " has gap "
               << static_cast<double>(g) << " to body " << i << " (tolerance " << tol << ")"
               << config_literal<D>(fixed, r);
      if (fixed[i].is_wall() && (fixed[i].wall->kind == WallKind::Sphere || fixed[i].wall->kind == WallKind::Cylinder)) {
        const Wall<D>& w = *fixed[i].wall;
        Vec<D> d = out[k].position - w.point;
        if (w.kind == WallKind::Cylinder) d -= d.dot(w.axis) * w.axis;
        if (!(d.norm() < w.radius))
          return ::testing::AssertionFailure() << "solution " << k << " is outside concave wall " << i
                                               << config_literal<D>(fixed, r);
      }
    }
  }
  return ::testing::AssertionSuccess();
}

/// The replay entry point of config_literal: solve and check tangency.
template <int D>
::testing::AssertionResult check_solve(std::span<const Body<D>> fixed, double r) {
  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> out;
  const int n = SphereContactSolver<D>{}.solve(fixed, Mobile<D>{r}, out);
  return check_tangent<D>(fixed, r, std::span<const Placement<D>>(out.data(), n));
}

template <int D, std::size_t N>
::testing::AssertionResult check_solve(const std::array<Body<D>, N>& fixed, double r) {
  return check_solve<D>(std::span<const Body<D>>(fixed.data(), N), r);
}

// ---- an independent reference solver in long double ----

template <int D>
struct Reference {
  std::vector<VecL<D>> positions;
  bool ambiguous = false;  ///< near a degeneracy (double root, parallel loci): do not compare counts
  bool supported = true;   ///< false for locus combinations the solver rejects by design
};

namespace detail {

enum class Kind { Sphere, Plane, Cylinder };

/// Locus of centres relative to the frame origin O: Sphere |y - p| = rho; Plane n.y = rho;
/// Cylinder: distance from y to the line (p, n) = rho.
template <int D>
struct LocusL {
  Kind kind = Kind::Sphere;
  VecL<D> p = VecL<D>::Zero(), n = VecL<D>::Zero();
  LD rho = 0;
};

inline LD cosl_(LD t) { return std::cos(t); }
inline LD sinl_(LD t) { return std::sin(t); }

/// Real roots t of f(t) = a0 + a1 cos t + b1 sin t + a2 cos 2t + b2 sin 2t, from the roots on
/// the unit circle of the quartic z^2 f = 0 (z = e^{it}), found as eigenvalues of its companion
/// matrix and polished by Newton in t. Returns false when the answer is too close to call: a
/// root pair closer than 1e-3 rad, or a root neither clearly on nor clearly off the circle.
inline bool trig_quadratic_roots(LD a0, LD a1, LD b1, LD a2, LD b2, std::vector<LD>& roots) {
  using C = std::complex<LD>;
  const C I(0, 1);
  // Coefficients of z^4 ... z^0 (c[4 - k] = conj(c[k])).
  std::array<C, 5> c = {(a2 - I * b2) / LD(2), (a1 - I * b1) / LD(2), C(a0), (a1 + I * b1) / LD(2), (a2 + I * b2) / LD(2)};
  LD cmax = 0;
  for (const C& x : c) cmax = std::max(cmax, std::abs(x));
  if (cmax == 0) return false;
  // A circle in a plane perpendicular to the axis has no cos 2t, sin 2t terms: z f is a quadratic.
  int lead = 0, deg = 4;
  while (deg > 0 && std::abs(c[lead]) <= 1e-17L * cmax) { ++lead; deg -= 2; }  // drop z^4 and z^0 together
  if (deg <= 0) return std::abs(c[2]) > 1e-12L * cmax;  // constant: no root, or (if 0) degenerate
  Eigen::Matrix<C, Eigen::Dynamic, Eigen::Dynamic> M = Eigen::Matrix<C, Eigen::Dynamic, Eigen::Dynamic>::Zero(deg, deg);
  for (int k = 0; k < deg; ++k) M(0, k) = -c[lead + 1 + k] / c[lead];
  for (int k = 1; k < deg; ++k) M(k, k - 1) = 1;
  Eigen::ComplexEigenSolver<decltype(M)> es(M, false);
  if (es.info() != Eigen::Success) return false;
  auto f = [&](LD t) { return a0 + a1 * std::cos(t) + b1 * std::sin(t) + a2 * std::cos(2 * t) + b2 * std::sin(2 * t); };
  auto df = [&](LD t) { return -a1 * std::sin(t) + b1 * std::cos(t) - 2 * a2 * std::sin(2 * t) + 2 * b2 * std::cos(2 * t); };
  bool clear = true;
  for (int k = 0; k < deg; ++k) {
    const C z = es.eigenvalues()[k];
    const LD off = std::abs(std::abs(z) - 1);
    if (off > 1e-5L) continue;              // clearly off the circle: a complex pair
    if (off > 1e-10L) { clear = false; continue; }
    LD t = std::arg(z);
    for (int it = 0; it < 8; ++it) {
      const LD d = df(t);
      if (d == 0) break;
      t -= f(t) / d;
    }
    roots.push_back(t);
  }
  constexpr LD kTwoPi = 2 * 3.14159265358979323846264338327950288L;
  for (std::size_t i = 0; i < roots.size(); ++i)
    for (std::size_t j = i + 1; j < roots.size(); ++j) {
      LD d = std::fmod(std::abs(roots[i] - roots[j]), kTwoPi);
      d = std::min(d, kTwoPi - d);
      if (d < 1e-3L) clear = false;
    }
  return clear;
}

}  // namespace detail

/// Solves the contact problem independently: every body becomes a locus of centres (exact
/// differences of doubles in long double, relative to the first sphere-like body), sphere and
/// plane loci are intersected by trilateration, a cylinder locus with the circle of the two
/// other loci through the roots of a quartic on the unit circle (not the solver's grid search).
template <int D>
Reference<D> reference_solutions(std::span<const Body<D>> fixed, double r) {
  using namespace detail;
  Reference<D> ref;
  const LD R = r;
  // Frame origin: the first particle / sphere wall / vertex centre, else a wall point.
  VecL<D> O = ld<D>(fixed[0].is_wall() ? fixed[0].wall->point : fixed[0].center);
  for (const Body<D>& b : fixed) {
    if (!b.is_wall()) { O = ld<D>(b.center); break; }
    if (b.wall->kind == WallKind::Sphere || b.wall->kind == WallKind::Vertex) { O = ld<D>(b.wall->point); break; }
  }
  std::vector<LocusL<D>> L;
  for (const Body<D>& b : fixed) {
    LocusL<D> l;
    if (!b.is_wall()) {
      l.kind = Kind::Sphere; l.p = ld<D>(b.center) - O; l.rho = LD(b.radius) + R;
    } else {
      const Wall<D>& w = *b.wall;
      switch (w.kind) {
        case WallKind::Plane:
          l.kind = Kind::Plane; l.n = ld<D>(w.normal); l.rho = l.n.dot(ld<D>(w.point) - O) + R; break;
        case WallKind::Sphere:
          if (!(w.radius > r)) { ref.supported = false; return ref; }
          l.kind = Kind::Sphere; l.p = ld<D>(w.point) - O; l.rho = LD(w.radius) - R; break;
        case WallKind::Vertex:
          l.kind = Kind::Sphere; l.p = ld<D>(w.point) - O; l.rho = R; break;
        case WallKind::Cylinder:
          if (D == 2 || !(w.radius > r)) { ref.supported = false; return ref; }
          l.kind = Kind::Cylinder; l.p = ld<D>(w.point) - O; l.n = ld<D>(w.axis); l.rho = LD(w.radius) - R; break;
      }
    }
    L.push_back(l);
  }
  auto emit = [&](const VecL<D>& y) { ref.positions.push_back(O + y); };
  // Radical plane a.y = b of locus l against sphere s (absolute frame coordinates).
  auto radical = [](const LocusL<D>& s, const LocusL<D>& l, VecL<D>& a, LD& b) {
    if (l.kind == Kind::Plane) { a = l.n; b = l.rho; return; }
    // |y-p_s|^2 - rho_s^2 = |y-p|^2 - rho^2  =>  2(p - p_s).y = |p|^2 - |p_s|^2 - rho^2 + rho_s^2
    a = 2 * (l.p - s.p);
    b = l.p.squaredNorm() - s.p.squaredNorm() - l.rho * l.rho + s.rho * s.rho;
  };
  int ncyl = 0, cyl = -1, sph = -1;
  for (int i = 0; i < D; ++i) {
    if (L[i].kind == Kind::Cylinder) { ++ncyl; cyl = i; }
    if (L[i].kind == Kind::Sphere && sph < 0) sph = i;
  }
  if (ncyl > 1) { ref.supported = false; return ref; }
  // Relative thresholds of "too close to call".
  constexpr LD kSine = 1e-4L, kRoot = 1e-6L;

  if constexpr (D == 2) {
    if (sph < 0) {  // two lines
      const LD det = L[0].n[0] * L[1].n[1] - L[0].n[1] * L[1].n[0];
      if (std::abs(det) < kSine) { ref.ambiguous = true; return ref; }
      emit(VecL<D>((L[0].rho * L[1].n[1] - L[1].rho * L[0].n[1]) / det, (L[0].n[0] * L[1].rho - L[1].n[0] * L[0].rho) / det));
      return ref;
    }
    const LocusL<D>& S = L[sph];
    VecL<D> a; LD b;
    radical(S, L[1 - sph], a, b);
    const LD an = a.norm();
    if (an < kSine * S.rho) { ref.ambiguous = true; return ref; }
    // Closest point of the line to S.p, then +- along the line.
    const VecL<D> n = a / an;
    const LD dist = b / an - n.dot(S.p);
    const LD t2 = S.rho * S.rho - dist * dist;
    if (std::abs(t2) < kRoot * S.rho * S.rho) { ref.ambiguous = true; return ref; }
    if (t2 < 0) return ref;
    const VecL<D> foot = S.p + dist * n, u(-n[1], n[0]);
    emit(foot + std::sqrt(t2) * u);
    emit(foot - std::sqrt(t2) * u);
    return ref;
  } else {
    auto line_of = [&](const VecL<D>& a1, LD b1, const VecL<D>& a2, LD b2, VecL<D>& y0, VecL<D>& u) {
      const VecL<D> c = a1.cross(a2);
      if (c.norm() < kSine * a1.norm() * a2.norm()) return false;
      // y0 = point of the line closest to the origin.
      y0 = (b1 * a2.cross(c) + b2 * c.cross(a1)) / c.squaredNorm();
      u = c.normalized();
      return true;
    };
    if (ncyl == 0) {
      if (sph < 0) {  // three planes
        Eigen::Matrix<LD, 3, 3> A;
        for (int i = 0; i < 3; ++i) A.row(i) = L[i].n.transpose();
        if (std::abs(A.determinant()) < kSine) { ref.ambiguous = true; return ref; }
        emit(A.fullPivLu().solve(VecL<D>(L[0].rho, L[1].rho, L[2].rho)));
        return ref;
      }
      const LocusL<D>& S = L[sph];
      VecL<D> a1, a2, y0, u;
      LD b1, b2;
      radical(S, L[(sph + 1) % 3], a1, b1);
      radical(S, L[(sph + 2) % 3], a2, b2);
      if (!line_of(a1, b1, a2, b2, y0, u)) { ref.ambiguous = true; return ref; }
      const VecL<D> foot = y0 + u.dot(S.p - y0) * u;
      const LD t2 = S.rho * S.rho - (foot - S.p).squaredNorm();
      if (std::abs(t2) < kRoot * S.rho * S.rho) { ref.ambiguous = true; return ref; }
      if (t2 < 0) return ref;
      emit(foot + std::sqrt(t2) * u);
      emit(foot - std::sqrt(t2) * u);
      return ref;
    }
    const LocusL<D>& C = L[cyl];
    const LocusL<D>& A = L[(cyl + 1) % 3];
    const LocusL<D>& B = L[(cyl + 2) % 3];
    auto perp = [&](const VecL<D>& v) -> VecL<D> { return v - v.dot(C.n) * C.n; };
    if (A.kind == Kind::Plane && B.kind == Kind::Plane) {
      VecL<D> y0, u;
      if (!line_of(A.n, A.rho, B.n, B.rho, y0, u)) { ref.ambiguous = true; return ref; }
      const VecL<D> g = perp(y0 - C.p), up = perp(u);
      const LD qa = up.squaredNorm(), qb = g.dot(up), qc = g.squaredNorm() - C.rho * C.rho;
      if (qa < kSine) { ref.ambiguous = true; return ref; }
      const LD disc = qb * qb - qa * qc;
      if (std::abs(disc) < kRoot * qa * C.rho * C.rho) { ref.ambiguous = true; return ref; }
      if (disc < 0) return ref;
      emit(y0 + (-qb + std::sqrt(disc)) / qa * u);
      emit(y0 + (-qb - std::sqrt(disc)) / qa * u);
      return ref;
    }
    const LocusL<D>& S = (A.kind == Kind::Sphere) ? A : B;
    const LocusL<D>& other = (A.kind == Kind::Sphere) ? B : A;
    VecL<D> a; LD b;
    radical(S, other, a, b);
    const LD an = a.norm();
    if (an < kSine * S.rho) { ref.ambiguous = true; return ref; }
    const VecL<D> k = a / an;
    const LD dist = b / an - k.dot(S.p);  // signed distance from S.p to the radical plane
    const LD rc2 = S.rho * S.rho - dist * dist;
    if (std::abs(rc2) < kRoot * S.rho * S.rho) { ref.ambiguous = true; return ref; }
    if (rc2 < 0) return ref;
    const VecL<D> m = S.p + dist * k;
    const LD rc = std::sqrt(rc2);
    VecL<D> e1 = (std::abs(k[2]) < 0.6L ? VecL<D>(0, 0, 1) : VecL<D>(1, 0, 0)).cross(k).normalized();
    const VecL<D> e2 = k.cross(e1);
    const VecL<D> g = perp(m - C.p), p1 = perp(rc * e1), p2 = perp(rc * e2);
    std::vector<LD> roots;
    if (!trig_quadratic_roots(g.squaredNorm() + (p1.squaredNorm() + p2.squaredNorm()) / 2 - C.rho * C.rho,
                              2 * g.dot(p1), 2 * g.dot(p2), (p1.squaredNorm() - p2.squaredNorm()) / 2, p1.dot(p2), roots))
      ref.ambiguous = true;
    for (LD t : roots) emit(m + rc * (cosl_(t) * e1 + sinl_(t) * e2));
    return ref;
  }
}

/// Every solver position matches a distinct reference position within `tol`, and (unless the
/// reference is ambiguous) the counts agree.
template <int D>
::testing::AssertionResult check_against_reference(std::span<const Body<D>> fixed, double r,
                                                   std::span<const Placement<D>> out, double tol) {
  const Reference<D> ref = reference_solutions<D>(fixed, r);
  if (!ref.supported) {
    if (out.empty()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "solutions for an unsupported combination" << config_literal<D>(fixed, r);
  }
  if (ref.ambiguous) return ::testing::AssertionSuccess();
  if (out.size() != ref.positions.size())
    return ::testing::AssertionFailure() << "solver returned " << out.size() << " solutions, reference "
                                         << ref.positions.size() << config_literal<D>(fixed, r);
  std::vector<bool> used(ref.positions.size(), false);
  for (const Placement<D>& p : out) {
    int best = -1;
    LD best_d = 0;
    for (std::size_t q = 0; q < ref.positions.size(); ++q) {
      if (used[q]) continue;
      const LD d = (ld<D>(p.position) - ref.positions[q]).norm();
      if (best < 0 || d < best_d) { best = static_cast<int>(q); best_d = d; }
    }
    if (best < 0 || !(best_d <= tol))
      return ::testing::AssertionFailure() << "solution " << vec_literal<D>(p.position) << " is "
                                           << static_cast<double>(best_d) << " from the nearest reference solution (tolerance "
                                           << tol << ")" << config_literal<D>(fixed, r);
    used[best] = true;
  }
  return ::testing::AssertionSuccess();
}

// ---- random configurations ----

template <int D>
Vec<D> random_unit(Rng& rng) {
  for (;;) {
    Vec<D> v;
    for (int a = 0; a < D; ++a) v[a] = rng.uniform(-1.0, 1.0);
    const double n = v.norm();
    if (n > 0.1 && n <= 1.0) return v / n;
  }
}

/// Log-uniform in [lo, hi].
inline double log_uniform(Rng& rng, double lo, double hi) { return lo * std::pow(hi / lo, rng.uniform01()); }

enum class BodyKind { Particle, Plane, SphereWall, Cylinder, Vertex };

inline const char* kind_name(BodyKind k) {
  switch (k) {
    case BodyKind::Particle: return "particle";
    case BodyKind::Plane: return "plane";
    case BodyKind::SphereWall: return "sphere-wall";
    case BodyKind::Cylinder: return "cylinder";
    case BodyKind::Vertex: return "vertex";
  }
  return "?";
}

/// A configuration that owns its walls (bodies point into `walls`, a deque so they never move).
template <int D>
struct Config {
  std::deque<Wall<D>> walls;
  std::array<Body<D>, D> fixed;
  double r = 1;
  std::span<const Body<D>> span() const { return {fixed.data(), static_cast<std::size_t>(D)}; }
};

/// A body of kind `k` touching the ball (x, r) in direction d (unit; the body lies on that side
/// of x), sized by `size` (particle radius, or concave wall radius = r + size). Returns the unit
/// normal of the gap's gradient at x, for conditioning checks.
template <int D>
Vec<D> add_tangent_body(Config<D>& cfg, int slot, BodyKind k, const Vec<D>& x, double r, const Vec<D>& d,
                        double size, Rng& rng) {
  switch (k) {
    case BodyKind::Particle:
      cfg.fixed[slot] = Body<D>::sphere(x + (r + size) * d, size);
      return -d;
    case BodyKind::Plane:
      cfg.walls.push_back(Wall<D>::plane(x + r * d, -d));
      break;
    case BodyKind::SphereWall:
      cfg.walls.push_back(Wall<D>::sphere(x - size * d, r + size));
      break;
    case BodyKind::Cylinder: {
      if constexpr (D == 3) {
        // Axis perpendicular to d, random around it.
        Vec<D> a = random_unit<D>(rng);
        a -= a.dot(d) * d;
        a.normalize();
        cfg.walls.push_back(Wall<D>::cylinder(x - size * d + rng.uniform(-3, 3) * (r + size) * a, a, r + size));
      }
      break;
    }
    case BodyKind::Vertex:
      cfg.walls.push_back(Wall<D>::vertex(x + r * d));
      break;
  }
  cfg.fixed[slot] = Body<D>::of_wall(cfg.walls.back());
  return -d;
}

/// Smallest singular value of the rows `normals` (the gap Jacobian at the solution):
/// small means the solution is ill-conditioned (near a double root or a degenerate set).
template <int D>
double sigma_min(const std::array<Vec<D>, D>& normals) {
  Eigen::Matrix<double, D, D> J;
  for (int i = 0; i < D; ++i) J.row(i) = normals[i].transpose();
  const Eigen::Matrix<double, D, D> G = J * J.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> es(G, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, es.eigenvalues().minCoeff()));
}

/// Index of the solution closest to x, and its distance (-1 if none).
template <int D>
std::pair<int, double> closest(std::span<const Placement<D>> out, const Vec<D>& x) {
  int best = -1;
  double bd = 0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double d = (out[k].position - x).norm();
    if (best < 0 || d < bd) { best = static_cast<int>(k); bd = d; }
  }
  return {best, bd};
}

/// Counters of a batch of random configurations (printed by the tests, asserted on where they
/// guard against a test that silently checks nothing).
struct Tally {
  int configs = 0;          ///< solve() calls
  int well_conditioned = 0; ///< calls where the known solution had to be found
  int found = 0;            ///< ... and was
  int compared = 0;         ///< calls whose count was compared with the reference
  int solutions = 0;        ///< positions returned (all checked for tangency)
  double worst_gap = 0;     ///< max |gap| / (kGapTol * size) seen (must stay <= 1)
};

/// Sizes of a constructed configuration.
struct Ranges {
  double r_lo = 0.2, r_hi = 5;        ///< mobile radius
  double size_lo = 0.2, size_hi = 5;  ///< particle radius / concave wall radius minus r
  double spread = 5;                  ///< x uniform in offset + [-spread, spread]^D
  double offset = 0;
  std::vector<std::pair<double, double>> slot_sizes;  ///< optional per-body size range
};

/// Below this smallest singular value of the gap Jacobian the known solution is a near double
/// root: the solver may legitimately merge or drop it, so only tangency is asserted.
inline constexpr double kWellConditioned = 1e-2;

/// Builds `trials` configurations of the given kinds touching a known ball (x, r), solves each in
/// every order of its bodies and asserts: every position is tangent (check_tangent), the solution
/// set matches the reference solver, and x is found when well conditioned — within the distance
/// the gap tolerance allows, 2 sqrt(D) kGapTol r / sigma_min.
template <int D>
void run_constructed(const std::array<BodyKind, D>& kinds, int trials, std::uint64_t seed, const Ranges& g,
                     Tally& t) {
  Rng rng(seed);
  const SphereContactSolver<D> solver;
  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> out;
  for (int trial = 0; trial < trials; ++trial) {
    Config<D> cfg;
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = g.offset + rng.uniform(-g.spread, g.spread);
    const double r = log_uniform(rng, g.r_lo, g.r_hi);
    cfg.r = r;
    std::array<Vec<D>, D> normals;
    for (int i = 0; i < D; ++i)
      normals[i] = add_tangent_body<D>(cfg, i, kinds[i], x, r, random_unit<D>(rng),
                                       i < static_cast<int>(g.slot_sizes.size())
                                           ? log_uniform(rng, g.slot_sizes[i].first, g.slot_sizes[i].second)
                                           : log_uniform(rng, g.size_lo, g.size_hi),
                                       rng);
    const double smin = sigma_min<D>(normals);
    std::array<int, D> order;
    for (int i = 0; i < D; ++i) order[i] = i;
    do {
      std::array<Body<D>, D> f;
      for (int i = 0; i < D; ++i) f[i] = cfg.fixed[order[i]];
      const std::span<const Body<D>> fs(f.data(), D);
      const int n = solver.solve(fs, Mobile<D>{r}, out);
      const std::span<const Placement<D>> sol(out.data(), n);
      ++t.configs;
      t.solutions += n;
      ASSERT_TRUE(check_tangent<D>(fs, r, sol));
      for (const auto& p : sol)
        for (const auto& b : f) t.worst_gap = std::max(t.worst_gap, static_cast<double>(std::abs(gap_ld<D>(b, p.position, r))) / (kGapTol * body_size<D>(b, r)));
      const Reference<D> ref = reference_solutions<D>(fs, r);
      if (ref.supported && !ref.ambiguous) ++t.compared;
      ASSERT_TRUE(check_against_reference<D>(fs, r, sol, 1e-6 * r));
      if (smin >= kWellConditioned) {
        ++t.well_conditioned;
        const auto [k, dist] = closest<D>(sol, x);
        const double tol = 2 * std::sqrt(double(D)) * kGapTol * r / smin;
        ASSERT_TRUE(k >= 0 && dist <= tol) << "known solution " << vec_literal<D>(x) << " not found (nearest at " << dist
                                           << ", tolerance " << tol << ", sigma_min " << smin << ")"
                                           << config_literal<D>(fs, r);
        ++t.found;
      }
    } while (std::next_permutation(order.begin(), order.end()));
  }
}

}  // namespace fp::contact_test
