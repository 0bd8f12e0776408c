// SphereContactSolver with walls as bodies: every combination of body kinds (particle, plane,
// concave sphere, cylinder, vertex) built around a known ball, solved in every body order, checked
// for tangency (wall.gap ~ 0), inside-ness for concave walls, the known solution and the count of
// the long-double reference. Plus the classic named cases (box corner, cylinder cap edge).
#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "contact_test_support.hpp"

namespace fp {
namespace {

using namespace contact_test;

constexpr std::array<BodyKind, 5> kAllKinds = {BodyKind::Particle, BodyKind::Plane, BodyKind::SphereWall,
                                               BodyKind::Cylinder, BodyKind::Vertex};

std::string kinds_name(std::span<const BodyKind> k) {
  std::string s;
  for (BodyKind b : k) s += std::string(s.empty() ? "" : "+") + kind_name(b);
  return s;
}

TEST(SphereContactSolver3D, EveryCombinationOfBodyKindsTouchesTheKnownBall) {
  // All multisets of three kinds with at most one cylinder (two cylinder loci are not analytic).
  int combos = 0;
  for (int a = 0; a < 5; ++a)
    for (int b = a; b < 5; ++b)
      for (int c = b; c < 5; ++c) {
        const std::array<BodyKind, 3> k = {kAllKinds[a], kAllKinds[b], kAllKinds[c]};
        if ((a == 3) + (b == 3) + (c == 3) > 1) continue;
        Tally t;
        run_constructed<3>(k, 800, 200 + 25 * a + 5 * b + c, Ranges{}, t);
        if (HasFatalFailure()) {
          ADD_FAILURE() << "combination " << kinds_name(k);
          return;
        }
        std::cout << "[ stats    ] " << kinds_name(k) << ": " << t.configs << " solves, " << t.solutions
                  << " positions, " << t.compared << " counts compared, " << t.found << "/" << t.well_conditioned
                  << " known found\n";
        // The checks must have had something to check.
        EXPECT_GT(t.well_conditioned, t.configs / 2) << kinds_name(k);
        EXPECT_GT(t.compared, t.configs / 2) << kinds_name(k);
        ++combos;
      }
  EXPECT_EQ(combos, 30);
}

TEST(SphereContactSolver2D, EveryCombinationOfBodyKindsTouchesTheKnownDisk) {
  const std::array<BodyKind, 4> kinds2 = {BodyKind::Particle, BodyKind::Plane, BodyKind::SphereWall, BodyKind::Vertex};
  int combos = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      const std::array<BodyKind, 2> k = {kinds2[a], kinds2[b]};
      Tally t;
      run_constructed<2>(k, 3000, 300 + 4 * a + b, Ranges{}, t);
      if (HasFatalFailure()) {
        ADD_FAILURE() << "combination " << kinds_name(k);
        return;
      }
      std::cout << "[ stats    ] " << kinds_name(k) << ": " << t.configs << " solves, " << t.solutions
                << " positions, " << t.found << "/" << t.well_conditioned << " known found\n";
      EXPECT_GT(t.well_conditioned, t.configs / 2) << kinds_name(k);
      EXPECT_GT(t.compared, t.configs / 2) << kinds_name(k);
      ++combos;
    }
  EXPECT_EQ(combos, 10);
}

/// Perturbs a constructed configuration (moves every body by up to `max_amount` r), so that
/// some have no solution any more: the answer must still be tangent and match the reference.
template <int D>
void run_perturbed(const std::array<BodyKind, D>& kinds, int trials, std::uint64_t seed, double max_amount, Tally& t,
                   int& empty) {
  Rng rng(seed);
  const SphereContactSolver<D> solver;
  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> out;
  for (int trial = 0; trial < trials; ++trial) {
    Config<D> cfg;
    Vec<D> x = Vec<D>::Zero();
    const double r = log_uniform(rng, 0.2, 5);
    cfg.r = r;
    for (int i = 0; i < D; ++i)
      add_tangent_body<D>(cfg, i, kinds[i], x, r, random_unit<D>(rng), log_uniform(rng, 0.2, 5), rng);
    const double amount = rng.uniform(0, max_amount);
    for (int i = 0; i < D; ++i) {
      if (!cfg.fixed[i].is_wall()) cfg.fixed[i].center += amount * r * random_unit<D>(rng);
    }
    for (Wall<D>& w : cfg.walls) w.point += amount * r * random_unit<D>(rng);
    const int n = solver.solve(cfg.span(), Mobile<D>{r}, out);
    const std::span<const Placement<D>> sol(out.data(), n);
    ++t.configs;
    t.solutions += n;
    empty += n == 0;
    ASSERT_TRUE(check_tangent<D>(cfg.span(), r, sol)) << kinds_name(kinds);
    const Reference<D> ref = reference_solutions<D>(cfg.span(), r);
    t.compared += ref.supported && !ref.ambiguous;
    ASSERT_TRUE(check_against_reference<D>(cfg.span(), r, sol, 1e-6 * r)) << kinds_name(kinds);
  }
}

TEST(SphereContactSolver3D, PerturbedWallConfigurationsMatchTheReference) {
  int combos = 0, empty = 0, configs = 0;
  for (int a = 0; a < 5; ++a)
    for (int b = a; b < 5; ++b)
      for (int c = b; c < 5; ++c) {
        const std::array<BodyKind, 3> k = {kAllKinds[a], kAllKinds[b], kAllKinds[c]};
        if ((a == 3) + (b == 3) + (c == 3) > 1) continue;
        Tally t;
        run_perturbed<3>(k, 2000, 400 + 25 * a + 5 * b + c, 3.0, t, empty);
        if (HasFatalFailure()) return;
        EXPECT_GT(t.compared, t.configs / 2) << kinds_name(k);
        configs += t.configs;
        ++combos;
      }
  EXPECT_EQ(combos, 30);
  std::cout << "[ stats    ] " << configs << " perturbed configurations, " << empty << " without solution\n";
  EXPECT_GT(empty, configs / 10);  // the 0-solution answers were exercised too
}

TEST(SphereContactSolver2D, PerturbedWallConfigurationsMatchTheReference) {
  const std::array<BodyKind, 4> kinds2 = {BodyKind::Particle, BodyKind::Plane, BodyKind::SphereWall, BodyKind::Vertex};
  int empty = 0, configs = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      Tally t;
      run_perturbed<2>({kinds2[a], kinds2[b]}, 5000, 500 + 4 * a + b, 3.0, t, empty);
      if (HasFatalFailure()) return;
      EXPECT_GT(t.compared, t.configs / 2);
      configs += t.configs;
    }
  std::cout << "[ stats    ] " << configs << " perturbed configurations, " << empty << " without solution\n";
  EXPECT_GT(empty, configs / 10);
}

