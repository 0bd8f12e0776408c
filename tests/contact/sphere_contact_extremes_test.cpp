// SphereContactSolver on degenerate and extreme configurations: collinear and coplanar centres,
// concentric circles, radius ratios of 1000 both ways, coordinates offset by 1e6, radii of 1e-6,
// bodies too far apart, wall reference points far from the contact. The contract everywhere: no
// solution, or verified tangent ones; and where the configuration is well conditioned, the known
// solution.
#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "contact_test_support.hpp"

namespace fp {
namespace {

using namespace contact_test;

constexpr std::array<BodyKind, 5> kAllKinds = {BodyKind::Particle, BodyKind::Plane, BodyKind::SphereWall,
                                               BodyKind::Cylinder, BodyKind::Vertex};

template <int D, std::size_t N>
int solve(const std::array<Body<D>, N>& f, double r, std::array<Placement<D>, 4>& out) {
  return SphereContactSolver<D>{}.solve(std::span<const Body<D>>(f.data(), N), Mobile<D>{r}, out);
}

template <int D>
std::span<const Placement<D>> first(const std::array<Placement<D>, 4>& out, int n) {
  return {out.data(), static_cast<std::size_t>(n)};
}

/// Every 3D combination (at most one cylinder) and every 2D one, constructed with ranges `g`.
void run_all_combinations(const Ranges& g, int trials3, int trials2, std::uint64_t seed, const char* what) {
  Tally t3, t2;
  for (int a = 0; a < 5; ++a)
    for (int b = a; b < 5; ++b)
      for (int c = b; c < 5; ++c) {
        if ((a == 3) + (b == 3) + (c == 3) > 1) continue;
        run_constructed<3>({kAllKinds[a], kAllKinds[b], kAllKinds[c]}, trials3, seed++, g, t3);
        if (::testing::Test::HasFatalFailure()) return;
      }
  for (int a = 0; a < 5; ++a)
    for (int b = a; b < 5; ++b) {
      if (a == 3 || b == 3) continue;
      run_constructed<2>({kAllKinds[a], kAllKinds[b]}, trials2, seed++, g, t2);
      if (::testing::Test::HasFatalFailure()) return;
    }
  std::cout << "[ stats    ] " << what << ": 3D " << t3.found << "/" << t3.well_conditioned << " known found in "
            << t3.configs << " solves, 2D " << t2.found << "/" << t2.well_conditioned << " in " << t2.configs
            << "; worst |gap| " << std::max(t3.worst_gap, t2.worst_gap) << " x tolerance\n";
  EXPECT_GT(t3.well_conditioned, t3.configs / 2);
  EXPECT_GT(t2.well_conditioned, t2.configs / 2);
}

// ---- degeneracies ----

TEST(SphereContactSolverDegenerate, CollinearCentresGiveNoSolution) {
  // Three centres on a line, all touching a ball (x, r) off the line: the ball can turn around
  // the line, a ring of solutions and no isolated one. The solver must refuse.
  Rng rng(800);
  int near_solved = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double r = log_uniform(rng, 0.1, 10);
    const Vec3 x(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
    // Axis-aligned (exactly collinear) or along a random direction (collinear up to rounding).
    Vec3 u = Vec3::UnitX(), e = Vec3::UnitY();
    if (trial % 2 == 0) {
      u = random_unit<3>(rng);
      e = u.cross(random_unit<3>(rng)).normalized();
    }
    const double rho = r * (1 + log_uniform(rng, 0.05, 10));  // distance of the line from x
    std::array<Body<3>, 3> f;
    for (int i = 0; i < 3; ++i) {
      const Vec3 c = x + rho * e + rng.uniform(-3, 3) * rho * u;
      f[i] = Body<3>::sphere(c, (c - x).norm() - r);
    }
    std::array<Placement<3>, 4> out;
    ASSERT_EQ(solve<3>(f, r, out), 0) << config_literal<3>(f, r);
    // Nearly collinear (bent by 1e-14 .. 1e-4): two ill-conditioned solutions, refused or verified.
    const Vec3 bent = f[2].center + std::pow(10.0, rng.uniform(-14, -4)) * rho * random_unit<3>(rng);
    const std::array<Body<3>, 3> g = {f[0], f[1], Body<3>::sphere(bent, (bent - x).norm() - r)};
    const int n = solve<3>(g, r, out);
    ASSERT_TRUE(check_tangent<3>(g, r, first<3>(out, n)));
    near_solved += n > 0;
  }
  std::cout << "[ stats    ] nearly collinear: " << near_solved << " of 20000 solved (and verified)\n";
  EXPECT_GT(near_solved, 1000);  // the verification of ill-conditioned answers was exercised
}

TEST(SphereContactSolverDegenerate, CoplanarCentresGiveTheDoubleRoot) {
  // x in the plane of the three centres: the two solutions merge into x.
  Rng rng(801);
  int exact = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double r = log_uniform(rng, 0.2, 5);
    const Vec3 x(rng.uniform(-5, 5), rng.uniform(-5, 5), trial % 2 ? 0.0 : rng.uniform(-5, 5));
    // Plane z = const (exact in double) or a random plane through x.
    Vec3 e1 = Vec3::UnitX(), e2 = Vec3::UnitY();
    if (trial % 2 == 0) {
      const Vec3 k = random_unit<3>(rng);
      e1 = k.cross(random_unit<3>(rng)).normalized();
      e2 = k.cross(e1);
    }
    std::array<Body<3>, 3> f;
    std::array<Vec3, 3> normals;
    double scale = 0;
    for (int i = 0; i < 3; ++i) {
      const double phi = rng.uniform(0, 2 * kPi), ri = log_uniform(rng, 0.2, 5);
      Vec3 d = std::cos(phi) * e1 + std::sin(phi) * e2;
      if (trial % 2) d.z() = 0;
      f[i] = Body<3>::sphere(x + (r + ri) * d, ri);
      normals[i] = d;
      scale = std::max(scale, r + ri);
    }
    std::array<Placement<3>, 4> out;
    const int n = solve<3>(f, r, out);
    ASSERT_TRUE(check_tangent<3>(f, r, first<3>(out, n)));
    // The 2D problem inside the plane must be well posed for x to be an isolated double root.
    Eigen::Matrix<double, 3, 2> P;
    P << e1, e2;
    std::array<Vec2, 2> in_plane = {P.transpose() * normals[0] - P.transpose() * normals[2],
                                    P.transpose() * normals[1] - P.transpose() * normals[2]};
    const double sine = std::abs(in_plane[0].x() * in_plane[1].y() - in_plane[0].y() * in_plane[1].x()) /
                        (in_plane[0].norm() * in_plane[1].norm());
    if (sine < 1e-2) continue;
    ++exact;
    // A double root is found to ~sqrt(eps) along the plane normal: the tangency check is the
    // strict one, the position only needs to be the right root.
    ASSERT_GE(n, 1) << config_literal<3>(f, r);
    for (int k = 0; k < n; ++k)
      ASSERT_LT((out[k].position - x).norm(), 1e-6 * scale) << config_literal<3>(f, r);
  }
  EXPECT_GT(exact, 15000);
}

TEST(SphereContactSolverDegenerate, ConcentricCirclesGiveNoSolution) {
  Rng rng(802);
  int near_solved = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec2 c(rng.uniform(-5, 5), rng.uniform(-5, 5));
    const double R = log_uniform(rng, 2, 20), ri = R * rng.uniform(0.05, 0.9);
    // The second r makes R - r == ri + r exactly (in reals): a whole circle of solutions.
    const double r = trial % 2 ? rng.uniform(0.01, 1) * (R - ri) / 2 : (R - ri) / 2;
    const std::vector<Wall<2>> w = {Wall<2>::sphere(c, R)};
    const std::array<Body<2>, 2> f = {Body<2>::of_wall(w[0]), Body<2>::sphere(c, ri)};
    const std::array<Body<2>, 2> g = {Body<2>::sphere(c, ri), Body<2>::of_wall(w[0])};
    const std::array<Body<2>, 2> h = {Body<2>::sphere(c, ri), Body<2>::sphere(c, R * 0.5)};
    std::array<Placement<2>, 4> out;
    ASSERT_EQ(solve<2>(f, r, out), 0) << config_literal<2>(f, r);
    ASSERT_EQ(solve<2>(g, r, out), 0) << config_literal<2>(g, r);
    ASSERT_EQ(solve<2>(h, r, out), 0) << config_literal<2>(h, r);
    // Nearly concentric: refused or verified.
    const std::array<Body<2>, 2> k = {Body<2>::of_wall(w[0]),
                                      Body<2>::sphere(c + std::pow(10.0, rng.uniform(-14, -3)) * R * random_unit<2>(rng), ri)};
    const int n = solve<2>(k, r, out);
    ASSERT_TRUE(check_tangent<2>(k, r, first<2>(out, n)));
    near_solved += n > 0;
    // 3D analogue: a particle at the centre of a spherical container, with any third body.
    const std::vector<Wall<3>> w3 = {Wall<3>::sphere(Vec3(c.x(), c.y(), 1), R)};
    const std::array<Body<3>, 3> f3 = {Body<3>::sphere(Vec3(c.x(), c.y(), 1), ri), Body<3>::of_wall(w3[0]),
                                       Body<3>::sphere(Vec3(c.x() + R / 2, c.y(), 1), ri / 2)};
    std::array<Placement<3>, 4> out3;
    ASSERT_EQ(solve<3>(f3, r, out3), 0) << config_literal<3>(f3, r);
  }
  std::cout << "[ stats    ] nearly concentric: " << near_solved << " of 20000 solved (and verified)\n";
}

