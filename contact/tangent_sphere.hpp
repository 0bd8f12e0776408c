#pragma once
// The sphere (3D) or disk (2D) touching D + 1 given ones from outside, its radius unknown: the
// geometric procedure of paper 000 (Jerier et al. 2010, Sect. 2.1, Eqs. 1-9), which places a
// sphere in contact with the four spheres of a tetrahedron (and the disk with three disks).
// Eqs. 1-4: |x - c_i|^2 = (r + r_i)^2. Subtracting the first from the others leaves D linear
// equations in x whose right-hand side is affine in r (Eq. 5), so x = x_a + x_b r (Eq. 9); put
// back into the first, a quadratic in r whose positive roots are the solutions. Coordinates are
// taken relative to the first centre and scaled to the configuration's size first (a scene
// 1e9 from the origin or scaled by 2^-60 gives the same digits), and each root is polished by
// Newton steps on the D + 1 tangency equations. Centres on a common plane (line in 2D) leave
// the linear system singular: no solution, as the paper stops there. A plane (a container wall)
// may stand for a sphere: its equation n . (x - p) = r is linear already.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include <Eigen/Dense>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D>
struct TangentSphere {
  Vec<D> centre;
  double radius = 0.0;
};

/// Up to two solutions, smallest radius first.
template <int D>
struct TangentSpheres {
  std::array<TangentSphere<D>, 2> at;
  int count = 0;
};

/// A body the unknown sphere touches: a sphere (centre, radius >= 0), touched from outside, or a
/// plane (a point on it, its unit normal), touched from the side the normal points to (a
/// container wall: the normal points into the container).
template <int D>
struct TangentBody {
  Vec<D> point = Vec<D>::Zero();   ///< sphere: centre; plane: a point on it
  double radius = 0.0;             ///< sphere radius
  Vec<D> normal = Vec<D>::Zero();  ///< plane: unit normal; zero for a sphere
  bool plane = false;

  static TangentBody sphere(const Vec<D>& c, double r) { TangentBody b; b.point = c; b.radius = r; return b; }
  static TangentBody wall(const Vec<D>& p, const Vec<D>& unit_normal) {
    TangentBody b; b.point = p; b.normal = unit_normal; b.plane = true; return b;
  }
};

