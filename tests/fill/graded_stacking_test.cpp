// Graded large-first stacking (fill/graded_stacking.hpp, paper 003), checked by the independent
// code of tests/front: no overlap beyond 1e-9 r_min, every sphere inside, the list placed in full
// below the law's reach and the radii then its own; both orders, 2D and 3D, a cylinder; the same
// seed the same bytes; a scene shifted by 1e9 or scaled by 2^+-60 placing the same spheres.
#include "fill/graded_stacking.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/geometry/box_container.hpp"
#include "core/geometry/cylinder_container.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "tests/front/front_checks.hpp"

namespace fp {
namespace {

using fptest::box_distance;
using fptest::expect_valid;

template <int D>
std::vector<double> list_for(double phi, double measure, double r_min, double r_max, std::uint64_t seed) {
  Rng rng(seed);
  return radii_for_measure<D>(UniformRadius(r_min, r_max), phi * measure, rng);
}

TEST(GradedStacking, TheListOfATargetIsLargestFirstAndWithinHalfAParticle) {
  const std::vector<double> radii = list_for<3>(0.5, 1.0, 0.01, 0.02, 3);
  ASSERT_GT(radii.size(), 1000u);
  EXPECT_TRUE(std::is_sorted(radii.begin(), radii.end(), std::greater<>()));
  double sum = 0;
  for (const double r : radii) sum += ball_measure<3>(r);
  EXPECT_LE(std::abs(sum - 0.5), ball_measure<3>(0.02) / 2);
}

template <int D>
void check_box(double phi, bool contacts_first, const std::string& what) {
  const BoxContainer<D> box(Vec<D>::Zero(), Vec<D>::Constant(D == 3 ? 0.5 : 1.5));
  std::vector<double> radii = list_for<D>(phi, box.measure(), 0.01, 0.02, 5);
  StackingOptions o;
  o.contacts_first = contacts_first;
  Packing<D> p;
  const StackingReport rep = stack_graded<D>(box, radii, o, 7, 1e-9, p);
  EXPECT_EQ(rep.asked, radii.size()) << what;
  EXPECT_EQ(rep.placed, p.size()) << what;
  EXPECT_EQ(rep.unplaced, 0u) << what << ": the whole list goes in below the law's reach";
  EXPECT_EQ(rep.by_random + rep.by_near + rep.by_two_contact + rep.by_three_contact, rep.placed) << what;
  expect_valid<D>(p, box_distance<D>(Vec<D>::Zero(), Vec<D>::Constant(D == 3 ? 0.5 : 1.5)), 0.01, 0.02, what);
  // The radii placed are the list's (as a multiset).
  std::vector<double> placed = p.radii;
  std::sort(placed.begin(), placed.end(), std::greater<>());
  EXPECT_EQ(placed, radii) << what;
  // The same seed, the same packing; another seed, another.
  Packing<D> again, other;
  stack_graded<D>(box, radii, o, 7, 1e-9, again);
  EXPECT_EQ(again.centers, p.centers) << what;
  stack_graded<D>(box, radii, o, 8, 1e-9, other);
  EXPECT_NE(other.centers, p.centers) << what;
}

TEST(GradedStacking, PlacesTheWholeListValidly) {
  check_box<3>(0.45, false, "3D, paper's order, 0.45");
  check_box<3>(0.45, true, "3D, contacts first, 0.45");
  check_box<2>(0.70, false, "2D, paper's order, 0.70");
  check_box<2>(0.60, true, "2D, contacts first, 0.60");  // grown clusters leave pockets: 4 of 0.70 stay out
}

TEST(GradedStacking, ReshapesAndLeavesWhatFitsNowhereStillValid) {
  // Above what the law reaches (0.70 for U[r, 2r] in 3D): reshape passes run, the rest is left
  // out and said; every sphere placed is still valid, moved ones included.
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(0.4));
  const std::vector<double> radii = list_for<3>(0.70, box.measure(), 0.01, 0.02, 9);
  Packing<3> p;
  const StackingReport rep = stack_graded<3>(box, radii, StackingOptions{}, 2, 1e-9, p);
  EXPECT_GT(rep.unplaced, 0u);
  EXPECT_EQ(rep.placed + rep.unplaced, rep.asked);
  EXPECT_EQ(rep.reshape_passes, 8u);
  EXPECT_GT(rep.reshape_moves, 0u);
  EXPECT_NEAR(rep.solid_placed, [&] {
    double s = 0;
    for (const double r : p.radii) s += ball_measure<3>(r);
    return s;
  }(), 1e-12);
  expect_valid<3>(p, box_distance<3>(Vec3::Zero(), Vec3::Constant(0.4)), 0.01, 0.02, "dense box");
}

TEST(GradedStacking, ACylinderWithItsCurvedWall) {
  const CylinderContainer c(Vec3::Zero(), Vec3(0, 0, 1), 0.25, 0.5);
  const std::vector<double> radii = list_for<3>(0.5, c.measure(), 0.01, 0.02, 4);
  Packing<3> p;
  const StackingReport rep = stack_graded<3>(c, radii, StackingOptions{}, 3, 1e-9, p);
  EXPECT_EQ(rep.unplaced, 0u);
  expect_valid<3>(p, fptest::cylinder_distance(Vec3::Zero(), Vec3(0, 0, 1), 0.25, 0.5), 0.01, 0.02, "cylinder");
}

TEST(GradedStacking, ShiftedAndScaledScenesPlaceTheSameSpheres) {
  const std::vector<double> radii = list_for<3>(0.5, 0.3 * 0.3 * 0.3, 0.01, 0.02, 6);
  Packing<3> plain;
  stack_graded<3>(BoxContainer<3>(Vec3::Zero(), Vec3::Constant(0.3)), radii, StackingOptions{}, 1, 1e-9, plain);
  // Shifted by 1e9: the container's frame keeps the local coordinates.
  Packing<3> far;
  far.origin = Vec3::Constant(1e9);
  stack_graded<3>(BoxContainer<3>::from_local(Vec3::Zero(), Vec3::Constant(0.3), far.origin), radii, StackingOptions{}, 1,
                  1e-9, far);
  EXPECT_EQ(far.centers, plain.centers);
  for (const double s : {0x1p-60, 0x1p60}) {
    std::vector<double> scaled = radii;
    for (double& r : scaled) r *= s;
    Packing<3> q;
    stack_graded<3>(BoxContainer<3>(Vec3::Zero(), Vec3::Constant(0.3 * s)), scaled, StackingOptions{}, 1, 1e-9, q);
    ASSERT_EQ(q.size(), plain.size()) << s;
    for (std::size_t i = 0; i < q.size(); ++i) ASSERT_EQ(q.centers[i], plain.centers[i] * s) << s << " sphere " << i;
  }
}

}  // namespace
}  // namespace fp
