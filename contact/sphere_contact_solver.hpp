#pragma once
// Analytic contact solver for disks (2D) and spheres (3D): the positions of a mobile ball of
// radius r touching D fixed bodies, each a ball (a particle) or a container wall.
//
// Method (paper 002, Sect. 2, function f; design.md "Sphere tangent to three spheres"):
// the centre of a ball of radius r touching a body lies on that body's *centre locus*:
//   particle (c_i, r_i)        -> sphere |x - c_i| = r_i + r          (outer contact)
//   concave sphere wall (C, R) -> sphere |x - C|   = R - r            (inner contact)
//   vertex v                   -> sphere |x - v|   = r
//   plane wall (p, n inward)   -> plane  n.(x - p) = r
//   cylinder wall (axis, R)    -> cylinder of radius R - r            (3D only)
// Subtracting one sphere equation from the others leaves linear equations (radical planes),
// so D loci of sphere/plane type reduce to a line cut by one sphere: a quadratic. A cylinder
// locus is cut by the circle (or line) the other two loci define: a trigonometric polynomial
// of degree 2 in the circle angle, whose roots are bracketed on a fixed grid and polished.
//
// Frame: everything is expressed in a frame centred on `origin` (the front particle's centre)
// and scaled by `scale` (its locus radius r0 + r), so coordinates offset by 1e6 or radii of
// 1e-6 keep their digits. Quantities like |q|^2 - rho^2 are formed as (|q|-rho)(|q|+rho).
//
// Touching rule and degeneracy: a configuration is rejected (0 solutions) when the radical
// planes are nearly parallel (collinear / coplanar centres), tested relative to the norms of
// the normals, never with an absolute epsilon. Every returned position is verified: its gap to
// each body is at most kTangencyTol * min(r, r_body) (after at most two Newton steps); a
// position that fails is dropped, never returned.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "contact/contact_solver.hpp"

namespace fp {

namespace sphere_contact_detail {

enum class LocusKind { Sphere, Plane, Cylinder };

/// A locus of centres in the local frame. Sphere: |y - p| = rho. Plane: n.y = rho (n unit).
/// Cylinder: distance from y to the line (p, n) = rho.
template <int D>
struct Locus {
  LocusKind kind;
  Vec<D> p;
  Vec<D> n;
  double rho;
};

}  // namespace sphere_contact_detail

template <int D>
class SphereContactSolver final : public ContactSolver<D> {
 public:
  /// A returned position's gap to every body is within this fraction of min(r, r_body).
  static constexpr double kTangencyTol = 1e-10;
  /// Radical planes whose normals make a sine below this are treated as parallel.
  static constexpr double kParallelTol = 1e-9;

  int solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile,
            std::span<Placement<D>> out) const override {
    if (fixed.size() != static_cast<std::size_t>(D) || fixed.empty()) return 0;
    // Frame on the first particle if there is one: a wall's reference point (a box corner, a
    // facet vertex) can be far from the contact, and the frame's rounding would then exceed the
    // tolerance the verification is meant to guarantee.
    const Body<D>* b0 = &fixed[0];
    for (const Body<D>& b : fixed)
      if (!b.is_wall()) { b0 = &b; break; }
    const Vec<D> origin = b0->is_wall() ? b0->wall->point : b0->center;
    const double scale = b0->is_wall() ? mobile.radius : b0->radius + mobile.radius;
    return solve_in_frame(fixed, mobile.radius, origin, scale, out);
  }

