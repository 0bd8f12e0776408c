#include "contact/ellipsoid_contact_solver.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "contact/ellipsoid_gap.hpp"
#include "contact/sphere_contact_solver.hpp"
#include "shapes/ellipsoid_shape.hpp"

namespace fp {
namespace {

/// A body of the problem (SmoothConvexBody, ellipsoid_gap.hpp) with the radii of the
/// equivalent spheres that start Newton.
template <int D>
struct Smooth {
  SmoothConvexBody<D> body;
  double circumscribed = 0;  ///< radius of its circumscribed sphere about the centre
  double equivalent = 0;     ///< radius of the ball of the same measure
};

/// An ellipsoid or a sphere (by the shape's kind) at rotation R about c.
template <int D>
Smooth<D> smooth_of(const Shape<D>& s, const Mat<D>& R, const Vec<D>& c) {
  Smooth<D> b{smooth_convex_body<D>(s, R, c), s.bounding_radius(), s.bounding_radius()};
  if (std::strcmp(s.kind(), EllipsoidShape<D>::kKind) == 0)
    b.equivalent = std::pow(static_cast<const EllipsoidShape<D>&>(s).semi_axes().prod(), 1.0 / D);
  return b;
}

template <int D>
Smooth<D> ball(const Vec<D>& c, double r) {
  return {smooth_ball<D>(c, r), r, r};
}

/// The wrapper of fixed body F for the mobile A: its boundary point of outward normal n (unit)
/// and, if H is given, the Hessian of its support function there (d P / d n on the tangent plane).
template <int D>
void wrapper_point(const SmoothConvexBody<D>& F, const SmoothConvexBody<D>& A, const Vec<D>& n, Vec<D>& P, Mat<D>* H) {
  P = F.center;
  if (H) H->setZero();
  add_support_norm<D>(F.Q, n, 1.0, nullptr, P, H);
  add_support_norm<D>(A.Q, n, 1.0, nullptr, P, H);
  const double rho = F.rho + A.rho;
  P += rho * n;
  if (H) *H += rho * (Mat<D>::Identity() - n * n.transpose());
}

/// One fixed body of the problem: a curved wrapper (x = P(n)) or an offset plane (w.x = b).
template <int D>
struct Locus {
  bool plane = false;
  Smooth<D> curved;          ///< curved
  Vec<D> w = Vec<D>::Zero();  ///< plane: inward unit normal
  double b = 0;              ///< plane: offset of the mobile's centre
};

// Newton gives up on a start whose residual is still above kSlowFactor x the tolerance after
// kSlowAfter iterations (most problems of the pair scan have no solution). Measured on the
// tests' thin ellipsoids (semi-axes 20 : 1): after 6 or 8 iterations the known position was
// found in only 47-83 % of their problems, after 12 in 90-97 %.
constexpr int kSlowAfter = 12;
constexpr double kSlowFactor = 1e8;
constexpr int kMaxUnknowns = 9;  // 3D, three curved bodies: x and three normals of 2 parameters
using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxUnknowns, 1>;
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxUnknowns, kMaxUnknowns>;

/// Residual of the system at (x, normals): x - P_i(n_i) for curved loci, w.x - b for planes.
template <int D>
Vector residual(const std::array<Locus<D>, D>& loci, const SmoothConvexBody<D>& A, const Vec<D>& x, const std::array<Vec<D>, D>& n, int rows) {
  Vector r(rows);
  int row = 0;
  for (int i = 0; i < D; ++i) {
    if (loci[i].plane) {
      r(row++) = loci[i].w.dot(x) - loci[i].b;
    } else {
      Vec<D> P;
      wrapper_point<D>(loci[i].curved.body, A, n[i], P, nullptr);
      r.template segment<D>(row) = x - P;
      row += D;
    }
  }
  return r;
}

/// The Newton step by eliminating the normals' parameters (newton's comment); false when a block
/// is degenerate.
template <int D>
bool eliminated_step(const std::array<Locus<D>, D>& loci, const std::array<Eigen::Matrix<double, D, D - 1>, D>& AT,
                     const Vector& r, Vector& step) {
  Mat<D> G;
  Vec<D> g;
  std::array<int, D> at{};  // each block's first residual row
  int row = 0;
  for (int i = 0; i < D; ++i) {
    at[i] = row;
    if (loci[i].plane) {
      G.row(i) = loci[i].w.transpose();
      g(i) = -r(row++);
      continue;
    }
    Vec<D> q;
    double scale;
    if constexpr (D == 2) {
      q = Vec2(-AT[i](1, 0), AT[i](0, 0));
      scale = AT[i].col(0).norm();
    } else {
      q = AT[i].col(0).cross(AT[i].col(1));
      scale = AT[i].col(0).norm() * AT[i].col(1).norm();
    }
    if (!(q.norm() > 1e-12 * scale)) return false;
    q.normalize();
    G.row(i) = q.transpose();
    g(i) = -q.dot(r.template segment<D>(row));
    row += D;
  }
  const Vec<D> dx = G.fullPivLu().solve(g);
  step.template head<D>() = dx;
  int col = D;
  for (int i = 0; i < D; ++i) {
    if (loci[i].plane) continue;
    const Vec<D> rhs = dx + r.template segment<D>(at[i]);
    step.segment(col, D - 1) = (AT[i].transpose() * AT[i]).ldlt().solve(AT[i].transpose() * rhs);
    col += D - 1;
  }
  return true;
}

/// The Newton step from the whole system's LU (partial pivoting).
template <int D>
Vector full_step(const std::array<Locus<D>, D>& loci, const std::array<Eigen::Matrix<double, D, D - 1>, D>& AT,
                 const Vector& r, int rows, int unknowns) {
  Matrix J = Matrix::Zero(rows, unknowns);
  int row = 0, col = D;
  for (int i = 0; i < D; ++i) {
    if (loci[i].plane) {
      J.block(row, 0, 1, D) = loci[i].w.transpose();
      ++row;
      continue;
    }
    J.block(row, 0, D, D) = Mat<D>::Identity();
    J.block(row, col, D, D - 1) = -AT[i];
    row += D;
    col += D - 1;
  }
  return Eigen::PartialPivLU<Matrix>(J).solve(-r);
}

/// Newton's method on the system from (x, n); true when it converged (|residual| <= tol).
template <int D>
bool newton(const std::array<Locus<D>, D>& loci, const SmoothConvexBody<D>& A, Vec<D>& x, std::array<Vec<D>, D>& n, double tol) {
  int curved = 0;
  for (const Locus<D>& l : loci) curved += !l.plane;
  const int unknowns = D + (D - 1) * curved;
  const int rows = D * curved + (D - curved);
  Vector r = residual<D>(loci, A, x, n, rows);
  double norm = r.norm();
  const double slow = kSlowFactor * tol;  // still this far after kSlowAfter iterations: not converging
  for (int it = 0; it < 30; ++it) {
    if (norm <= tol) return true;
    // Newton wanders where the problem has no solution; from a start in a solution's basin it
    // converges quadratically.
    if (it >= kSlowAfter && norm > slow) return false;
    std::array<Eigen::Matrix<double, D, D - 1>, D> T, AT;  // tangent bases; dP_i/d(normal parameters)
    for (int i = 0; i < D; ++i) {
      if (loci[i].plane) continue;
      Vec<D> P;
      Mat<D> H;
      wrapper_point<D>(loci[i].curved.body, A, n[i], P, &H);
      T[i] = ellipsoid_gap_detail::tangent_basis<D>(n[i]);
      AT[i] = H * T[i];
    }
    // The Newton system J step = -r: a curved block i reads dx - AT_i dn_i = -r_i, a plane's row
    // w_i . dx = -r_i. A vector q_i normal to AT_i's columns eliminates dn_i (q_i . dx =
    // -q_i . r_i): D rows for dx, then dn_i from AT_i dn_i = dx + r_i. A D x D solve and D small
    // ones where the whole system's LU (9 x 9 in 3D) took a third of an ellipsoid packing; where
    // a block is degenerate (its columns parallel), the whole system's LU.
    Vector step(unknowns);
    if (!eliminated_step<D>(loci, AT, r, step)) step = full_step<D>(loci, AT, r, rows, unknowns);
    // A singular system (parallel planes, coincident wrappers) shows as a non-finite or absurd step.
    if (!step.allFinite() || step.template head<D>().norm() > 1e6 * (x.norm() + 1)) return false;
    bool improved = false;
    for (int halvings = 0; halvings < 12 && !improved; ++halvings) {
      Vec<D> x1 = x + step.template head<D>();
      std::array<Vec<D>, D> n1 = n;
      int c = D;
      for (int i = 0; i < D; ++i) {
        if (loci[i].plane) continue;
        n1[i] = (n[i] + T[i] * step.segment(c, D - 1)).normalized();
        c += D - 1;
      }
      const Vector r1 = residual<D>(loci, A, x1, n1, rows);
      const double norm1 = r1.norm();
      if (norm1 < norm) {
        x = x1, n = n1, r = r1, norm = norm1;
        improved = true;
      } else {
        step *= 0.5;
      }
    }
    if (!improved) return norm <= tol;
  }
  return norm <= tol;
}

}  // namespace

template <int D>
int EllipsoidContactSolver<D>::solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile, std::span<Placement<D>> out) const {
  if (fixed.size() != static_cast<std::size_t>(D) || out.empty()) return 0;
  const Smooth<D> A = mobile.shape ? smooth_of<D>(*mobile.shape, mobile.rotation, Vec<D>::Zero()) : ball<D>(Vec<D>::Zero(), mobile.radius);
  std::array<Locus<D>, D> loci;
  // Work relative to the first particle body's centre (coordinates far from the origin lose
  // nothing), and measure the residual on the scale of the bodies.
  Vec<D> origin = Vec<D>::Zero();
  for (const Body<D>& b : fixed)
    if (!b.is_wall()) { origin = b.center; break; }
  double size = A.circumscribed;
  for (int i = 0; i < D; ++i) {
    const Body<D>& b = fixed[static_cast<std::size_t>(i)];
    Locus<D>& l = loci[static_cast<std::size_t>(i)];
    if (b.is_wall()) {
      if (b.wall->kind != WallKind::Plane) return 0;  // registered for plane walls only
      l.plane = true;
      l.w = b.wall->normal;
      // The mobile touches the plane from the container side: w.(x - p) = its extent along -w.
      l.b = l.w.dot(b.wall->point - origin) + std::sqrt(std::max(0.0, l.w.dot(A.body.Q * l.w))) + A.body.rho;
    } else {
      l.curved = b.shaped ? smooth_of<D>(*b.shaped->shape, b.shaped->pose.rotation, Vec<D>(b.center - origin))
                        : ball<D>(Vec<D>(b.center - origin), b.radius);
      size = std::min(size, l.curved.circumscribed);
    }
  }
  const double tol = 1e-12 * size;

  // Starts: the positions of the equivalent-sphere problems (circumscribed, then same-measure radii).
  std::array<Body<D>, D> spheres;
  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> starts;
  const SphereContactSolver<D> sphere_solver;
  int found = 0;
  for (const bool circumscribed : {true, false}) {
    // Two positions from the circumscribed spheres' starts: the volume-equivalent ones find the
    // same two (they are the second chance for problems the first starts miss).
    if (!circumscribed && found >= 2) break;
    for (int i = 0; i < D; ++i) {
      const Locus<D>& l = loci[static_cast<std::size_t>(i)];
      const Body<D>& b = fixed[static_cast<std::size_t>(i)];
      spheres[static_cast<std::size_t>(i)] =
          l.plane ? b : Body<D>::sphere(l.curved.body.center, circumscribed ? l.curved.circumscribed : l.curved.equivalent);
    }
    // The sphere solver sees the walls in world coordinates: shift them into the working frame.
    std::array<Wall<D>, D> walls;
    for (int i = 0; i < D; ++i)
      if (loci[static_cast<std::size_t>(i)].plane) {
        walls[static_cast<std::size_t>(i)] = *fixed[static_cast<std::size_t>(i)].wall;
        walls[static_cast<std::size_t>(i)].point -= origin;
        spheres[static_cast<std::size_t>(i)] = Body<D>::of_wall(walls[static_cast<std::size_t>(i)]);
      }
    Mobile<D> ball_mobile;
    ball_mobile.radius = circumscribed ? A.circumscribed : A.equivalent;
    const int m = sphere_solver.solve(std::span<const Body<D>>(spheres.data(), D), ball_mobile, starts);
    for (int s = 0; s < m; ++s) {
      Vec<D> x = starts[static_cast<std::size_t>(s)].position;
      std::array<Vec<D>, D> n;
      for (int i = 0; i < D; ++i) {
        const Locus<D>& l = loci[static_cast<std::size_t>(i)];
        const Vec<D> d = l.plane ? Vec<D>(l.w) : Vec<D>(x - l.curved.body.center);
        n[static_cast<std::size_t>(i)] = d.norm() > 0 ? Vec<D>(d.normalized()) : Vec<D>(Vec<D>::UnitX());
      }
      if (!newton<D>(loci, A.body, x, n, tol)) continue;
      const Vec<D> world = x + origin;
      bool seen = false;
      for (int k = 0; k < found && !seen; ++k) seen = (out[static_cast<std::size_t>(k)].position - world).norm() <= 1e-8 * size;
      if (seen) continue;
      out[static_cast<std::size_t>(found++)].position = world;
      if (found == static_cast<int>(out.size())) return found;
    }
  }
  return found;
}

template class EllipsoidContactSolver<2>;
template class EllipsoidContactSolver<3>;

}  // namespace fp
