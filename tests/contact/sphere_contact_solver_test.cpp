// SphereContactSolver with particles only: seeded random configurations checked against an
// independent long-double trilateration (counts and positions), tangency of every returned
// position, and the known solution of configurations built around it, in every body order.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <iostream>

#include "contact_test_support.hpp"

namespace fp {
namespace {

using namespace contact_test;

void print(const char* what, const Tally& t) {
  std::cout << "[ stats    ] " << what << ": " << t.configs << " solves, " << t.solutions << " positions, "
            << t.compared << " counts compared, " << t.found << "/" << t.well_conditioned
            << " known solutions found, worst |gap| = " << t.worst_gap << " x tolerance\n";
}

TEST(SphereContactSolver3D, ThreeTangentSpheresGiveTheKnownSolutionInEveryOrder) {
  Tally t;
  run_constructed<3>({BodyKind::Particle, BodyKind::Particle, BodyKind::Particle}, 10000, 101, Ranges{}, t);
  print("3 spheres, constructed", t);
  EXPECT_GT(t.well_conditioned, t.configs * 8 / 10);  // the check of x ran on most configurations
  EXPECT_GT(t.compared, t.configs * 8 / 10);
  EXPECT_LE(t.worst_gap, 1.0);
}

TEST(SphereContactSolver2D, TwoTangentDisksGiveTheKnownSolutionInEveryOrder) {
  Tally t;
  run_constructed<2>({BodyKind::Particle, BodyKind::Particle}, 20000, 102, Ranges{}, t);
  print("2 disks, constructed", t);
  EXPECT_GT(t.well_conditioned, t.configs * 8 / 10);
  EXPECT_GT(t.compared, t.configs * 8 / 10);
}

/// Fully random centres and radii: about half the configurations have no solution.
template <int D>
void run_random_particles(int trials, std::uint64_t seed, double box, int& with, int& without, Tally& t) {
  Rng rng(seed);
  const SphereContactSolver<D> solver;
  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> out;
  for (int trial = 0; trial < trials; ++trial) {
    std::array<Body<D>, D> f;
    for (auto& b : f) {
      Vec<D> c;
      for (int a = 0; a < D; ++a) c[a] = rng.uniform(-box, box);
      b = Body<D>::sphere(c, log_uniform(rng, 0.2, 3.0));
    }
    const double r = log_uniform(rng, 0.2, 3.0);
    const std::span<const Body<D>> fs(f.data(), D);
    const int n = solver.solve(fs, Mobile<D>{r}, out);
    const std::span<const Placement<D>> sol(out.data(), n);
    ++t.configs;
    t.solutions += n;
    ASSERT_TRUE(check_tangent<D>(fs, r, sol));
    const Reference<D> ref = reference_solutions<D>(fs, r);
    ASSERT_TRUE(ref.supported);
    if (!ref.ambiguous) {
      ++t.compared;
      // Away from degeneracies the answer is exactly two positions or none.
      ASSERT_TRUE(n == 0 || n == 2) << config_literal<D>(fs, r);
      (n == 2 ? with : without) += 1;
    }
    ASSERT_TRUE(check_against_reference<D>(fs, r, sol, 1e-6 * r));
  }
}

TEST(SphereContactSolver3D, RandomThreeSpheresMatchLongDoubleTrilateration) {
  Tally t;
  int with = 0, without = 0;
  run_random_particles<3>(100000, 103, 2.0, with, without, t);
  print("3 spheres, random", t);
  std::cout << "[ stats    ] " << with << " with 2 solutions, " << without << " with none\n";
  EXPECT_GT(with, t.configs / 5);
  EXPECT_GT(without, t.configs / 5);
}

TEST(SphereContactSolver2D, RandomTwoDisksMatchCircleIntersection) {
  Tally t;
  int with = 0, without = 0;
  run_random_particles<2>(100000, 104, 3.0, with, without, t);
  print("2 disks, random", t);
  std::cout << "[ stats    ] " << with << " with 2 solutions, " << without << " with none\n";
  EXPECT_GT(with, t.configs / 5);
  EXPECT_GT(without, t.configs / 5);
}

TEST(SphereContactSolver3D, MutuallyTangentUnitSpheresHaveTheTetrahedronApexes) {
  // Three unit spheres at the corners of an equilateral triangle of side 2: a unit mobile sits
  // at the apexes of the regular tetrahedron, height 2 sqrt(2/3) above/below the centroid.
  const double h = std::sqrt(3.0);
  const std::array<Body<3>, 3> f = {Body<3>::sphere(Vec3(-1, 0, 0), 1), Body<3>::sphere(Vec3(1, 0, 0), 1),
                                    Body<3>::sphere(Vec3(0, h, 0), 1)};
  std::array<Placement<3>, 4> out;
  const int n = SphereContactSolver<3>{}.solve(f, Mobile<3>{1.0}, out);
  ASSERT_EQ(n, 2);
  const Vec3 centroid(0, h / 3, 0);
  const double z = 2 * std::sqrt(2.0 / 3.0);
  const double zmax = std::max(out[0].position.z(), out[1].position.z());
  const double zmin = std::min(out[0].position.z(), out[1].position.z());
  EXPECT_NEAR(zmax, z, 1e-14);
  EXPECT_NEAR(zmin, -z, 1e-14);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR((out[k].position - centroid).head<2>().norm(), 0.0, 1e-14);
}

TEST(SphereContactSolver, RejectsMalformedCallsAndHonoursTheOutputSize) {
  const SphereContactSolver<3> solver;
  const ContactSolver<3>& iface = solver;  // the same answers through the interface
  const std::array<Body<3>, 3> f = {Body<3>::sphere(Vec3(-1, 0, 0), 1), Body<3>::sphere(Vec3(1, 0, 0), 1),
                                    Body<3>::sphere(Vec3(0, 1.5, 0), 1)};
  std::array<Placement<3>, 4> out;
  EXPECT_EQ(iface.solve(f, Mobile<3>{1.0}, out), 2);
  EXPECT_EQ(solver.solve(std::span<const Body<3>>(f.data(), 2), Mobile<3>{1.0}, out), 0);  // needs D bodies
  EXPECT_EQ(solver.solve(f, Mobile<3>{0.0}, out), 0);
  EXPECT_EQ(solver.solve(f, Mobile<3>{-1.0}, out), 0);
  EXPECT_EQ(solver.solve(f, Mobile<3>{std::nan("")}, out), 0);
  // Room for one: one position, and it is a verified one.
  EXPECT_EQ(solver.solve(f, Mobile<3>{1.0}, std::span<Placement<3>>(out.data(), 1)), 1);
  EXPECT_TRUE(check_tangent<3>(f, 1.0, std::span<const Placement<3>>(out.data(), 1)));
}

TEST(ConfigLiteral, PrintsAPasteableConfigurationWithRoundTripDigits) {
  std::deque<Wall<3>> walls = {Wall<3>::plane(Vec3(0.1, 0, 0), Vec3(1, 0, 0))};
  const std::array<Body<3>, 3> f = {Body<3>::sphere(Vec3(1.0 / 3.0, 2, 3), 0.1), Body<3>::of_wall(walls[0]),
                                    Body<3>::sphere(Vec3(-1, 1e6, 1e-300), 2.5)};
  const std::string s = config_literal<3>(std::span<const Body<3>>(f.data(), 3), 0.7);
  EXPECT_NE(s.find("fp::Wall<3>::plane(fp::Vec3(0.10000000000000001, 0, 0), fp::Vec3(1, 0, 0))"), std::string::npos) << s;
  EXPECT_NE(s.find("fp::Body<3>::sphere(fp::Vec3(0.33333333333333331, 2, 3), 0.10000000000000001)"), std::string::npos) << s;
  EXPECT_NE(s.find("fp::Body<3>::of_wall(walls[0])"), std::string::npos) << s;
  EXPECT_NE(s.find("fp::Vec3(-1, 1000000, 1e-300)"), std::string::npos) << s;
  EXPECT_NE(s.find("const double r = 0.69999999999999996;"), std::string::npos) << s;
  EXPECT_NE(s.find("check_solve<3>(fixed, r)"), std::string::npos) << s;
  // %.17g round-trips every double exactly.
  EXPECT_EQ(std::strtod(num(1.0 / 3.0).c_str(), nullptr), 1.0 / 3.0);
  EXPECT_EQ(std::strtod(num(0.1 + 0.2).c_str(), nullptr), 0.1 + 0.2);
}

TEST(ConfigLiteral, PastedLiteralReplays) {
  // What config_literal prints for a plane + two spheres, pasted verbatim.
  const std::vector<fp::Wall<3>> walls = {
      fp::Wall<3>::plane(fp::Vec3(0, 0, 0), fp::Vec3(0, 0, 1))};
  const std::array<fp::Body<3>, 3> fixed = {
      fp::Body<3>::of_wall(walls[0]),
      fp::Body<3>::sphere(fp::Vec3(0, 0, 1), 1),
      fp::Body<3>::sphere(fp::Vec3(2, 0, 1), 1)};
  const double r = 1;
  EXPECT_TRUE(fp::contact_test::check_solve<3>(fixed, r));
  std::array<Placement<3>, 4> out;
  ASSERT_EQ(SphereContactSolver<3>{}.solve(fixed, Mobile<3>{r}, out), 2);  // (1, +-sqrt(3), 1)
  EXPECT_NEAR(std::abs(out[0].position.y()), std::sqrt(3.0), 1e-14);
}

}  // namespace
}  // namespace fp