  /// Batched form for the front manager: one front particle s0 (the frame), one mobile radius,
  /// many pairs of bodies. begin() precomputes every body's radical plane relative to s0's
  /// centre locus (the unit sphere of the frame), so a particle-particle pair costs one cross
  /// product, one square root and, for ill-conditioned pairs only, the Newton verification.
  /// Pairs involving a wall go through solve_in_frame(). Results are the same positions
  /// solve() returns for (s0, bodies[i], bodies[j]).
  class Session {
   public:
    void begin(const Body<D>& s0, double r, std::span<const Body<D>> bodies) {
      s0_ = s0;
      r_ = r;
      bodies_ = bodies;
      origin_ = s0.center;
      scale_ = s0.radius + r;
      const double inv = 1.0 / scale_;
      a_.resize(bodies.size());
      b_.resize(bodies.size());
      for (std::size_t k = 0; k < bodies.size(); ++k) {
        if (bodies[k].is_wall()) continue;
        // Radical plane of body k against the unit sphere |y| = 1: a.y = b (see radical()).
        a_[k] = (bodies[k].center - origin_) * inv;
        const double q = a_[k].norm();
        const double rho = (bodies[k].radius + r) * inv;
        b_[k] = 0.5 * ((q - rho) * (q + rho) + 1.0);
      }
    }

    /// 3D: positions touching s0, bodies[i] and bodies[j].  2D: touching s0 and bodies[i] (j ignored).
    int solve(int i, int j, std::span<Placement<D>> out) const {
      const Body<D>& bi = bodies_[i];
      if constexpr (D == 2) {
        if (bi.is_wall()) return general(i, j, out);
        const Vec2& a = a_[i];
        const double an2 = a.squaredNorm();
        if (!(an2 > kParallelTol * kParallelTol)) return 0;
        const Vec2 y0 = a * (b_[i] / an2);
        const double t2 = 1.0 - y0.squaredNorm();
        if (!(t2 > 1e-8)) return t2 < -kParallelTol ? 0 : general(i, j, out);  // near-tangent: careful path
        const double t = std::sqrt(t2 / an2);
        const Vec2 u(-a.y() * t, a.x() * t);
        out[0].position = origin_ + scale_ * (y0 + u);
        out[1].position = origin_ + scale_ * (y0 - u);
        return 2;
      } else {
        const Body<D>& bj = bodies_[j];
        if (bi.is_wall() || bj.is_wall()) return general(i, j, out);
        const Vec3& a1 = a_[i];
        const Vec3& a2 = a_[j];
        const Vec3 c = a1.cross(a2);
        const double cn2 = c.squaredNorm();
        const double scale2 = a1.squaredNorm() * a2.squaredNorm();
        if (!(cn2 > kParallelTol * kParallelTol * scale2)) return 0;
        const Vec3 y0 = (b_[i] * a2.cross(c) + b_[j] * c.cross(a1)) / cn2;
        const double t2 = 1.0 - y0.squaredNorm();
        if (t2 < -kParallelTol) return 0;
        // Well-conditioned pairs (planes far from parallel, roots well apart) are exact to a
        // few ulps of the frame; the others take the verified path.
        if (!(cn2 > 1e-4 * scale2) || !(t2 > 1e-8)) return general(i, j, out);
        const Vec3 u = c * std::sqrt(t2 / cn2);
        out[0].position = origin_ + scale_ * (y0 + u);
        out[1].position = origin_ + scale_ * (y0 - u);
        return 2;
      }
    }

   private:
    int general(int i, int j, std::span<Placement<D>> out) const {
      std::array<Body<D>, D> f;
      f[0] = s0_;
      f[1] = bodies_[i];
      if constexpr (D == 3) f[2] = bodies_[j];
      (void)j;
      return SphereContactSolver{}.solve_in_frame(std::span<const Body<D>>(f.data(), D), r_, origin_, scale_, out);
    }

    Body<D> s0_;
    double r_ = 0, scale_ = 1;
    Vec<D> origin_;
    std::span<const Body<D>> bodies_;
    std::vector<Vec<D>> a_;
    std::vector<double> b_;
  };