/// The spheres of positive radius touching the D + 1 bodies (at least one of them a sphere):
/// |x - c_i| = r + r_i for a sphere, n . (x - p) = r for a plane (paper 000, Eqs. 1-9, with the
/// plane rows already linear), to rounding after the Newton polish (`polish` = false skips it:
/// an estimate, for ordering voids).
template <int D>
TangentSpheres<D> spheres_tangent_to(std::array<TangentBody<D>, D + 1> b, bool polish = true) {
  using Mat = Eigen::Matrix<double, D, D>;
  TangentSpheres<D> out;
  // A sphere first: the quadratic is its equation.
  for (int i = 1; i <= D; ++i)
    if (b[0].plane && !b[static_cast<std::size_t>(i)].plane) std::swap(b[0], b[static_cast<std::size_t>(i)]);
  if (b[0].plane) return out;
  // Frame: origin at the first centre, unit the largest of the offsets and radii.
  const Vec<D> o = b[0].point;
  double unit = b[0].radius;
  for (int i = 1; i <= D; ++i) {
    const TangentBody<D>& bi = b[static_cast<std::size_t>(i)];
    unit = bi.plane ? std::max(unit, std::abs(bi.normal.dot(bi.point - o))) : std::max({unit, (bi.point - o).norm(), bi.radius});
  }
  if (!(unit > 0) || !std::isfinite(unit)) return out;
  std::array<Vec<D>, D + 1> c;   // sphere: centre; plane: normal
  std::array<double, D + 1> r;   // sphere: radius; plane: height of the origin under it, n . (p - o)
  for (int i = 0; i <= D; ++i) {
    const TangentBody<D>& bi = b[static_cast<std::size_t>(i)];
    c[static_cast<std::size_t>(i)] = bi.plane ? bi.normal : Vec<D>((bi.point - o) / unit);
    r[static_cast<std::size_t>(i)] = bi.plane ? bi.normal.dot(bi.point - o) / unit : bi.radius / unit;
  }
  // Eq. 5, with c_0 = 0: 2 c_i . x = |c_i|^2 - r_i^2 + r_0^2 - 2 r (r_i - r_0), i = 1..D; a
  // plane's row is n . x = h + r.
  Mat A;
  Vec<D> b0, b1;
  for (int i = 1; i <= D; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (b[k].plane) {
      A.row(i - 1) = c[k].transpose();
      b0[i - 1] = r[k];
      b1[i - 1] = 1.0;
    } else {
      A.row(i - 1) = 2.0 * c[k].transpose();
      b0[i - 1] = c[k].squaredNorm() - r[k] * r[k] + r[0] * r[0];
      b1[i - 1] = -2.0 * (r[k] - r[0]);
    }
  }
  const Eigen::FullPivLU<Mat> lu(A);
  // Coplanar centres: a singular system (relative to the unit-size frame).
  if (lu.rank() < D || std::abs(lu.determinant()) < 1e-12) return out;
  const Vec<D> xa = lu.solve(b0), xb = lu.solve(b1);
  // Eq. 1 with x = xa + xb r: |xa + xb r|^2 = (r + r_0)^2.
  const double qa = xb.squaredNorm() - 1.0, qb = 2.0 * (xa.dot(xb) - r[0]), qc = xa.squaredNorm() - r[0] * r[0];
  std::array<double, 2> roots{};
  int n = 0;
  if (std::abs(qa) < 1e-14 * (std::abs(qb) + std::abs(qc))) {
    if (qb != 0) roots[static_cast<std::size_t>(n++)] = -qc / qb;
  } else {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) return out;
    const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));  // no cancellation
    roots[static_cast<std::size_t>(n++)] = q / qa;
    if (q != 0) roots[static_cast<std::size_t>(n++)] = qc / q;
  }
  for (int k = 0; k < n; ++k) {
    double rr = roots[static_cast<std::size_t>(k)];
    if (!(rr > 0) || !std::isfinite(rr)) continue;
    Vec<D> x = xa + xb * rr;
    // Newton on f_i = |x - c_i| - r - r_i (sphere) or n . x - h - r (plane), i = 0..D.
    for (int step = 0; polish && step < 3; ++step) {
      Eigen::Matrix<double, D + 1, D + 1> J;
      Eigen::Matrix<double, D + 1, 1> f;
      bool defined = true;
      for (int i = 0; i <= D && defined; ++i) {
        const auto q = static_cast<std::size_t>(i);
        if (b[q].plane) {
          f[i] = c[q].dot(x) - r[q] - rr;
          J.row(i).template head<D>() = c[q].transpose();
        } else {
          const Vec<D> d = x - c[q];
          const double len = d.norm();
          defined = len > 0;
          f[i] = len - rr - r[q];
          J.row(i).template head<D>() = (d / (defined ? len : 1.0)).transpose();
        }
        J(i, D) = -1.0;
      }
      if (!defined) break;
      const Eigen::Matrix<double, D + 1, 1> delta = J.fullPivLu().solve(f);
      if (!delta.allFinite()) break;
      x -= delta.template head<D>();
      rr -= delta[D];
    }
    if (!(rr > 0) || !x.allFinite()) continue;
    out.at[static_cast<std::size_t>(out.count++)] = {o + x * unit, rr * unit};
  }
  if (out.count == 2 && out.at[1].radius < out.at[0].radius) std::swap(out.at[0], out.at[1]);
  return out;
}

/// The spheres of positive radius touching the D + 1 spheres (centres[i], radii[i] >= 0) from
/// outside: |x - c_i| = r + r_i for every i, to rounding after the Newton polish.
template <int D>
TangentSpheres<D> spheres_tangent_to(const std::array<Vec<D>, D + 1>& centres, const std::array<double, D + 1>& radii) {
  std::array<TangentBody<D>, D + 1> b;
  for (std::size_t i = 0; i <= static_cast<std::size_t>(D); ++i) b[i] = TangentBody<D>::sphere(centres[i], radii[i]);
  return spheres_tangent_to<D>(b);
}

}  // namespace fp