TEST(Wall, GapMatchesTheLongDoubleDefinition) {
  // The tests verify tangency with gap_ld; Wall::gap (used by the packer) must agree with it.
  Rng rng(600);
  for (int trial = 0; trial < 2000; ++trial) {
    Config<3> cfg;
    const Vec3 x(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3));
    const double r = log_uniform(rng, 0.1, 3);
    for (int i = 0; i < 3; ++i)
      add_tangent_body<3>(cfg, i, kAllKinds[1 + (trial + i) % 4], Vec3::Zero(), 1.0, random_unit<3>(rng), 2.0, rng);
    for (const Body<3>& b : cfg.fixed) {
      const double g = b.wall->gap(x, r);
      EXPECT_NEAR(g, static_cast<double>(gap_ld<3>(b, x, r)), 1e-14 * (1 + std::abs(g)));
    }
  }
}

// ---- named cases ----

TEST(SphereContactSolver3D, BoxCornerGivesTheSinglePositionOffsetByRFromEachFace) {
  const std::vector<Wall<3>> w = {Wall<3>::plane(Vec3(0, 0, 0), Vec3(1, 0, 0)), Wall<3>::plane(Vec3(0, 0, 0), Vec3(0, 1, 0)),
                                  Wall<3>::plane(Vec3(0, 0, 0), Vec3(0, 0, 1))};
  const std::array<Body<3>, 3> f = {Body<3>::of_wall(w[0]), Body<3>::of_wall(w[1]), Body<3>::of_wall(w[2])};
  std::array<Placement<3>, 4> out;
  ASSERT_EQ(SphereContactSolver<3>{}.solve(f, Mobile<3>{0.25}, out), 1);
  EXPECT_EQ(out[0].position, Vec3(0.25, 0.25, 0.25));
  // Two parallel faces (a slab) and a third: no isolated position.
  const std::vector<Wall<3>> slab = {Wall<3>::plane(Vec3(0, 0, 0), Vec3(1, 0, 0)), Wall<3>::plane(Vec3(1, 0, 0), Vec3(-1, 0, 0)),
                                     Wall<3>::plane(Vec3(0, 0, 0), Vec3(0, 0, 1))};
  const std::array<Body<3>, 3> g = {Body<3>::of_wall(slab[0]), Body<3>::of_wall(slab[1]), Body<3>::of_wall(slab[2])};
  EXPECT_EQ(SphereContactSolver<3>{}.solve(g, Mobile<3>{0.5}, out), 0);
}