  /// The workhorse: as solve(), with the local frame given explicitly.
  int solve_in_frame(std::span<const Body<D>> fixed, double r, const Vec<D>& origin, double scale,
                     std::span<Placement<D>> out) const {
    using namespace sphere_contact_detail;
    if (!(r > 0.0) || !(scale > 0.0) || fixed.size() != static_cast<std::size_t>(D)) return 0;
    const double inv = 1.0 / scale;
    std::array<Locus, D> loci;
    for (int i = 0; i < D; ++i)
      if (!make_locus(fixed[i], r, origin, inv, loci[i])) return 0;

    std::array<Vec<D>, ContactSolver<D>::kMaxSolutions> local;
    int n = 0;
    if constexpr (D == 2) n = intersect2(loci, local);
    else n = intersect3(loci, local);

    int kept = 0;
    for (int k = 0; k < n && kept < static_cast<int>(out.size()); ++k) {
      Vec<D> y = local[k];
      if (!verify(loci, fixed, r, inv, y)) continue;
      out[kept++].position = origin + scale * y;
    }
    return kept;
  }

 private:
  using Locus = sphere_contact_detail::Locus<D>;
  using LocusKind = sphere_contact_detail::LocusKind;
  using Sols = std::array<Vec<D>, ContactSolver<D>::kMaxSolutions>;

  static bool make_locus(const Body<D>& b, double r, const Vec<D>& o, double inv, Locus& L) {
    if (!b.is_wall()) {
      L.kind = LocusKind::Sphere;
      L.p = (b.center - o) * inv;
      L.rho = (b.radius + r) * inv;
      return true;
    }
    const Wall<D>& w = *b.wall;
    switch (w.kind) {
      case WallKind::Plane:
        L.kind = LocusKind::Plane;
        L.n = w.normal;
        L.rho = (r + w.normal.dot(w.point - o)) * inv;
        return true;
      case WallKind::Sphere:
        if (!(w.radius > r)) return false;
        L.kind = LocusKind::Sphere;
        L.p = (w.point - o) * inv;
        L.rho = (w.radius - r) * inv;
        return true;
      case WallKind::Cylinder:
        if constexpr (D == 2) return false;
        if (!(w.radius > r)) return false;
        L.kind = LocusKind::Cylinder;
        L.p = (w.point - o) * inv;
        L.n = w.axis;
        L.rho = (w.radius - r) * inv;
        return true;
      case WallKind::Vertex:
        L.kind = LocusKind::Sphere;
        L.p = (w.point - o) * inv;
        L.rho = r * inv;
        return true;
    }
    return false;
  }

  /// Linear equation a.y = b that locus `L` imposes relative to the reference sphere `S`
  /// (radical plane) in coordinates centred on S's centre.
  static void radical(const Locus& S, const Locus& L, Vec<D>& a, double& b) {
    if (L.kind == LocusKind::Plane) {
      a = L.n;
      b = L.rho - L.n.dot(S.p);
      return;
    }
    // |y|^2 = rho_s^2 and |y - q|^2 = rho^2  =>  q.y = ((|q| - rho)(|q| + rho) + rho_s^2) / 2
    a = L.p - S.p;
    const double q = a.norm();
    b = 0.5 * ((q - L.rho) * (q + L.rho) + S.rho * S.rho);
  }

  /// y0 +- t u on the reference sphere of radius rho (y0 is perpendicular to u; centred frame).
  static int line_sphere(const Vec<D>& y0, const Vec<D>& u_unit, double rho, const Vec<D>& centre, Sols& s) {
    const double t2 = (rho - y0.norm()) * (rho + y0.norm());
    if (t2 < -kParallelTol * rho * rho) return 0;
    if (t2 <= kParallelTol * kParallelTol * rho * rho) {
      s[0] = centre + y0;
      return 1;
    }
    const double t = std::sqrt(t2);
    s[0] = centre + y0 + t * u_unit;
    s[1] = centre + y0 - t * u_unit;
    return 2;
  }

