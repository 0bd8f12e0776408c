// The gap Newton solver (contact/gap_newton_solver.cpp): Newton's method alone on the contact
// equations, registered for 3D capsules with capsules, spheres and smooth walls.
//  1. every returned position touches each fixed body within 1e-9 of the smaller size and
//     overlaps none, by the independent long-double gaps of general_contact_support.hpp; the
//     constructed (known) position is found in most problems, about as often as the minimisation
//     solver finds it in the same problems (printed: both start from equivalent spheres and can
//     miss one; neither returns a wrong one);
//  2. against the minimisation solver on the same problems: the positions it finds that Newton
//     alone does not are counted and printed, and must stay a small share;
//  3. spheres alone give the analytic sphere solver's positions; far apart gives none;
//  4. extremes: aspect ratio 0.05 (length / width 20), sizes 1 : 100, coordinates offset by 1e6,
//     and nearly parallel capsules.
#include <gtest/gtest.h>

#include <cstdio>

#include "contact/gap_newton_solver.hpp"
#include "general_contact_support.hpp"

namespace fp::general_test {
namespace {

constexpr double kTol = 1e-9;  // the contact accuracy, relative to the smaller size

// The problems of run_constructed_with solved by Newton alone (every position checked to 1e-9)
// and, the same problems (same seed), by the minimisation solver (checked to its own 1e-6): Newton
// alone finds the known position about as often as the minimisation does (within 1 problem in
// 10; both miss some from the equivalent-sphere starts), and in at least `floor` of them.
template <int D>
void expect_like_the_minimisation(const char* name, Kind mobile, const std::array<Kind, D>& fixed, int trials, std::uint64_t seed,
                                  double floor, const Sizes& sizes = Sizes{}) {
  NarrowPhase<D> np;
  const GapNewtonSolver<D> newton(np, MinimisationOptions{}.gap_tolerance);
  const MinimisationSolver<D> minimisation(np, MinimisationOptions{});
  const Tally t = run_constructed_with<D>(newton, name, mobile, fixed, trials, seed, kTol, 1e-7, sizes);
  const Tally m = run_constructed_with<D>(minimisation, name, mobile, fixed, trials, seed, MinimisationOptions{}.gap_tolerance, 1e-5, sizes);
  print_tally<D>(name, t);
  std::printf("     minimisation, same problems: known found %5.1f %% (+%d on a stretch)\n", 100 * m.known_recall(), m.known_on_stretch);
  const int found = t.known_found + t.known_on_stretch, found_by_minimisation = m.known_found + m.known_on_stretch;
  EXPECT_GE(found, found_by_minimisation - t.built / 10) << name;
  EXPECT_GE(found, floor * t.built) << name;
}

// ================================================================ 1. touching and overlap-free

TEST(GapNewtonSolver, EveryPositionTouchesEveryBodyAndOverlapsNone) {
  using K = Kind;
  struct Case { const char* name; K mobile; std::array<K, 3> fixed; };
  const Case cases[] = {
      {"capsule | capsule x3", K::Capsule, {K::Capsule, K::Capsule, K::Capsule}},
      {"capsule | sphere capsule capsule", K::Capsule, {K::Sphere, K::Capsule, K::Capsule}},
      {"sphere | capsule x3", K::Sphere, {K::Capsule, K::Capsule, K::Capsule}},
      {"capsule | sphere x3", K::Capsule, {K::Sphere, K::Sphere, K::Sphere}},
      {"capsule | plane capsule capsule", K::Capsule, {K::Plane, K::Capsule, K::Capsule}},
      {"capsule | plane plane capsule", K::Capsule, {K::Plane, K::Plane, K::Capsule}},
      {"capsule | sphere wall capsule capsule", K::Capsule, {K::SphereWall, K::Capsule, K::Capsule}},
      {"capsule | cylinder wall plane capsule", K::Capsule, {K::CylinderWall, K::Plane, K::Capsule}},
  };
  std::uint64_t seed = 9900;
  for (const Case& c : cases) expect_like_the_minimisation<3>(c.name, c.mobile, c.fixed, 40, seed++, 0.75);
}

// ============================================================== 2. against the minimisation

TEST(GapNewtonSolver, AgainstTheMinimisation) {
  NarrowPhase<3> np;
  const GapNewtonSolver<3> solver(np, MinimisationOptions{}.gap_tolerance);
  const KindDraw<3> kinds = [](Rng& rng, Kind& mobile, std::array<Kind, 3>& fixed) {
    mobile = rng.below(4) == 0 ? Kind::Sphere : Kind::Capsule;
    for (Kind& k : fixed) k = rng.below(4) == 0 ? Kind::Sphere : Kind::Capsule;
    if (rng.below(3) == 0) fixed[0] = Kind::Plane;
  };
  const int missed = missed_minimisation_positions<3>(solver, "capsules, spheres, planes", kinds, 60, 9950);
  EXPECT_LE(missed, 60 / 10);
}

// ========================================================= 3. spheres, and nothing to find

TEST(GapNewtonSolver, SpheresGiveTheAnalyticPositions) {
  NarrowPhase<3> np;
  expect_analytic_positions_for_spheres<3>(GapNewtonSolver<3>(np, MinimisationOptions{}.gap_tolerance), 60, 9960);
}

TEST(GapNewtonSolver, FarApartGivesNothing) {
  NarrowPhase<3> np;
  expect_nothing_when_one_is_far<3>(GapNewtonSolver<3>(np, MinimisationOptions{}.gap_tolerance), Kind::Capsule,
                                    {Kind::Capsule, Kind::Capsule, Kind::Capsule}, 100, 30, 27, 9970);
}

// ====================================================================== 4. extremes

TEST(GapNewtonSolver, AspectRatioTwentyAndSizesOneToHundred) {
  using K = Kind;
  expect_like_the_minimisation<3>("thin capsule | capsule x3", K::ThinCapsule, {K::Capsule, K::Capsule, K::Capsule}, 30, 9980, 0.5);
  expect_like_the_minimisation<3>("capsule | thin capsule x3", K::Capsule, {K::ThinCapsule, K::ThinCapsule, K::ThinCapsule}, 30, 9981, 0.5);
  Sizes tiny;
  tiny.mobile = 0.01;
  tiny.allow_fixed_overlap = true;  // a tiny mobile cannot touch three big bodies that do not overlap
  expect_like_the_minimisation<3>("small capsule | capsule x3", K::Capsule, {K::Capsule, K::Capsule, K::Capsule}, 30, 9982, 0.75, tiny);
  Sizes big;
  big.fixed = {0.01, 0.01, 0.01};
  expect_like_the_minimisation<3>("big capsule | small capsule x3", K::Capsule, {K::Capsule, K::Capsule, K::Capsule}, 30, 9983, 0.6, big);
}

TEST(GapNewtonSolver, CoordinatesOffsetByAMillion) {
  NarrowPhase<3> np;
  expect_same_when_shifted<3>(GapNewtonSolver<3>(np, MinimisationOptions{}.gap_tolerance), Kind::Capsule,
                              {Kind::Plane, Kind::Capsule, Kind::Capsule}, kTol, 9990);
}

// Two fixed capsules side by side and parallel (axes along x, touching), the mobile lying in
// their groove, nearly parallel to both (its axis and the second's 0 to 1e-3 rad off), and a third
// capsule across its end: the contact normals of the first two are nearly the same along most of
// the groove and the Newton matrix is nearly singular there. Every position returned touches all
// three bodies; the one in the groove is found.
TEST(GapNewtonSolver, NearlyParallelCapsules) {
  NarrowPhase<3> np;
  const GapNewtonSolver<3> solver(np, MinimisationOptions{}.gap_tolerance);
  const auto capsule = std::make_shared<SpherocylinderShape<3>>(1.0, 0.5);
  auto placed = [&](const Vec3& at, const Mat<3>& rotation) {
    Particle<3> p;
    p.shape = capsule;
    p.pose.position = at;
    p.pose.rotation = rotation;
    return p;
  };
  auto about = [](double angle, const Vec3& axis) -> Mat<3> { return Eigen::AngleAxisd(angle, axis).toRotationMatrix(); };
  const double h = std::sqrt(0.75);  // the groove's height: the mobile's axis 1 from both axes
  int found_in_groove = 0;
  for (const double tilt : {0.0, 1e-9, 1e-6, 1e-3}) {
    Problem<3> pb;
    pb.set_particle(0, placed(Vec3(0, 0, 0), Mat<3>::Identity()));
    pb.set_particle(1, placed(Vec3(0, 1, 0), about(tilt, Vec3::UnitZ())));
    pb.set_particle(2, placed(Vec3(1.7, 0.5, h), about(kPi / 2, Vec3::UnitZ())));  // across, its axis along y
    pb.mobile_shape = capsule;
    pb.mobile_rotation = about(tilt, Vec3::UnitY());
    std::array<Placement<3>, ContactSolver<3>::kMaxCandidates> out;
    const int n = solver.solve(pb.span(), pb.mobile(), out);
    const std::span<const Placement<3>> got(out.data(), static_cast<std::size_t>(n));
    EXPECT_TRUE(check_placements<3>(pb, got, kTol)) << "tilt " << tilt << pb.literal();
    found_in_groove += n > 0 && closest<3>(got, Vec3(-0.3, 0.5, h)).second < 1e-2;
  }
  std::printf("  nearly parallel capsules: the groove position found at %d of 4 tilts\n", found_in_groove);
  EXPECT_GE(found_in_groove, 3);
}

}  // namespace
}  // namespace fp::general_test