TEST(SphereContactSolver3D, CylinderCapEdgeWithASphere) {
  // Cylinder container of radius R around the z axis, bottom cap z = 0, a sphere resting on the
  // cap at distance rho_i from the axis. In the plane z = r the centres touching cap and sphere
  // form a circle of radius 2 sqrt(r r_i) around the sphere; the rim (touching side and cap) is
  // the circle of radius R - r around the axis: two intersections, computed here in closed form.
  Rng rng(601);
  const SphereContactSolver<3> solver;
  int checked = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    const double R = rng.uniform(3, 10), r = rng.uniform(0.2, 1.5), ri = rng.uniform(0.2, 1.5);
    const double a = 2 * std::sqrt(r * ri), b = R - r;
    const double rho_lo = b - a, rho_hi = R - ri;  // the circles cross; the sphere is inside
    if (!(rho_hi > rho_lo)) continue;
    const double rho_i = rho_lo + (rho_hi - rho_lo) * rng.uniform(0.02, 0.98);
    const double phi = rng.uniform(0, 2 * kPi);
    const Vec3 e(std::cos(phi), std::sin(phi), 0), e_perp(-std::sin(phi), std::cos(phi), 0);
    const Vec3 ci = rho_i * e + Vec3(0, 0, ri);
    const std::vector<Wall<3>> w = {Wall<3>::cylinder(Vec3(0, 0, rng.uniform(-5, 5)), Vec3(0, 0, 1), R),
                                    Wall<3>::plane(Vec3(0, 0, 0), Vec3(0, 0, 1))};
    std::array<Body<3>, 3> f = {Body<3>::sphere(ci, ri), Body<3>::of_wall(w[0]), Body<3>::of_wall(w[1])};
    if (trial % 3 == 1) std::swap(f[0], f[1]);
    if (trial % 3 == 2) std::swap(f[0], f[2]);
    std::array<Placement<3>, 4> out;
    const int n = solver.solve(f, Mobile<3>{r}, out);
    const std::span<const Placement<3>> sol(out.data(), n);
    ASSERT_TRUE(check_tangent<3>(f, r, sol));
    ASSERT_TRUE(check_against_reference<3>(f, r, sol, 1e-6 * r));
    // Circle-circle intersection: along e at u = (rho_i^2 + b^2 - a^2) / (2 rho_i), +-v across.
    const double u = (rho_i * rho_i + b * b - a * a) / (2 * rho_i), v = std::sqrt(b * b - u * u);
    if (!(v > 1e-3 * r)) continue;  // nearly tangent circles: a double root
    ++checked;
    ASSERT_EQ(n, 2) << config_literal<3>(f, r);
    for (const double sgn : {-1.0, 1.0}) {
      const Vec3 x = u * e + sgn * v * e_perp + Vec3(0, 0, r);
      const auto [k, d] = closest<3>(sol, x);
      ASSERT_TRUE(k >= 0 && d < 1e-9 * R / (v / b)) << "distance " << d << config_literal<3>(f, r);
    }
    for (int k = 0; k < n; ++k) EXPECT_NEAR(out[k].position.z(), r, 1e-12 * R);  // on the cap
  }
  EXPECT_GT(checked, 2500);
}