  // ---- 2D: two loci (circles and lines) ----
  static int intersect2(const std::array<Locus, D>& L, Sols& s) requires(D == 2) {
    int si = -1;
    for (int i = 0; i < 2; ++i)
      if (L[i].kind == LocusKind::Sphere) { si = i; break; }
    if (si < 0) {  // two lines: one point
      Eigen::Matrix2d A;
      A << L[0].n.transpose(), L[1].n.transpose();
      const double det = A.determinant();
      if (std::abs(det) < kParallelTol) return 0;  // unit normals: det is the sine of their angle
      s[0] = A.inverse() * Vec2(L[0].rho, L[1].rho);
      return 1;
    }
    const Locus& S = L[si];
    Vec2 a;
    double b;
    radical(S, L[1 - si], a, b);
    const double an = a.norm();
    if (!(an > kParallelTol * S.rho)) return 0;  // concentric circles
    const Vec2 n = a / an;
    return line_sphere(n * (b / an), Vec2(-n.y(), n.x()), S.rho, S.p, s);
  }

  // ---- 3D: three loci (spheres, planes, at most one cylinder) ----
  static int intersect3(const std::array<Locus, D>& L, Sols& s) requires(D == 3) {
    int cyl = -1, ncyl = 0, si = -1;
    for (int i = 0; i < 3; ++i) {
      if (L[i].kind == LocusKind::Cylinder) { cyl = i; ++ncyl; }
      else if (L[i].kind == LocusKind::Sphere && si < 0) si = i;
    }
    if (ncyl > 1) return 0;
    if (ncyl == 0) {
      if (si < 0) return three_planes(L, s);
      const Locus& S = L[si];
      Vec3 a1, a2;
      double b1, b2;
      radical(S, L[(si + 1) % 3], a1, b1);
      radical(S, L[(si + 2) % 3], a2, b2);
      Vec3 y0, u;
      if (!plane_pair_line(a1, b1, a2, b2, y0, u)) return 0;
      return line_sphere(y0, u, S.rho, S.p, s);
    }
    const Locus& C = L[cyl];
    const Locus& A = L[(cyl + 1) % 3];
    const Locus& B = L[(cyl + 2) % 3];
    if (A.kind == LocusKind::Plane && B.kind == LocusKind::Plane) {
      Vec3 y0, u;  // frame origin at 0 here: planes are n.y = rho
      if (!plane_pair_line(A.n, A.rho, B.n, B.rho, y0, u)) return 0;
      return line_cylinder(y0, u, C, s);
    }
    const Locus& S = (A.kind == LocusKind::Sphere) ? A : B;
    const Locus& other = (A.kind == LocusKind::Sphere) ? B : A;
    Vec3 a;
    double b;
    radical(S, other, a, b);
    const double an = a.norm();
    if (!(an > kParallelTol * S.rho)) return 0;
    const Vec3 k = a / an;
    const double delta = b / an;
    const double rc2 = (S.rho - delta) * (S.rho + delta);
    if (!(rc2 > 0.0)) return 0;
    return circle_cylinder(S.p + delta * k, k, std::sqrt(rc2), C, s);
  }

  /// Line of two planes a1.y = b1, a2.y = b2: point y0 (perpendicular to u) and unit direction u.
  static bool plane_pair_line(const Vec3& a1, double b1, const Vec3& a2, double b2, Vec3& y0, Vec3& u)
    requires(D == 3) {
    const Vec3 c = a1.cross(a2);
    const double cn2 = c.squaredNorm();
    if (!(cn2 > kParallelTol * kParallelTol * a1.squaredNorm() * a2.squaredNorm())) return false;
    y0 = (b1 * a2.cross(c) + b2 * c.cross(a1)) / cn2;
    u = c / std::sqrt(cn2);
    return true;
  }

  static int three_planes(const std::array<Locus, D>& L, Sols& s) requires(D == 3) {
    Eigen::Matrix3d A;
    A << L[0].n.transpose(), L[1].n.transpose(), L[2].n.transpose();
    const double det = A.determinant();  // unit normals: |det| <= 1
    if (std::abs(det) < kParallelTol) return 0;
    s[0] = A.partialPivLu().solve(Vec3(L[0].rho, L[1].rho, L[2].rho));
    return 1;
  }

