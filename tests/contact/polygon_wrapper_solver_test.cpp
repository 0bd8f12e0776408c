// The 2D polygon wrapper solver (contact/polygon_wrapper_solver.cpp): disks, stadiums, convex
// polygons and clusters against each other and the walls, by intersecting circumpolygons.
//  1. every returned position touches each fixed body within 1e-9 of the smaller size and
//     overlaps none (independent long-double gaps), and the constructed position is found;
//  2. against the brute force (crossings of the two touching contours, traced from the shapes'
//     own support functions): every crossing is found, and nothing else is returned;
//  3. every position the minimisation solver finds is one of them;
//  4. far apart gives none; extremes: aspect ratio 0.05, size ratio 1:100, offset 1e6,
//     near-parallel edges (squares at 1e-9 rad of each other).
#include <gtest/gtest.h>

#include <cstdio>

#include "contact/polygon_wrapper_solver.hpp"
#include "general_contact_support.hpp"

namespace fp::general_test {
namespace {

constexpr double kTol = 1e-9;

using Out = std::array<Placement<2>, ContactSolver<2>::kMaxCandidates>;
std::span<const Placement<2>> first(const Out& out, int n) { return {out.data(), static_cast<std::size_t>(n)}; }

Tally run_constructed(const char* name, Kind mobile, const std::array<Kind, 2>& fixed, int trials, std::uint64_t seed,
                      const Sizes& sizes = Sizes{}) {
  const PolygonWrapperSolver solver;
  const Tally t = run_constructed_with<2>(solver, name, mobile, fixed, trials, seed, kTol, 1e-7, sizes);
  print_tally<2>(name, t);
  return t;
}

// ================================================================ 1. touching and overlap-free

TEST(PolygonWrapperSolver, EveryPositionTouchesEveryBodyAndOverlapsNone) {
  using K = Kind;
  struct Case { const char* name; K mobile; std::array<K, 2> fixed; };
  const Case cases[] = {
      {"polygon | polygon polygon", K::Polytope, {K::Polytope, K::Polytope}},
      {"polygon | capsule capsule", K::Polytope, {K::Capsule, K::Capsule}},
      {"capsule | polygon polygon", K::Capsule, {K::Polytope, K::Polytope}},
      {"capsule | capsule capsule", K::Capsule, {K::Capsule, K::Capsule}},
      {"disk | polygon capsule", K::Sphere, {K::Polytope, K::Capsule}},
      {"polygon | disk disk", K::Polytope, {K::Sphere, K::Sphere}},
      {"cluster | polygon polygon", K::Cluster, {K::Polytope, K::Polytope}},
      {"polygon | cluster capsule", K::Polytope, {K::Cluster, K::Capsule}},
      {"cluster | cluster cluster", K::Cluster, {K::Cluster, K::Cluster}},
      {"polygon | plane polygon", K::Polytope, {K::Plane, K::Polytope}},
      {"capsule | plane capsule", K::Capsule, {K::Plane, K::Capsule}},
      {"polygon | disk-wall polygon", K::Polytope, {K::SphereWall, K::Polytope}},
      {"cluster | disk-wall capsule", K::Cluster, {K::SphereWall, K::Capsule}},
      {"capsule | plane cluster", K::Capsule, {K::Plane, K::Cluster}},
  };
  std::uint64_t seed = 9000;
  for (const Case& c : cases) {
    const Tally t = run_constructed(c.name, c.mobile, c.fixed, 60, seed++);
    EXPECT_EQ(t.known_found + t.known_on_stretch + t.known_inexact, t.built) << c.name;
  }
}

// ================================================================== 2. brute force (contours)

// Capsule / polygon / disk mobiles against two fixed convex particles at random gaps. The brute
// force samples each touching contour at 4096 support directions and bisects its crossings: its
// positions are accurate to ~1e-6 of the size, and crossings closer than 2 % of the size or at
// less than 2 degrees (near-tangent) are not told apart, so those configurations are not counted.
TEST(PolygonWrapperSolver, FindsEveryBruteForceSolutionAndNothingElse) {
  NarrowPhase<2> np;
  const PolygonWrapperSolver solver;
  Rng rng(9100);
  const Kind mobiles[] = {Kind::Capsule, Kind::Polytope, Kind::Sphere};
  const Kind fixeds[] = {Kind::Sphere, Kind::Capsule, Kind::Polytope};
  int configs = 0, counted = 0, reference = 0, matched = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Problem<2> pb;
    if (!gapped_pair_problem(pb, np, fixeds[rng.below(3)], fixeds[rng.below(3)], mobiles[rng.below(3)], rng)) continue;
    ++configs;
    double angle = 180;
    const std::vector<Vec2> ref = brute_force_crossings(pb, angle);
    Out out;
    const int n = solver.solve(pb.span(), pb.mobile(), out);
    ASSERT_TRUE(check_placements<2>(pb, first(out, n), kTol)) << "trial " << trial;
    const double r_mob = pb.mobile_shape->bounding_radius();
    bool isolated = angle > 2;
    for (std::size_t i = 0; i < ref.size(); ++i)
      for (std::size_t j = i + 1; j < ref.size(); ++j) isolated &= (ref[i] - ref[j]).norm() > 2e-2 * r_mob;
    if (!isolated) continue;
    ++counted;
    reference += static_cast<int>(ref.size());
    EXPECT_EQ(static_cast<std::size_t>(n), ref.size()) << "trial " << trial << pb.literal();
    for (const Vec2& x : ref) {
      const double d = closest<2>(first(out, n), x).second;
      matched += d <= 1e-5 * r_mob;
      EXPECT_LE(d, 1e-5 * r_mob) << "trial " << trial << ": crossing " << vec_literal<2>(x) << " not found" << pb.literal();
    }
  }
  std::printf("  %d configurations, %d with isolated crossings: %d / %d crossings found\n", configs, counted, matched, reference);
  EXPECT_GT(counted, 120);
}

// ================================================================ 3. against the minimisation

TEST(PolygonWrapperSolver, FindsEveryPositionOfTheMinimisation) {
  const KindDraw<2> any = [](Rng& rng, Kind& mobile, std::array<Kind, 2>& fixed) {
    const Kind kinds[] = {Kind::Polytope, Kind::Capsule, Kind::Sphere, Kind::Cluster};
    mobile = kinds[rng.below(4)];
    for (Kind& k : fixed) k = kinds[rng.below(4)];
  };
  EXPECT_EQ(missed_minimisation_positions<2>(PolygonWrapperSolver(), "rounded cores", any, 80, 9200), 0);
}

// ============================================================= 4. failures and extremes

TEST(PolygonWrapperSolver, FarApartGivesNothing) {
  expect_nothing_when_one_is_far<2>(PolygonWrapperSolver{}, Kind::Polytope, {Kind::Polytope, Kind::Capsule}, 50, 40, 36, 9300);
}

TEST(PolygonWrapperSolver, ThinCapsulesAndSizeRatioOneToHundred) {
  using K = Kind;
  Sizes tiny;
  tiny.mobile = 0.01;
  tiny.allow_fixed_overlap = true;
  Sizes big;
  big.fixed = {0.01, 0.01};
  const Tally a = run_constructed("thin capsule | polygon thin capsule", K::ThinCapsule, {K::Polytope, K::ThinCapsule}, 40, 9400);
  const Tally b = run_constructed("small polygon | polygon polygon", K::Polytope, {K::Polytope, K::Polytope}, 40, 9401, tiny);
  const Tally c = run_constructed("big polygon | small capsule x2", K::Polytope, {K::Capsule, K::Capsule}, 40, 9402, big);
  for (const Tally& t : {a, b, c}) EXPECT_EQ(t.known_found + t.known_on_stretch + t.known_inexact, t.built);
}

TEST(PolygonWrapperSolver, CoordinatesOffsetByAMillion) {
  expect_same_when_shifted<2>(PolygonWrapperSolver(), Kind::Polytope, {Kind::Polytope, Kind::Plane}, kTol, 9500);
}

// Squares side by side, their edges parallel to 1e-9 rad, a square dropped onto both: the
// positions are the ends of the flush contacts, each touching both squares and overlapping none.
TEST(PolygonWrapperSolver, NearParallelEdges) {
  ShapeParameters p;
  p.point_lists["vertices"] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const ShapePtr<2> square = family_prototype<2>("polygon", p);
  for (const double tilt : {0.0, 1e-12, 1e-9, 1e-6}) {
    Problem<2> pb;
    Particle<2> a, b;
    a.shape = b.shape = square;
    a.pose.position = Vec2(0, 0);
    b.pose.position = Vec2(3 * square->bounding_radius() / std::sqrt(2.0), 0);
    b.pose.rotation = rotation_2d(tilt);
    pb.set_particle(0, a);
    pb.set_particle(1, b);
    pb.mobile_shape = square;
    pb.mobile_rotation = rotation_2d(-tilt);
    Out out;
    const PolygonWrapperSolver solver;
    const int n = solver.solve(pb.span(), pb.mobile(), out);
    EXPECT_GE(n, 2) << "tilt " << tilt;
    EXPECT_TRUE(check_placements<2>(pb, first(out, n), kTol)) << "tilt " << tilt;
  }
}

}  // namespace
}  // namespace fp::general_test