TEST(SphereContactSolver3D, CylinderRootPairInsideOneGridCellIsFound) {
  // Regression (found by EveryCombinationOfBodyKindsTouchesTheKnownBall): the circle of centres
  // touching both spheres crosses the cylinder locus twice within 0.04 rad, inside one cell of
  // the solver's 96-step angular grid, so no sign change was seen and both were missed
  // (2.5-3.5% of valid positions for sphere + sphere/plane/vertex + cylinder).
  const std::vector<fp::Wall<3>> walls = {
      fp::Wall<3>::cylinder(fp::Vec3(-2.1401171880215841, 0.89645338504244387, 2.2787193636225185), fp::Vec3(-0.86355163722374584, -0.46778779183545899, 0.18829007317937235), 2.5398667173602676)};
  const std::array<fp::Body<3>, 3> fixed = {
      fp::Body<3>::sphere(fp::Vec3(-6.8890184033923845, -4.8866976732065242, -0.11130001512543419), 4.0519871972313926),
      fp::Body<3>::sphere(fp::Vec3(-4.0507047580837252, -3.7210143714289954, 1.7954989754669572), 1.2628630085244077),
      fp::Body<3>::of_wall(walls[0])};
  const double r = 1.8472176103249485;
  EXPECT_TRUE(fp::contact_test::check_solve<3>(fixed, r));
  std::array<Placement<3>, 4> out;
  const int n = SphereContactSolver<3>{}.solve(fixed, Mobile<3>{r}, out);
  ASSERT_EQ(n, 2);
  // The constructed ball, and the second root 0.1 away.
  const Vec3 x(-3.7423202389623986, -0.75916806028278749, 2.6926984367119475);
  EXPECT_LT(closest<3>(std::span<const Placement<3>>(out.data(), n), x).second, 1e-9);
  EXPECT_GT((out[0].position - out[1].position).norm(), 0.05);
}

TEST(SphereContactSolver2D, ConcaveCircleAndDiskKeepTheParticleInside) {
  // A disk container of radius 10; a fixed disk touching its wall; the mobile disk must be inside.
  const std::vector<Wall<2>> w = {Wall<2>::sphere(Vec2(1, 2), 10)};
  const std::array<Body<2>, 2> f = {Body<2>::of_wall(w[0]), Body<2>::sphere(Vec2(1 + 9, 2), 1)};
  std::array<Placement<2>, 4> out;
  const int n = SphereContactSolver<2>{}.solve(f, Mobile<2>{1.0}, out);
  ASSERT_EQ(n, 2);
  for (int k = 0; k < n; ++k) {
    EXPECT_NEAR(w[0].gap(out[k].position, 1.0), 0.0, 1e-13);
    EXPECT_LT((out[k].position - Vec2(1, 2)).norm(), 10.0 - 1.0 + 1e-12);
  }
  // A mobile disk larger than the container cannot touch it from inside.
  EXPECT_EQ(SphereContactSolver<2>{}.solve(f, Mobile<2>{10.0}, out), 0);
  EXPECT_EQ(SphereContactSolver<2>{}.solve(f, Mobile<2>{12.0}, out), 0);
}

TEST(SphereContactSolver2D, CylinderWallIsRejectedIn2D) {
  Wall<2> cyl;
  cyl.kind = WallKind::Cylinder;
  cyl.radius = 5;
  const std::array<Body<2>, 2> f = {Body<2>::of_wall(cyl), Body<2>::sphere(Vec2(3, 0), 1)};
  std::array<Placement<2>, 4> out;
  EXPECT_EQ(SphereContactSolver<2>{}.solve(f, Mobile<2>{1.0}, out), 0);
}

TEST(SphereContactSolver2D, TwoLinesGiveTheCornerPosition) {
  // A 60 degree wedge: the disk touching both sides sits on the bisector at r / sin(30 deg).
  const std::vector<Wall<2>> w = {Wall<2>::plane(Vec2(0, 0), Vec2(0, 1)),
                                  Wall<2>::plane(Vec2(0, 0), Vec2(std::sin(kPi / 3), -std::cos(kPi / 3)))};
  const std::array<Body<2>, 2> f = {Body<2>::of_wall(w[0]), Body<2>::of_wall(w[1])};
  std::array<Placement<2>, 4> out;
  ASSERT_EQ(SphereContactSolver<2>{}.solve(f, Mobile<2>{0.5}, out), 1);
  EXPECT_NEAR(out[0].position.x(), 0.5 / std::tan(kPi / 6), 1e-14);
  EXPECT_NEAR(out[0].position.y(), 0.5, 1e-15);
}

}  // namespace
}  // namespace fp
