#pragma once
// Signed gap of two smooth convex bodies E = {c + M u + rho w : |u| <= 1, |w| <= 1}: an
// ellipsoid (M = R diag(semi-axes), rho = 0) or a ball (M = 0, rho = r), in 2D and 3D, without
// FCL. Their support function is h(n) = c.n + |M^T n| + rho |n|, smooth, so the separating-axis
// form of the signed distance (support_gap in narrow_phase.cpp)
//   gap = max over unit n of f(n) = d.n - |Ma^T n| - |Mb^T n| - rho_a - rho_b,   d = c_b - c_a,
// (the distance when apart, minus the penetration depth on overlap) is maximised by Newton's
// method on the unit sphere, with the exact Hessian: a few iterations to rounding, where FCL's
// GJK on fcl::Ellipsoid took ~10 us per query at the 1e-10 tolerance the minimiser needs (and
// an ascent of ~100 support evaluations on overlap). The maximiser n is d(gap)/d(c_b).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "contact/narrow_phase.hpp"
#include "core/geometry/vec.hpp"
#include "shapes/ellipsoid_shape.hpp"

namespace fp {

template <int D>
struct SmoothConvexBody {
  Vec<D> center;
  Mat<D> M = Mat<D>::Zero();  ///< the linear part: R diag(semi-axes) for an ellipsoid, 0 for a ball
  Mat<D> Q = Mat<D>::Zero();  ///< M M^T: |M^T n| = sqrt(n^T Q n)
  double rho = 0.0;           ///< rounding radius: a ball's radius
  /// An ellipsoid's M^-1 = diag(1 / semi-axes) R^T and least semi-axis (depth_inside uses them).
  Mat<D> M_inverse = Mat<D>::Zero();
  double least_axis = 0.0;

