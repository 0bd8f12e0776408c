// SphereContactSolver::Session (the front manager's batched form) against solve(): for one front
// particle s0 and a neighbourhood of particles and walls, Session::solve(i, j) must return the
// positions solve() returns for the bodies (s0, b_i, b_j), up to 1e-12 relative (more only near a
// double root, where the positions themselves are ill-conditioned), in any order.
// The neighbourhoods mix random particles with pairs built to reach the session's other paths:
// nearly collinear with s0 (radical planes almost parallel) and near double roots.
#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "contact_test_support.hpp"

namespace fp {
namespace {

using namespace contact_test;

/// Positions equal as sets up to `tol` (counts equal, greedy nearest matching).
template <int D>
::testing::AssertionResult same_positions(std::span<const Placement<D>> a, std::span<const Placement<D>> b, double tol) {
  if (a.size() != b.size())
    return ::testing::AssertionFailure() << "session returned " << a.size() << " positions, solve() " << b.size();
  std::vector<bool> used(b.size(), false);
  for (const auto& p : a) {
    int best = -1;
    double bd = 0;
    for (std::size_t q = 0; q < b.size(); ++q) {
      const double d = (p.position - b[q].position).norm();
      if (!used[q] && (best < 0 || d < bd)) { best = static_cast<int>(q); bd = d; }
    }
    if (!(bd <= tol)) return ::testing::AssertionFailure() << "positions differ by " << bd << " (tolerance " << tol << ")";
    used[best] = true;
  }
  return ::testing::AssertionSuccess();
}

struct SessionTally {
  int pairs = 0, with_solutions = 0, near_parallel = 0, near_double = 0, wall_pairs = 0;
};

/// One neighbourhood around s0 = (c0, r0), mobile radius r; returns the bodies (walls in `walls`).
template <int D>
std::vector<Body<D>> neighbourhood(Rng& rng, const Vec<D>& c0, double r0, double r, std::deque<Wall<D>>& walls) {
  std::vector<Body<D>> bodies;
  // Walls first, as the front manager orders them: touching a ball (x, r) tangent to s0.
  const Vec<D> x = c0 + (r0 + r) * random_unit<D>(rng);
  walls.push_back(Wall<D>::plane(x + r * random_unit<D>(rng), Vec<D>::Zero()));
  walls.back().normal = (x - walls.back().point).normalized();
  walls.push_back(Wall<D>::sphere(x + rng.uniform(0, 3 * r) * random_unit<D>(rng), 0));
  walls.back().radius = (x - walls.back().point).norm() + r;
  walls.push_back(Wall<D>::vertex(x + r * random_unit<D>(rng)));
  if constexpr (D == 3) {
    Vec3 a = random_unit<3>(rng), d = random_unit<3>(rng);
    d = (d - d.dot(a) * a).normalized();
    const double R = r + rng.uniform(1, 20) * r0;
    walls.push_back(Wall<3>::cylinder(x - (R - r) * d, a, R));
  }
  const int nw = 1 + static_cast<int>(rng.below(walls.size()));
  for (int k = 0; k < nw; ++k) bodies.push_back(Body<D>::of_wall(walls[k]));
  // Random particles within reach of s0 (V of the front manager: d <= r0 + r_k + 2r).
  for (int k = 0; k < 10; ++k) {
    const double rk = r0 * log_uniform(rng, 0.3, 3);
    bodies.push_back(Body<D>::sphere(c0 + (r0 + rk + rng.uniform(0, 2 * r)) * random_unit<D>(rng), rk, k));
  }
  // Nearly collinear with s0: the same direction, another distance.
  {
    const Vec<D> u = random_unit<D>(rng);
    const double ra = r0 * rng.uniform(0.5, 2), rb = r0 * rng.uniform(0.5, 2);
    Vec<D> v = u;
    if constexpr (D == 3) v = (u + std::pow(10.0, rng.uniform(-9, -1)) * random_unit<D>(rng)).normalized();
    bodies.push_back(Body<D>::sphere(c0 + (r0 + ra + rng.uniform(0, r)) * u, ra, 100));
    bodies.push_back(Body<D>::sphere(c0 + (r0 + rb + rng.uniform(0, r)) * v, rb, 101));
  }
  // Near double root: a ball touching s0 and two particles whose centres are almost coplanar with it.
  {
    const Vec<D> y = c0 + (r0 + r) * random_unit<D>(rng);
    const Vec<D> n0 = (c0 - y).normalized();
    Vec<D> w = Vec<D>::Zero();  // 3D: normal of one plane containing n0
    if constexpr (D == 3) w = n0.cross(random_unit<3>(rng)).normalized();
    const double tilt = std::pow(10.0, rng.uniform(-8, -1));
    for (int k = 0; k < D - 1; ++k) {
      Vec<D> d = random_unit<D>(rng);
      if constexpr (D == 3) {
        // Both neighbours almost in that plane: y is almost in the plane of the three centres.
        d = (d - d.dot(w) * w + tilt * w).normalized();
      } else {
        d = (-n0 + std::pow(10.0, rng.uniform(-8, 0)) * d).normalized();  // 2D: almost opposite s0
      }
      const double rk = r0 * rng.uniform(0.5, 2);
      bodies.push_back(Body<D>::sphere(y + (r + rk) * d, rk, 200 + k));
    }
  }
  return bodies;
}

template <int D>
void run_sessions(int trials, std::uint64_t seed, double offset, double unit, SessionTally& t) {
  Rng rng(seed);
  const SphereContactSolver<D> solver;
  typename SphereContactSolver<D>::Session session;
  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> a, b;
  for (int trial = 0; trial < trials; ++trial) {
    Vec<D> c0;
    for (int k = 0; k < D; ++k) c0[k] = offset + unit * rng.uniform(-10, 10);
    const double r0 = unit * log_uniform(rng, 0.3, 3), r = unit * log_uniform(rng, 0.3, 3);
    std::deque<Wall<D>> walls;
    const std::vector<Body<D>> bodies = neighbourhood<D>(rng, c0, r0, r, walls);
    const Body<D> s0 = Body<D>::sphere(c0, r0, -1);
    session.begin(s0, r, bodies);
    const double scale = r0 + r;
    const int nb = static_cast<int>(bodies.size());
    for (int j = (D == 2 ? 0 : 1); j < nb; ++j)
      for (int i = 0; i < (D == 2 ? 1 : j); ++i) {
        const int bi = D == 2 ? j : i;  // 2D: one body per call
        std::array<Body<D>, D> f;
        f[0] = s0;
        f[1] = bodies[bi];
        if constexpr (D == 3) f[2] = bodies[j];
        const std::span<const Body<D>> fs(f.data(), D);
        const int na = session.solve(bi, j, a);
        const int nbs = solver.solve(fs, Mobile<D>{r}, b);
        const std::span<const Placement<D>> sa(a.data(), na), sb(b.data(), nbs);
        double xmax = 0;
        for (const auto& p : sa) xmax = std::max(xmax, p.position.cwiseAbs().maxCoeff());
        // 1e-12 relative, except near a double root: there the two roots y0 +- t u (t relative to
        // the frame scale) are only defined to ~eps / t by any formula (measured: < 5e-15 / t).
        // Below t = 1e-4 both take the same (verified) path.
        const double t_rel = na == 2 ? std::max(1e-4, (a[0].position - a[1].position).norm() / (2 * scale)) : 1.0;
        const double tol = std::max(scale, xmax) * (1e-12 + 5e-14 / t_rel);
        ASSERT_TRUE(same_positions<D>(sa, sb, tol)) << "pair (" << bi << ", " << j << ")" << config_literal<D>(fs, r);
        ASSERT_TRUE(check_tangent<D>(fs, r, sa));
        ++t.pairs;
        t.with_solutions += na > 0;
        const bool wall = bodies[bi].is_wall() || bodies[j].is_wall();
        t.wall_pairs += wall;
        if (!wall && D == 3) {  // which path of Session::solve the pair takes, recomputed here
          const Vec<D> a1 = (bodies[bi].center - c0) / scale, a2 = (bodies[j].center - c0) / scale;
          if constexpr (D == 3) {
            const double sine2 = a1.cross(a2).squaredNorm() / (a1.squaredNorm() * a2.squaredNorm());
            t.near_parallel += sine2 < 1e-4;
          }
        }
        if (!wall && na > 0 && (na == 1 || (a[0].position - a[1].position).norm() < 2e-4 * scale)) ++t.near_double;
      }
  }
}

TEST(SphereContactSolverSession, MatchesSolveIn3D) {
  SessionTally t;
  run_sessions<3>(1500, 700, 0.0, 1.0, t);
  std::cout << "[ stats    ] " << t.pairs << " pairs, " << t.with_solutions << " with solutions, " << t.wall_pairs
            << " with a wall, " << t.near_parallel << " nearly parallel, " << t.near_double << " near double roots\n";
  EXPECT_GT(t.pairs, 1500 * 100);
  EXPECT_GT(t.with_solutions, t.pairs / 10);
  EXPECT_GT(t.near_parallel, 200);  // the session's careful path was exercised
  EXPECT_GT(t.near_double, 50);
}

TEST(SphereContactSolverSession, MatchesSolveIn2D) {
  SessionTally t;
  run_sessions<2>(10000, 701, 0.0, 1.0, t);
  std::cout << "[ stats    ] " << t.pairs << " pairs, " << t.with_solutions << " with solutions, " << t.near_double
            << " near double roots\n";
  EXPECT_GT(t.with_solutions, t.pairs / 4);
  EXPECT_GT(t.near_double, 50);
}

TEST(SphereContactSolverSession, MatchesSolveFarFromTheOriginAndAtMicroScale) {
  for (int D3 = 0; D3 < 2; ++D3) {
    SessionTally t1, t2;
    if (D3) {
      run_sessions<3>(300, 702, 1e6, 1.0, t1);
      run_sessions<3>(300, 703, 0.0, 1e-6, t2);
    } else {
      run_sessions<2>(2000, 704, 1e6, 1.0, t1);
      run_sessions<2>(2000, 705, 0.0, 1e-6, t2);
    }
    if (HasFatalFailure()) return;
    EXPECT_GT(t1.with_solutions, t1.pairs / 10);
    EXPECT_GT(t2.with_solutions, t2.pairs / 10);
  }
}

}  // namespace
}  // namespace fp