  static int line_cylinder(const Vec3& y0, const Vec3& u, const Locus& C, Sols& s) requires(D == 3) {
    const Vec3 g = y0 - C.p;
    const Vec3 gp = g - g.dot(C.n) * C.n;
    const Vec3 up = u - u.dot(C.n) * C.n;
    const double qa = up.squaredNorm();
    if (!(qa > kParallelTol)) return 0;  // line parallel to the axis
    const double qb = gp.dot(up);
    const double gn = gp.norm();
    const double qc = (gn - C.rho) * (gn + C.rho);
    const double disc = qb * qb - qa * qc;
    if (disc < 0.0) return 0;
    const double sq = std::sqrt(disc);
    // Numerically stable pair of roots of qa t^2 + 2 qb t + qc = 0.
    const double q = -(qb + std::copysign(sq, qb));
    int n = 0;
    if (q != 0.0) s[n++] = y0 + (qc / q) * u;
    s[n++] = y0 + (q / qa) * u;
    return n;
  }

  /// Circle (centre m, unit normal k, radius rc) against a cylinder locus: roots of
  /// f(t) = |perp(m + rc(cos t e1 + sin t e2) - p)|^2 - rho^2, a trigonometric polynomial of
  /// degree 2 with at most 4 roots, bracketed on a fixed grid and refined by Newton/bisection.
  /// A sign test per cell misses two roots inside one cell (and sees one of three). With M a
  /// bound on |f''|, a cell is skipped when f cannot vanish on it (|f - linear interpolant| <=
  /// M h^2 / 8), solved directly when f is monotone on it (|f'(t0)| > M h), and otherwise split
  /// where f' changes sign on a finer sub-grid: each monotone piece holds a root exactly when its
  /// ends differ in sign.
  static int circle_cylinder(const Vec3& m, const Vec3& k, double rc, const Locus& C, Sols& s)
    requires(D == 3) {
    Vec3 e1 = (std::abs(k.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY()).cross(k).normalized();
    Vec3 e2 = k.cross(e1);
    auto perp = [&](const Vec3& v) -> Vec3 { return v - v.dot(C.n) * C.n; };
    const Vec3 g = perp(m - C.p), p1 = perp(rc * e1), p2 = perp(rc * e2);
    auto f = [&](double t) { return (g + std::cos(t) * p1 + std::sin(t) * p2).squaredNorm() - C.rho * C.rho; };
    auto df = [&](double t) {
      const Vec3 w = g + std::cos(t) * p1 + std::sin(t) * p2;
      return 2.0 * w.dot(-std::sin(t) * p1 + std::cos(t) * p2);
    };
    // Root in [lo, hi] where f(lo) has the sign of flo and f(hi) the other.
    auto refine = [&](double lo, double hi, double flo) {
      double t = 0.5 * (lo + hi);
      for (int it = 0; it < 100; ++it) {
        const double ft = f(t);
        if (ft == 0.0) break;
        if ((ft < 0.0) == (flo < 0.0)) { lo = t; flo = ft; } else { hi = t; }
        const double d = df(t);
        double tn = (d != 0.0) ? t - ft / d : 0.5 * (lo + hi);
        if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi);
        if (std::abs(tn - t) <= 1e-15 * (1.0 + std::abs(t))) { t = tn; break; }
        t = tn;
      }
      return t;
    };
    auto point = [&](double t) -> Vec3 { return m + rc * (std::cos(t) * e1 + std::sin(t) * e2); };
    constexpr int kSteps = 96, kSub = 16;
    constexpr int kMax = ContactSolver<D>::kMaxSolutions;
    const double h = 2.0 * kPi / kSteps;
    // |f''| <= 2|w'|^2 + 2|w||w''| with |w'|, |w''| <= |p1| + |p2| and |w| <= |g| + |p1| + |p2|.
    const double P = p1.norm() + p2.norm();
    const double f2max = 2.0 * P * (P + g.norm() + P);
    std::array<double, kSteps + 1> fs;
    for (int i = 0; i < kSteps; ++i) fs[i] = f(h * i);
    fs[kSteps] = fs[0];
    int n = 0;
    auto emit = [&](double t) {
      if (n < kMax) s[n++] = point(t);
    };
    for (int i = 0; i < kSteps && n < kMax; ++i) {
      const double t0 = h * i, t1 = t0 + h, f0 = fs[i], f1 = fs[i + 1];
      if (f0 == 0.0) emit(t0);  // a root on the grid belongs to the cell it starts
      const bool change = f0 != 0.0 && f1 != 0.0 && (f0 < 0.0) != (f1 < 0.0);
      if (!change && std::min(std::abs(f0), std::abs(f1)) > 0.125 * f2max * h * h) continue;
      double u = t0, fu = f0, du = df(t0);
      if (std::abs(du) > f2max * h) {  // f' keeps its sign on the cell
        if (change) emit(refine(t0, t1, f0));
        continue;
      }
      auto piece = [&](double v, double fv) {  // f is monotone on [u, v]; a root at u is out already
        if (fu != 0.0 && fv != 0.0 && (fu < 0.0) != (fv < 0.0)) emit(refine(u, v, fu));
        u = v;
        fu = fv;
      };
      const double sub = h / kSub;
      for (int j = 1; j <= kSub; ++j) {
        const double b = t0 + sub * j;
        const double db = df(b);
        if ((du < 0.0) == (db < 0.0)) continue;
        double lo = b - sub, hi = b;  // a critical point of f in [lo, hi]
        for (int it = 0; it < 40; ++it) {
          const double mid = 0.5 * (lo + hi);
          if ((df(mid) < 0.0) == (du < 0.0)) lo = mid; else hi = mid;
        }
        const double v = 0.5 * (lo + hi), fv = f(v);
        piece(v, fv);
        if (fv == 0.0) emit(v);  // a double root
        du = db;
      }
      piece(t1, f1);
    }
    return n;
  }