  /// A lower bound of how deep x lies inside (<= 0: not inside): for an ellipsoid, with
  /// y = M^-1 (x - c), the boundary is at least (1 - |y|) x the least semi-axis away.
  double depth_inside(const Vec<D>& x) const {
    if (least_axis > 0) return (1 - (M_inverse * (x - center)).norm()) * least_axis;
    return rho - (x - center).norm();
  }
};

/// A ball of radius r about c.
template <int D>
SmoothConvexBody<D> smooth_ball(const Vec<D>& c, double r) {
  SmoothConvexBody<D> s;
  s.center = c;
  s.rho = r;
  return s;
}

/// The body of an ellipsoid (ellipse) at rotation R about c; any other shape is taken for the
/// sphere (disk) of its circumscribed radius (callers pass ellipsoids and spheres only).
template <int D>
SmoothConvexBody<D> smooth_convex_body(const Shape<D>& shape, const Mat<D>& R, const Vec<D>& c) {
  if (std::strcmp(shape.kind(), EllipsoidShape<D>::kKind) != 0) return smooth_ball<D>(c, shape.bounding_radius());
  SmoothConvexBody<D> s;
  s.center = c;
  const Vec<D>& axes = static_cast<const EllipsoidShape<D>&>(shape).semi_axes();
  s.M = R * axes.asDiagonal();
  s.Q = s.M * s.M.transpose();
  s.M_inverse = axes.cwiseInverse().asDiagonal() * R.transpose();
  s.least_axis = axes.minCoeff();
  return s;
}

/// sign x |M^T n| = sign x sqrt(n^T Q n) at n, added to f (if given), its gradient to g and its
/// Hessian to H (if given): the support-function terms of the gap and of the wrappers. A ball's
/// Q = 0 adds nothing.
template <int D>
void add_support_norm(const Mat<D>& Q, const Vec<D>& n, double sign, double* f, Vec<D>& g, Mat<D>* H) {
  const Vec<D> q = Q * n;
  const double N2 = n.dot(q);
  if (!(N2 > 0)) return;
  const double N = std::sqrt(N2);
  if (f) *f += sign * N;
  g += sign * (q / N);
  if (H) *H += sign * ((Q - q * q.transpose() / N2) / N);
}

namespace ellipsoid_gap_detail {

/// f(n), its gradient and Hessian in R^D (f is 1-homogeneous: the norms |M^T n| are convex).
template <int D>
struct Local {
  double f;
  Vec<D> g;
  Mat<D> H;
};

template <int D>
Local<D> evaluate(const Vec<D>& d, const Mat<D>& Qa, const Mat<D>& Qb, double rho, const Vec<D>& n) {
  Local<D> L{d.dot(n) - rho, d, Mat<D>::Zero()};
  add_support_norm<D>(Qa, n, -1.0, &L.f, L.g, &L.H);
  add_support_norm<D>(Qb, n, -1.0, &L.f, L.g, &L.H);
  return L;
}

/// An orthonormal basis of the plane (line) orthogonal to the unit n, as columns.
template <int D>
Eigen::Matrix<double, D, D - 1> tangent_basis(const Vec<D>& n) {
  Eigen::Matrix<double, D, D - 1> T;
  if constexpr (D == 2) {
    T.col(0) = Vec2(-n.y(), n.x());
  } else {
    const Vec3 e1 = (std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    T.col(0) = e1;
    T.col(1) = n.cross(e1);
  }
  return T;
}

/// Newton's method for max f on the unit sphere from n (unit): Riemannian gradient T^T g and
/// Hessian T^T (H - (n.g) I) T (n.g = f + rho by homogeneity), shifted to be negative definite
/// where it is not (overlap: a saddle or a minimum of f is near), and a backtracking line search
/// on f. Apart, the Hessian is negative definite and the convergence quadratic.
template <int D>
double maximise_from(const Vec<D>& d, const Mat<D>& Qa, const Mat<D>& Qb, double rho, Vec<D>& n) {
  using Tangent = Eigen::Matrix<double, D - 1, 1>;
  using TangentMat = Eigen::Matrix<double, D - 1, D - 1>;
  Local<D> L = evaluate<D>(d, Qa, Qb, rho, n);
  for (int it = 0; it < 50; ++it) {
    const Eigen::Matrix<double, D, D - 1> T = tangent_basis<D>(n);
    const Tangent gr = T.transpose() * L.g;
    const double scale = L.g.norm() + 1e-300;
    const double grn = gr.norm();
    if (grn <= 1e-15 * scale) break;
    TangentMat Hr = T.transpose() * (L.H - L.g.dot(n) * Mat<D>::Identity()) * T;
    // Largest eigenvalue of the symmetric (D-1) x (D-1) Hessian.
    double top;
    if constexpr (D == 2) {
      top = Hr(0, 0);
    } else {
      const double m = 0.5 * (Hr(0, 0) + Hr(1, 1)), h = 0.5 * (Hr(0, 0) - Hr(1, 1));
      top = m + std::sqrt(h * h + Hr(0, 1) * Hr(1, 0));
    }
    const double floor = 1e-3 * grn;  // curvature no flatter than this: a bounded step
    if (top > -floor) Hr -= (top + floor) * TangentMat::Identity();
    Tangent v = -Hr.inverse() * gr;
    const double max_step = 0.5;  // radians, about: keeps a step from jumping to the far side
    if (v.norm() > max_step) v *= max_step / v.norm();
    bool improved = false;
    for (int halvings = 0; halvings < 30; ++halvings) {
      const Vec<D> m = (n + T * v).normalized();
      const Local<D> Lm = evaluate<D>(d, Qa, Qb, rho, m);
      if (Lm.f > L.f || (Lm.f == L.f && halvings == 0)) {
        n = m;
        L = Lm;
        improved = true;
        break;
      }
      v *= 0.5;
    }
    // f is flat to second order at the maximum: a step of 1e-9 rad changes it by ~1e-18.
    if (!improved || v.norm() < 1e-9) break;
  }
  return L.f;
}

}  // namespace ellipsoid_gap_detail

/// Signed gap of a and b, and its gradient for b's centre (the maximising unit n). On overlap the
/// maximum over the sphere can have several local maxima (a long body crossing another): the
/// centre line and the principal axes of both bodies (both signs) start the search there; the
/// best is kept. Apart, f is positive only on a cap where it is concave: one start suffices.
template <int D>
Gap<D> smooth_convex_gap(const SmoothConvexBody<D>& a, const SmoothConvexBody<D>& b) {
  using namespace ellipsoid_gap_detail;
  const Vec<D> d = b.center - a.center;
  const Mat<D>& Qa = a.Q;
  const Mat<D>& Qb = b.Q;
  const double rho = a.rho + b.rho;
  const double dn = d.norm();
  Vec<D> best_n = dn > 0 ? Vec<D>(d / dn) : Vec<D>(Vec<D>::UnitX());
  double best = maximise_from<D>(d, Qa, Qb, rho, best_n);
  if (best < 0) {
    for (const Mat<D>* M : {&a.M, &b.M})
      for (int k = 0; k < D; ++k) {
        const double len = M->col(k).norm();
        if (!(len > 0)) continue;
        for (const double sign : {1.0, -1.0}) {
          Vec<D> n = sign * M->col(k) / len;
          if (n.dot(d) < 0) continue;  // f(n) <= f(-n) there when the bodies are symmetric about their centres
          const double f = maximise_from<D>(d, Qa, Qb, rho, n);
          if (f > best) best = f, best_n = n;
          if (best >= 0) return {best, best_n};  // apart after all: f > 0 on one cap only
        }
      }
  }
  return {best, best_n};
}

/// gap(a, b) < -allowed, decided without the multi-start of smooth_convex_gap where it can be:
/// one ascent from the centre line that reaches -allowed settles "no" (every f(n) is a lower
/// bound of the gap); a point at depth d > allowed inside both settles "yes" (the intersection
/// then holds a ball of radius d, so separating them takes a translation of at least 2d). The
/// points tried: both centres and the middle of the two support points of that ascent.
template <int D>
bool smooth_convex_overlap_beyond(const SmoothConvexBody<D>& a, const SmoothConvexBody<D>& b, double allowed) {
  using namespace ellipsoid_gap_detail;
  const Vec<D> d = b.center - a.center;
  const Mat<D>& Qa = a.Q;
  const Mat<D>& Qb = b.Q;
  const double dn = d.norm();
  Vec<D> n = dn > 0 ? Vec<D>(d / dn) : Vec<D>(Vec<D>::UnitX());
  if (maximise_from<D>(d, Qa, Qb, a.rho + b.rho, n) >= -allowed) return false;
  auto support_offset = [](const Mat<D>& Q, double rho, const Vec<D>& u) {
    const Vec<D> q = Q * u;
    const double N = std::sqrt(std::max(0.0, u.dot(q)));
    return Vec<D>((N > 0 ? Vec<D>(q / N) : Vec<D>(Vec<D>::Zero())) + rho * u);
  };
  const Vec<D> middle = 0.5 * (a.center + support_offset(Qa, a.rho, n) + b.center - support_offset(Qb, b.rho, n));
  for (const Vec<D>& x : {a.center, b.center, middle})
    if (std::min(a.depth_inside(x), b.depth_inside(x)) > allowed) return true;
  return smooth_convex_gap<D>(a, b).value < -allowed;
}

}  // namespace fp
