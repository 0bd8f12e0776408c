// The ellipsoid contact solver (contact/ellipsoid_contact_solver.cpp): ellipsoids (ellipses) with
// spheres (disks) and plane walls, by Newton's method on the wrappers.
//  1. every returned position touches each fixed body within 1e-9 of the smaller size and
//     overlaps none, by the independent long-double gaps of general_contact_support.hpp; the
//     constructed (known) position is found in most problems (printed: Newton from the
//     equivalent-sphere starts can miss one, and never returns a wrong one);
//  2. against the minimisation solver on the same problems: the positions it finds that the
//     solver does not are counted and printed, and must stay a small share;
//  3. spheres alone give the analytic sphere solver's positions; far apart gives none;
//  4. extremes: aspect ratio 0.05 (semi-axes 20 : 1), sizes 1 : 100, coordinates offset by 1e6.
#include <gtest/gtest.h>

#include <cstdio>

#include "contact/ellipsoid_contact_solver.hpp"
#include "contact/sphere_contact_solver.hpp"
#include "general_contact_support.hpp"

namespace fp::general_test {
namespace {

constexpr double kTol = 1e-9;  // the contact accuracy, relative to the smaller size

template <int D>
Tally run_constructed(const char* name, Kind mobile, const std::array<Kind, D>& fixed, int trials, std::uint64_t seed,
                      const Sizes& sizes = Sizes{}) {
  const EllipsoidContactSolver<D> solver;
  const Tally t = run_constructed_with<D>(solver, name, mobile, fixed, trials, seed, kTol, 1e-7, sizes);
  print_tally<D>(name, t);
  return t;
}

// ================================================================ 1. touching and overlap-free

// The known position is found in at least 90 % of the problems (measured: 100 %; 90-97.5 % at
// the extremes of section 4).
TEST(EllipsoidContactSolver, EveryPositionTouchesEveryBodyAndOverlapsNone2D) {
  using K = Kind;
  struct Case { const char* name; K mobile; std::array<K, 2> fixed; };
  const Case cases[] = {
      {"ellipse | ellipse ellipse", K::Ellipsoid, {K::Ellipsoid, K::Ellipsoid}},
      {"ellipse | disk ellipse", K::Ellipsoid, {K::Sphere, K::Ellipsoid}},
      {"disk | ellipse ellipse", K::Sphere, {K::Ellipsoid, K::Ellipsoid}},
      {"ellipse | plane ellipse", K::Ellipsoid, {K::Plane, K::Ellipsoid}},
      {"ellipse | plane plane", K::Ellipsoid, {K::Plane, K::Plane}},
  };
  std::uint64_t seed = 9000;
  for (const Case& c : cases) {
    const Tally t = run_constructed<2>(c.name, c.mobile, c.fixed, 60, seed++);
    EXPECT_GE(t.known_found + t.known_on_stretch, t.built * 9 / 10) << c.name;
  }
}

TEST(EllipsoidContactSolver, EveryPositionTouchesEveryBodyAndOverlapsNone3D) {
  using K = Kind;
  struct Case { const char* name; K mobile; std::array<K, 3> fixed; };
  const Case cases[] = {
      {"ellipsoid | ellipsoid x3", K::Ellipsoid, {K::Ellipsoid, K::Ellipsoid, K::Ellipsoid}},
      {"ellipsoid | sphere ellipsoid ellipsoid", K::Ellipsoid, {K::Sphere, K::Ellipsoid, K::Ellipsoid}},
      {"sphere | ellipsoid x3", K::Sphere, {K::Ellipsoid, K::Ellipsoid, K::Ellipsoid}},
      {"ellipsoid | plane ellipsoid ellipsoid", K::Ellipsoid, {K::Plane, K::Ellipsoid, K::Ellipsoid}},
      {"ellipsoid | plane plane ellipsoid", K::Ellipsoid, {K::Plane, K::Plane, K::Ellipsoid}},
  };
  std::uint64_t seed = 9100;
  for (const Case& c : cases) {
    const Tally t = run_constructed<3>(c.name, c.mobile, c.fixed, 40, seed++);
    EXPECT_GE(t.known_found + t.known_on_stretch, t.built * 9 / 10) << c.name;
  }
}

// ============================================================== 2. against the minimisation

template <int D>
void minimisation_round(int trials, std::uint64_t seed) {
  const EllipsoidContactSolver<D> solver;
  const KindDraw<D> kinds = [](Rng& rng, Kind& mobile, std::array<Kind, D>& fixed) {
    mobile = rng.below(4) == 0 ? Kind::Sphere : Kind::Ellipsoid;
    for (Kind& k : fixed) k = rng.below(4) == 0 ? Kind::Sphere : Kind::Ellipsoid;
    if (rng.below(3) == 0) fixed[0] = Kind::Plane;
  };
  const int missed = missed_minimisation_positions<D>(solver, "ellipsoids, spheres, planes", kinds, trials, seed);
  EXPECT_LE(missed, trials / 10);
}

TEST(EllipsoidContactSolver, AgainstTheMinimisation2D) { minimisation_round<2>(60, 9200); }
TEST(EllipsoidContactSolver, AgainstTheMinimisation3D) { minimisation_round<3>(40, 9300); }

// ========================================================= 3. spheres, and nothing to find

TEST(EllipsoidContactSolver, SpheresGiveTheAnalyticPositions2D) { expect_analytic_positions_for_spheres<2>(EllipsoidContactSolver<2>{}, 60, 9400); }
TEST(EllipsoidContactSolver, SpheresGiveTheAnalyticPositions3D) { expect_analytic_positions_for_spheres<3>(EllipsoidContactSolver<3>{}, 60, 9500); }

TEST(EllipsoidContactSolver, FarApartGivesNothing) {
  expect_nothing_when_one_is_far<2>(EllipsoidContactSolver<2>{}, Kind::Ellipsoid, {Kind::Ellipsoid, Kind::Ellipsoid}, 100, 30, 27, 9600);
  expect_nothing_when_one_is_far<3>(EllipsoidContactSolver<3>{}, Kind::Ellipsoid, {Kind::Ellipsoid, Kind::Ellipsoid, Kind::Ellipsoid},
                                    100, 30, 27, 9601);
}

// ====================================================================== 4. extremes

TEST(EllipsoidContactSolver, AspectRatioTwentyAndSizesOneToHundred) {
  using K = Kind;
  std::vector<Tally> t;
  t.push_back(run_constructed<2>("thin ellipse | ellipse ellipse", K::ThinEllipsoid, {K::Ellipsoid, K::Ellipsoid}, 40, 9700));
  t.push_back(run_constructed<2>("ellipse | thin ellipse x2", K::Ellipsoid, {K::ThinEllipsoid, K::ThinEllipsoid}, 40, 9701));
  t.push_back(run_constructed<3>("thin ellipsoid | ellipsoid x3", K::ThinEllipsoid, {K::Ellipsoid, K::Ellipsoid, K::Ellipsoid}, 30, 9702));
  t.push_back(run_constructed<3>("ellipsoid | thin ellipsoid x3", K::Ellipsoid, {K::ThinEllipsoid, K::ThinEllipsoid, K::ThinEllipsoid}, 30, 9703));
  Sizes tiny;
  tiny.mobile = 0.01;
  tiny.allow_fixed_overlap = true;  // a tiny mobile cannot touch three big bodies that do not overlap
  t.push_back(run_constructed<3>("small ellipsoid | ellipsoid x3", K::Ellipsoid, {K::Ellipsoid, K::Ellipsoid, K::Ellipsoid}, 30, 9704, tiny));
  Sizes big;
  big.fixed = {0.01, 0.01, 0.01};
  t.push_back(run_constructed<3>("big ellipsoid | small ellipsoid x3", K::Ellipsoid, {K::Ellipsoid, K::Ellipsoid, K::Ellipsoid}, 30, 9705, big));
  // Every returned position is checked by run_constructed_with; the known one is found in most.
  for (const Tally& x : t) EXPECT_GE(x.known_found + x.known_on_stretch, x.built * 3 / 4);
}

TEST(EllipsoidContactSolver, CoordinatesOffsetByAMillion) {
  expect_same_when_shifted<2>(EllipsoidContactSolver<2>(), Kind::Ellipsoid, {Kind::Plane, Kind::Ellipsoid}, kTol, 9800);
  expect_same_when_shifted<3>(EllipsoidContactSolver<3>(), Kind::Ellipsoid, {Kind::Plane, Kind::Ellipsoid, Kind::Ellipsoid}, kTol, 9801);
}

}  // namespace
}  // namespace fp::general_test
