// Scale extremes: a wide size ratio (the hierarchical grid), coordinates far from the origin,
// and micrometre radii. The tolerances stay relative: overlap <= 1e-9 r_min, inside to 1e-9 r.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/metrics/radii_fit.hpp"
#include "core/metrics/validate.hpp"
#include "front_checks.hpp"

namespace fptest {
namespace {

template <int D>
void pack_valid(const std::string& name, const std::string& yaml, const SignedDistance<D>& sd, std::size_t min_n,
                bool expect_wall_contacts = true) {
  const fp::Scene scene = scene_from_yaml(yaml);
  const auto res = fp::pack<D>(scene);
  SCOPED_TRACE(name + ": " + std::to_string(res.packing.size()) + " particles");
  EXPECT_GE(res.packing.size(), min_n);
  const Validity v = expect_valid<D>(res.packing, sd, scene.radii->r_min(), scene.radii->r_max(), name);
  if (expect_wall_contacts) EXPECT_GT(v.containment.touching_walls, 0u);
  // Contacts are still exact to the relative tolerance: most particles touch three (two) others.
  const std::vector<int> z = particle_contacts<D>(res.packing, kOverlapTol);
  std::size_t connected = 0;
  for (int k : z) connected += k >= D ? 1 : 0;
  EXPECT_GT(static_cast<double>(connected), 0.8 * static_cast<double>(z.size()));
}

TEST(FrontExtremes, SizeRatio50In3D) {
  // Lognormal over [0.002, 0.1]: the hierarchical grid, neighbour sets of hundreds.
  pack_valid<3>("ratio 50, 3D", R"(
dimension: 3
seed: 43
container: {type: box, min: [0, 0, 0], max: [0.5, 0.5, 0.5]}
particles: {radius: {distribution: lognormal, median: 0.01, sigma: 0.8, min: 0.002, max: 0.1}}
stop: {particles: 4000}
)", box_distance<3>(Vec3::Zero(), Vec3::Constant(0.5)), 300, false);
}

TEST(FrontExtremes, SizeRatio50In2D) {
  // Mostly small disks with a few up to 50 times larger.
  pack_valid<2>("ratio 50, 2D", R"(
dimension: 2
seed: 42
container: {type: disk, center: [0, 0], radius: 0.6}
particles: {radius: {distribution: histogram, edges: [0.002, 0.01, 0.1], weights: [100, 1]}}
packer: {radius_pool: 4}
)", ball_distance<2>(Vec2::Zero(), 0.6), 2000, false);
}

TEST(FrontExtremes, WideBimodalMixPacksAndKeepsItsDistribution) {
  // 99 % radii near 0.01 and 1 % near 0.1 (by count; the large ones hold 88 % of the volume).
  // Each try of a large radius next to small particles has a V of hundreds; its pair scan is
  // capped (front/advancing_front.hpp), which is what lets the run end. The placed radii must
  // still follow the requested law (the validator's radii test) and the particles be valid.
  const fp::Scene scene = scene_from_yaml(R"(
dimension: 3
seed: 42
container: {type: box, min: [0, 0, 0], max: [0.6, 0.6, 0.6]}
particles: {radius: {distribution: histogram, edges: [0.01, 0.011, 0.09, 0.1], weights: [99, 0, 1]}}
)");
  const auto res = fp::pack<3>(scene);
  SCOPED_TRACE(std::to_string(res.packing.size()) + " particles");
  EXPECT_EQ(res.stop, fp::StopReason::FrontExhausted);
  EXPECT_GT(res.counters.contact_bodies_capped, 0u);
  EXPECT_EQ(res.counters.radii_on_skeleton, 0u);  // the large ones hold under 90 % of the volume
  expect_valid<3>(res.packing, box_distance<3>(Vec3::Zero(), Vec3::Constant(0.6)), 0.01, 0.1, "99:1 mix");
  std::size_t large = 0;
  for (const double r : res.packing.radii) large += r > 0.05 ? 1 : 0;
  EXPECT_GT(large, 10u);  // the large mode is placed, not left waiting in the pool
  EXPECT_GT(volume_fraction<3>(res.packing, 0.216), 0.6);
  const fp::ValidationReport v = fp::validate_packing<3>(res.packing, *scene.container3, scene.radii.get(), 1e-9);
  EXPECT_TRUE(v.ok) << v.summary();
}

/// Per grain of radius above `threshold`, the fines touching it (each counted once), and the
/// fines touching none: checked apart from the packer, on centres and radii alone.
std::pair<std::vector<int>, std::size_t> fines_per_grain(const fp::Packing<3>& P, double threshold) {
  std::vector<std::size_t> grains, fines;
  for (std::size_t i = 0; i < P.size(); ++i) (P.radii[i] > threshold ? grains : fines).push_back(i);
  std::vector<int> per_grain(grains.size(), 0);
  std::size_t loose = 0;
  for (const std::size_t f : fines) {
    bool touching = false;
    for (std::size_t g = 0; g < grains.size() && !touching; ++g) {
      const double d = (P.centers[f] - P.centers[grains[g]]).norm(), sum = P.radii[f] + P.radii[grains[g]];
      if (std::abs(d - sum) <= 1e-9 * P.radii[f] + 4e-16 * sum) touching = true, ++per_grain[g];
    }
    loose += touching ? 0 : 1;
  }
  return {per_grain, loose};
}

TEST(FrontExtremes, GravelHoldingNearlyAllTheVolumeIsASkeletonWithTheSandSpreadOnIt) {
  // Radii 0.001 and 0.1 at 1000 : 1: the gravel holds 99.9 % of the volume. Grown together from
  // the seed point, the sand filled the box first (a box of 0.6 ran 27 s to 0.311 with 16 gravel
  // grains of 23.6 expected; a box of 0.3 was left at 0.001 with no gravel). The gravel is now the
  // skeleton, packed first; each grain of sand is put on a skeleton grain picked at random. Every
  // grain of sand touches one, the counts of both classes are a sample of the law (drawn in its
  // order up to the draft after the skeleton's last), and the sand is spread over the grains as
  // evenly as a random pick spreads it (binomial standard deviation).
  const fp::Scene scene = scene_from_yaml(R"(
dimension: 3
seed: 42
container: {type: box, min: [0, 0, 0], max: [0.6, 0.6, 0.6]}
particles: {radius: {distribution: discrete, values: [[0.001, 1000], [0.1, 1]]}}
)");
  const auto res = fp::pack<3>(scene);
  SCOPED_TRACE(std::to_string(res.packing.size()) + " particles");
  EXPECT_EQ(res.stop, fp::StopReason::FrontExhausted);
  expect_valid<3>(res.packing, box_distance<3>(Vec3::Zero(), Vec3::Constant(0.6)), 0.001, 0.1, "skeleton and sand");
  const auto [per_grain, loose] = fines_per_grain(res.packing, 0.05);
  ASSERT_GE(per_grain.size(), 14u);  // a box 3 grain diameters wide: 16 with this seed
  EXPECT_EQ(loose, 0u);
  std::size_t fines = 0;
  for (const int k : per_grain) fines += static_cast<std::size_t>(k);
  EXPECT_EQ(res.counters.radii_on_skeleton, fines);
  EXPECT_EQ(fines + per_grain.size(), res.packing.size());
  EXPECT_EQ(res.counters.radii_drawn, res.packing.size() + res.counters.radii_unplaced);
  EXPECT_EQ(res.counters.radii_never_fit, 0u);
  EXPECT_GE(fp::radii_fit(res.packing.radii, *scene.radii).p, 0.001);
  const double mean = double(fines) / double(per_grain.size());
  double var = 0;
  for (const int k : per_grain) var += (k - mean) * (k - mean);
  const double sd = std::sqrt(var / double(per_grain.size() - 1));
  const double binomial = std::sqrt(double(fines) / double(per_grain.size()) * (1 - 1.0 / double(per_grain.size())));
  EXPECT_LT(sd, 2 * binomial) << "mean " << mean;
  EXPECT_GT(*std::min_element(per_grain.begin(), per_grain.end()), mean / 2);
  const fp::ValidationReport v = fp::validate_packing<3>(res.packing, *scene.container3, scene.radii.get(), 1e-9);
  EXPECT_TRUE(v.ok) << v.summary();
  // The box one grain wide holds one grain and its sand (before: no grain, 3,489 grains of sand).
  const fp::Scene narrow = scene_from_yaml(R"(
dimension: 3
seed: 42
container: {type: box, min: [0, 0, 0], max: [0.3, 0.3, 0.3]}
particles: {radius: {distribution: discrete, values: [[0.001, 1000], [0.1, 1]]}}
)");
  const auto one = fp::pack<3>(narrow);
  const auto [one_grain, one_loose] = fines_per_grain(one.packing, 0.05);
  ASSERT_EQ(one_grain.size(), 1u);
  EXPECT_EQ(one_loose, 0u);
  EXPECT_GT(one_grain[0], 500);
  // In 2D a disk's rim takes about 240 grains of sand at this ratio, not a thousand: the front
  // grows the sand with the gravel there, as before.
  const fp::Scene flat = scene_from_yaml(R"(
dimension: 2
seed: 42
container: {type: rectangle, min: [0, 0], max: [0.6, 0.6]}
particles: {radius: {distribution: discrete, values: [[0.001, 1000], [0.1, 1]]}}
stop: {particles: 3000}
)");
  EXPECT_EQ(fp::pack<2>(flat).counters.radii_on_skeleton, 0u);
}

TEST(FrontExtremes, RareLargeClassInABoxTooSmallForItIsListedAsLeftOut) {
  // Sand with a grain of gravel per thousand: radii 0.01 and 0.1 at 1000 : 1 in a box 2.5 gravel
  // diameters wide, where gravel centres fit only in the middle 0.3 of it. The gravel is placed
  // ahead of the front while it has room; the box fills (sand alone reaches 0.554 in it), and the
  // gravel left out is listed (the command line's verdict: incomplete, exit 4, when the placed
  // radii fail the size test).
  const fp::Scene scene = scene_from_yaml(R"(
dimension: 3
seed: 42
container: {type: box, min: [0, 0, 0], max: [0.5, 0.5, 0.5]}
particles: {radius: {distribution: discrete, values: [[0.01, 1000], [0.1, 1]]}}
)");
  const auto res = fp::pack<3>(scene);
  SCOPED_TRACE(std::to_string(res.packing.size()) + " particles");
  EXPECT_EQ(res.stop, fp::StopReason::FrontExhausted);
  expect_valid<3>(res.packing, box_distance<3>(Vec3::Zero(), Vec3::Constant(0.5)), 0.01, 0.1, "rare large class");
  EXPECT_GT(volume_fraction<3>(res.packing, 0.125), 0.58);
  std::size_t large = 0;
  for (const double r : res.packing.radii) large += r > 0.05 ? 1 : 0;
  EXPECT_GE(large, 1u);
  EXPECT_EQ(res.counters.radii_placed_ahead, large);  // every large one is placed ahead
  // What never fitted is counted and listed, gravel only, and the pool left little.
  ASSERT_EQ(res.never_fit_radii.size(), res.counters.radii_never_fit);
  for (const double r : res.never_fit_radii) EXPECT_EQ(r, 0.1);
  EXPECT_EQ(res.counters.radii_unplaced - res.counters.radii_never_fit, 4u);  // the pool of 4
  EXPECT_EQ(res.counters.radii_drawn, res.packing.size() + res.counters.radii_unplaced);
  // With the gravel that found no room the sizes follow the law: nothing else was left out.
  std::vector<double> all = res.packing.radii;
  all.insert(all.end(), res.never_fit_radii.begin(), res.never_fit_radii.end());
  EXPECT_GE(fp::radii_fit(all, *scene.radii).p, 0.001);
}

TEST(FrontExtremes, RareLargeClassFillsABoxFiveLargeDiametersWide) {
  // The same law in a box 5 gravel diameters wide, 78 % of it within a gravel diameter of a wall.
  // Placed in their turn, 62 of 104 gravel grains found no room once the sand had reached the
  // walls (container fraction 0.631). Placed ahead of the front at the rate the box closes to
  // them, every one fits, the counts follow the law, the box is denser than sand alone (0.573),
  // and the gravel centres are spread over the whole room they have: each coordinate uniform on
  // [0.1, 0.9] (Kolmogorov-Smirnov, sqrt(n) D below 1.95: p > 0.001).
  const fp::Scene scene = scene_from_yaml(R"(
dimension: 3
seed: 7
container: {type: box, min: [0, 0, 0], max: [1, 1, 1]}
particles: {radius: {distribution: discrete, values: [[0.01, 1000], [0.1, 1]]}}
)");
  const auto res = fp::pack<3>(scene);
  SCOPED_TRACE(std::to_string(res.packing.size()) + " particles");
  EXPECT_EQ(res.stop, fp::StopReason::FrontExhausted);
  expect_valid<3>(res.packing, box_distance<3>(Vec3::Zero(), Vec3::Constant(1.0)), 0.01, 0.1, "gravel in a box of 1");
  EXPECT_GE(fp::radii_fit(res.packing.radii, *scene.radii).p, 0.001);
  EXPECT_GT(volume_fraction<3>(res.packing, 1.0), 0.65);
  std::vector<Vec3> gravel;
  for (std::size_t i = 0; i < res.packing.size(); ++i)
    if (res.packing.radii[i] > 0.05) gravel.push_back(res.packing.centers[i]);
  ASSERT_GE(gravel.size(), 50u);
  // The gravel is placed at the rate the box closes to it, not in the law's own turns: when the
  // law happens to draw more of it than that (99 against 84 expected, this seed), the excess
  // drawn after the box has closed finds no room and is listed. Placed in their turn, 62 of 104.
  EXPECT_LE(res.counters.radii_never_fit, gravel.size() / 3);
  EXPECT_EQ(res.counters.radii_placed_ahead, gravel.size());
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> u;
    for (const Vec3& c : gravel) u.push_back((c[axis] - 0.1) / 0.8);
    std::sort(u.begin(), u.end());
    double d = 0;
    for (std::size_t i = 0; i < u.size(); ++i)
      d = std::max({d, double(i + 1) / u.size() - u[i], u[i] - double(i) / u.size()});
    EXPECT_LT(d * std::sqrt(double(u.size())), 1.95) << "axis " << axis;
  }
}

TEST(FrontExtremes, CoordinatesOffsetByOneMillion3D) {
  // 1e6 has an ulp of 1.2e-10: radii of order 1 keep 1e-9 relative resolution.
  const double o = 1e6;
  pack_valid<3>("offset 1e6, 3D", R"(
dimension: 3
seed: 44
container: {type: box, min: [1000000, 1000000, 1000000], max: [1000025, 1000025, 1000025]}
particles: {radius: {distribution: uniform, min: 1, max: 2}}
)", box_distance<3>(Vec3::Constant(o), Vec3::Constant(o + 25)), 400);
}

TEST(FrontExtremes, CoordinatesOffsetByOneMillionSphere3D) {
  pack_valid<3>("offset 1e6 sphere", R"(
dimension: 3
seed: 45
container: {type: sphere, center: [-1000000, 1000000, 1000000], radius: 14}
particles: {radius: {distribution: uniform, min: 1, max: 2}}
)", ball_distance<3>(Vec3(-1e6, 1e6, 1e6), 14), 300);
}

TEST(FrontExtremes, CoordinatesOffsetByOneMillion2D) {
  pack_valid<2>("offset 1e6, 2D", R"(
dimension: 2
seed: 46
container: {type: rectangle, min: [1000000, -1000000], max: [1000080, -999920]}
particles: {radius: {distribution: uniform, min: 1, max: 2}}
)", box_distance<2>(Vec2(1e6, -1e6), Vec2(1e6 + 80, -1e6 + 80)), 500);
}

TEST(FrontExtremes, MicrometreRadii3D) {
  pack_valid<3>("radii 1e-6, 3D", R"(
dimension: 3
seed: 47
container: {type: box, min: [0, 0, 0], max: [5.0e-5, 5.0e-5, 5.0e-5]}
particles: {radius: {distribution: uniform, min: 1.0e-6, max: 2.0e-6}}
)", box_distance<3>(Vec3::Zero(), Vec3::Constant(5e-5)), 3000);
}

TEST(FrontExtremes, MicrometreRadiiCylinder3D) {
  pack_valid<3>("radii 1e-6, cylinder", R"(
dimension: 3
seed: 48
container: {type: cylinder, base: [1.0e-5, 0, 0], axis: [1, 1, 0], radius: 2.0e-5, height: 4.0e-5}
particles: {radius: {distribution: uniform, min: 1.0e-6, max: 2.0e-6}}
)", cylinder_distance(Vec3(1e-5, 0, 0), Vec3(1, 1, 0), 2e-5, 4e-5), 1000);
}

TEST(FrontExtremes, MicrometreRadii2D) {
  pack_valid<2>("radii 1e-6, 2D", R"(
dimension: 2
seed: 49
container: {type: polygon, vertices: [[0, 0], [1.0e-4, 0], [1.0e-4, 5.0e-5], [5.0e-5, 5.0e-5], [5.0e-5, 1.0e-4], [0, 1.0e-4]]}
particles: {radius: {distribution: uniform, min: 1.0e-6, max: 2.0e-6}}
)", polygon_distance({{0, 0}, {1e-4, 0}, {1e-4, 5e-5}, {5e-5, 5e-5}, {5e-5, 1e-4}, {0, 1e-4}}), 500);
}

}  // namespace
}  // namespace fptest
