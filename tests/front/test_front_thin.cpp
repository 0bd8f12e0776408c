// Containers barely wider than a particle. A monolayer cell (a slab 2.05 r_max thick),
// needles (cylinders 1.5 r_max in radius, along an axis and along a diagonal), a 2D strip, and a
// box far too large to be filled that is packed around its seed point. Each packing is checked by
// the independent brute-force code (front_test_util.hpp) and must actually fill the container:
// before the fix the slab and the needle received one sphere each.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "front_checks.hpp"

namespace fptest {
namespace {

template <int D>
fp::PackResult<D> pack_valid(const std::string& name, const std::string& yaml, const SignedDistance<D>& sd) {
  const fp::Scene scene = scene_from_yaml(yaml);
  fp::PackResult<D> res = fp::pack<D>(scene);
  SCOPED_TRACE(name + ": " + std::to_string(res.packing.size()) + " particles");
  expect_valid<D>(res.packing, sd, scene.radii->r_min(), scene.radii->r_max(), name);
  return res;
}

TEST(FrontThin, MonolayerSlab) {
  // 1 x 1 x 0.041 with radii in [0.01, 0.02]: one layer of spheres, each touching a plate.
  const auto res = pack_valid<3>("slab", R"(
dimension: 3
seed: 42
container: {type: box, min: [0, 0, 0], max: [1, 1, 0.041]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)", box_distance<3>(Vec3::Zero(), Vec3(1, 1, 0.041)));
  const fp::Packing<3>& P = res.packing;
  EXPECT_GT(P.size(), 1000u);
  EXPECT_GT(volume_fraction<3>(P, 0.041), 0.4);
  // Spread over the whole cell, not a cluster in its middle.
  double lo = 1, hi = 0;
  for (const Vec3& c : P.centers) lo = std::min(lo, c.x()), hi = std::max(hi, c.x());
  EXPECT_LT(lo, 0.05);
  EXPECT_GT(hi, 0.95);
}

TEST(FrontThin, NeedlesAlongAnAxisAndADiagonal) {
  for (const Vec3 axis : {Vec3(0, 0, 1), Vec3(1, 1, 1)}) {
    const std::string a = "[" + std::to_string(axis.x()) + ", " + std::to_string(axis.y()) + ", " + std::to_string(axis.z()) + "]";
    const auto res = pack_valid<3>("needle " + a, R"(
dimension: 3
seed: 42
container: {type: cylinder, base: [0, 0, 0], axis: )" + a + R"(, radius: 0.03, height: 2}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)", cylinder_distance(Vec3::Zero(), axis, 0.03, 2.0));
    const fp::Packing<3>& P = res.packing;
    EXPECT_GT(P.size(), 100u) << a;
    EXPECT_GT(res.counters.two_contact_placements, 0u) << a;
    // The chain runs the needle's length: positions along the axis from near one cap to the other.
    const Vec3 u = axis.normalized();
    double lo = 2, hi = 0;
    for (const Vec3& c : P.centers) {
      const double t = (c + P.origin).dot(u);
      lo = std::min(lo, t), hi = std::max(hi, t);
    }
    EXPECT_LT(lo, 0.1) << a;
    EXPECT_GT(hi, 1.9) << a;
    // Each particle touches the needle's wall or a neighbour (a chain, not scattered seeds).
    const std::vector<int> z = particle_contacts<3>(P, kOverlapTol);
    EXPECT_EQ(std::count(z.begin(), z.end(), 0), 0) << a;
  }
}

TEST(FrontThin, Strip2D) {
  const auto res = pack_valid<2>("strip", R"(
dimension: 2
seed: 42
container: {type: rectangle, min: [0, 0], max: [2, 0.041]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)", box_distance<2>(Vec2::Zero(), Vec2(2, 0.041)));
  EXPECT_GT(res.packing.size(), 60u);
  EXPECT_GT(volume_fraction<2>(res.packing, 2 * 0.041), 0.6);
}

TEST(FrontThin, BoxFarTooLargeIsPackedAroundItsSeed) {
  // 10^6 wide, radii 0.01: its centre frame would leave coordinates of 5e5 (spacing 6e-11, a
  // few 1e-9 r); framed at the seed point the contacts keep their tolerance.
  const auto res = pack_valid<3>("huge box", R"(
dimension: 3
seed: 42
container: {type: box, min: [0, 0, 0], max: [1000000, 1000000, 1000000]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
stop: {particles: 3000}
)", box_distance<3>(Vec3::Zero(), Vec3::Constant(1e6)));
  EXPECT_EQ(res.packing.size(), 3000u);
  EXPECT_EQ(res.stop, fp::StopReason::ParticleCount);
  EXPECT_GT(res.packing.origin.norm(), 1e5);  // the frame is at the seed (the centre), not at 0
  for (const Vec3& c : res.packing.centers) EXPECT_LT(c.norm(), 1.0);
}

}  // namespace
}  // namespace fptest