TEST(SphereContactSolverDegenerate, BodiesTooFarApartGiveNoSolution) {
  Rng rng(803);
  for (int trial = 0; trial < 20000; ++trial) {
    const double r = log_uniform(rng, 0.1, 10), ri = log_uniform(rng, 0.1, 10), rj = log_uniform(rng, 0.1, 10);
    const Vec3 ci(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
    // d(ci, cj) > ri + rj + 2r: no ball of radius r touches both.
    const Vec3 cj = ci + (ri + rj + 2 * r) * (1 + log_uniform(rng, 1e-9, 1)) * random_unit<3>(rng);
    const double rk = log_uniform(rng, 0.1, 10);
    const Vec3 ck = ci + (ri + rk + rng.uniform(0, 2 * r)) * random_unit<3>(rng);
    std::array<Placement<3>, 4> out;
    const std::array<Body<3>, 3> f = {Body<3>::sphere(ck, rk), Body<3>::sphere(ci, ri), Body<3>::sphere(cj, rj)};
    ASSERT_EQ(solve<3>(f, r, out), 0) << config_literal<3>(f, r);
    const std::array<Body<2>, 2> g = {Body<2>::sphere(ci.head<2>(), ri),
                                      Body<2>::sphere(ci.head<2>() + (cj - ci).norm() * random_unit<2>(rng), rj)};
    std::array<Placement<2>, 4> out2;
    ASSERT_EQ(solve<2>(g, r, out2), 0) << config_literal<2>(g, r);
  }
}

// ---- scales ----

TEST(SphereContactSolverExtreme, TinyMobileBetweenHugeBodies) {
  Ranges g;
  g.r_lo = 0.5; g.r_hi = 1;
  g.size_lo = 500; g.size_hi = 1000;
  run_all_combinations(g, 200, 1000, 900, "r/r_i = 1/1000");
}

TEST(SphereContactSolverExtreme, HugeMobileBetweenTinyBodies) {
  Ranges g;
  g.r_lo = 500; g.r_hi = 1000;
  g.size_lo = 0.5; g.size_hi = 1;
  run_all_combinations(g, 200, 1000, 1000, "r/r_i = 1000");
}

TEST(SphereContactSolverExtreme, TinyBodiesNextToAHugeOne) {
  Ranges g;
  g.r_lo = 0.5; g.r_hi = 1;
  g.slot_sizes = {{500, 1000}, {0.5, 1}, {0.5, 1}};
  run_all_combinations(g, 200, 1000, 1100, "one body 1000x the others");
  g.slot_sizes = {{0.5, 1}, {0.5, 1}, {500, 1000}};  // the huge one last: another frame
  run_all_combinations(g, 200, 1000, 1200, "one body 1000x the others, last");
}

TEST(SphereContactSolverExtreme, CoordinatesOffsetByAMillion) {
  Ranges g;
  g.r_lo = 0.5; g.r_hi = 2;
  g.size_lo = 0.5; g.size_hi = 2;
  g.offset = 1e6;
  run_all_combinations(g, 200, 1000, 1300, "offset 1e6");
}

TEST(SphereContactSolverExtreme, MicrometreRadii) {
  Ranges g;
  g.r_lo = 0.5e-6; g.r_hi = 2e-6;
  g.size_lo = 0.5e-6; g.size_hi = 2e-6;
  g.spread = 5e-6;
  run_all_combinations(g, 200, 1000, 1400, "radii 1e-6");
}

TEST(SphereContactSolverExtreme, WallReferencePointsFarFromTheContact) {
  // A box face or mesh facet is given by a point that may be far from where the ball touches it.
  // Regression: solve() used the first body's point as its frame origin, so a plane listed first
  // with its point 1e6 r away put the whole frame's rounding (~1e-10 r per operation) into the
  // answer: 13% of the known solutions were lost and some returned positions had gaps above
  // 1e-9 r although the solver had "verified" them in its rounded frame.
  const std::array<std::array<BodyKind, 3>, 4> combos3 = {{{BodyKind::Plane, BodyKind::Particle, BodyKind::Particle},
                                                           {BodyKind::Plane, BodyKind::Plane, BodyKind::Particle},
                                                           {BodyKind::Plane, BodyKind::Cylinder, BodyKind::Particle},
                                                           {BodyKind::Plane, BodyKind::Plane, BodyKind::Plane}}};
  Rng rng(1500);
  std::array<Placement<3>, 4> out;
  std::array<Placement<2>, 4> out2;
  int checked = 0;
  for (const double F : {1e3, 1e5, 1e6}) {
    for (const auto& kinds : combos3) {
      // Three planes each far from the contact: the frame must be on one of them; keep F moderate.
      if (kinds[2] == BodyKind::Plane && F > 1e5) continue;
      for (int trial = 0; trial < 1500; ++trial) {
        Config<3> cfg;
        const Vec3 x(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
        const double r = log_uniform(rng, 0.2, 5);
        std::array<Vec3, 3> normals;
        for (int i = 0; i < 3; ++i)
          normals[i] = add_tangent_body<3>(cfg, i, kinds[i], x, r, random_unit<3>(rng), log_uniform(rng, 0.2, 5), rng);
        for (Wall<3>& w : cfg.walls) {  // slide every plane's point along its plane
          if (w.kind != WallKind::Plane) continue;
          Vec3 t = w.normal.cross(random_unit<3>(rng)).normalized();
          t = (t - t.dot(w.normal) * w.normal).normalized();  // again: n.t ~ eps, so the plane stays put
          w.point += F * r * t;
        }
        const int n = SphereContactSolver<3>{}.solve(cfg.span(), Mobile<3>{r}, out);
        const std::span<const Placement<3>> sol(out.data(), n);
        ASSERT_TRUE(check_tangent<3>(cfg.span(), r, sol)) << "F = " << F;
        const double smin = sigma_min<3>(normals);
        if (smin < kWellConditioned) continue;
        ++checked;
        const auto [k, d] = closest<3>(sol, x);
        ASSERT_TRUE(k >= 0 && d <= 2 * std::sqrt(3.0) * kGapTol * r / smin)
            << "known solution " << vec_literal<3>(x) << " lost (nearest at " << d << ", sigma_min " << smin
            << "), F = " << F << config_literal<3>(cfg.span(), r);
      }
    }
    for (int trial = 0; trial < 5000; ++trial) {  // 2D: a polygon edge given by a far vertex
      Config<2> cfg;
      const Vec2 x(rng.uniform(-5, 5), rng.uniform(-5, 5));
      const double r = log_uniform(rng, 0.2, 5);
      std::array<Vec2, 2> normals;
      normals[0] = add_tangent_body<2>(cfg, 0, BodyKind::Plane, x, r, random_unit<2>(rng), 1.0, rng);
      normals[1] = add_tangent_body<2>(cfg, 1, BodyKind::Particle, x, r, random_unit<2>(rng), log_uniform(rng, 0.2, 5), rng);
      Wall<2>& w = cfg.walls[0];
      w.point += F * r * Vec2(-w.normal.y(), w.normal.x());
      const int n = SphereContactSolver<2>{}.solve(cfg.span(), Mobile<2>{r}, out2);
      const std::span<const Placement<2>> sol(out2.data(), n);
      ASSERT_TRUE(check_tangent<2>(cfg.span(), r, sol)) << "F = " << F;
      const double smin = sigma_min<2>(normals);
      if (smin < kWellConditioned) continue;
      ++checked;
      const auto [k, d] = closest<2>(sol, x);
      ASSERT_TRUE(k >= 0 && d <= 2 * std::sqrt(2.0) * kGapTol * r / smin)
          << "known solution " << vec_literal<2>(x) << " lost (nearest at " << d << ", sigma_min " << smin
          << "), F = " << F << config_literal<2>(cfg.span(), r);
    }
  }
  EXPECT_GT(checked, 25000);
}

}  // namespace
}  // namespace fp