  /// Signed residual of y on locus L (local units) and its gradient.
  static double residual(const Locus& L, const Vec<D>& y, Vec<D>& grad) {
    switch (L.kind) {
      case LocusKind::Sphere: {
        const Vec<D> d = y - L.p;
        const double dn = d.norm();
        grad = dn > 0.0 ? Vec<D>(d / dn) : Vec<D>::Zero();
        return dn - L.rho;
      }
      case LocusKind::Plane:
        grad = L.n;
        return L.n.dot(y) - L.rho;
      case LocusKind::Cylinder: {
        const Vec<D> d = y - L.p;
        const Vec<D> dp = d - d.dot(L.n) * L.n;
        const double dn = dp.norm();
        grad = dn > 0.0 ? Vec<D>(dp / dn) : Vec<D>::Zero();
        return dn - L.rho;
      }
    }
    return 0.0;
  }

  /// Accepts y if every gap is within kTangencyTol * min(r, r_body); tries two Newton steps
  /// on the D x D system of gaps first if needed (ill-conditioned but valid configurations).
  static bool verify(const std::array<Locus, D>& L, std::span<const Body<D>> fixed, double r, double inv,
                     Vec<D>& y) {
    for (int iter = 0; iter < 3; ++iter) {
      Eigen::Matrix<double, D, D> J;
      Vec<D> F;
      bool ok = true;
      for (int i = 0; i < D; ++i) {
        Vec<D> g = Vec<D>::Zero();  // residual() sets it for every locus kind; GCC cannot see that
        F[i] = residual(L[i], y, g);
        J.row(i) = g.transpose();
        const double size = fixed[i].is_wall() ? r : std::min(r, fixed[i].radius);
        if (!(std::abs(F[i]) <= kTangencyTol * size * inv)) ok = false;
      }
      if (ok) return true;
      if (iter == 2) break;
      const auto lu = J.fullPivLu();
      if (!lu.isInvertible()) return false;
      y -= lu.solve(F);
    }
    return false;
  }
};

}  // namespace fp
