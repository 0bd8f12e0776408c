// Every combination of the packer's levers (front pick, candidate choice, pair order, walls as
// bodies, radius pool, contact bodies) still gives a valid packing: no overlap, every particle
// inside, the front run to exhaustion. 96 combinations, in a 3D box and a non-convex 2D polygon.
#include <gtest/gtest.h>

#include "front_checks.hpp"

namespace fptest {
namespace {

using Options = std::tuple<std::string, std::string, std::string, bool, int, std::string>;

std::string packer_yaml(const Options& o) {
  const auto& [front, candidate, pair_order, walls, pool, bodies] = o;
  return "packer: {front: " + front + ", candidate: " + candidate + ", pair_order: " + pair_order +
         ", walls: " + (walls ? "true" : "false") + ", radius_pool: " + std::to_string(pool) +
         ", contact_bodies: " + bodies + "}\n";
}

class FrontOptions : public ::testing::TestWithParam<Options> {};

TEST_P(FrontOptions, Box3DStaysValid) {
  const fp::Scene scene = scene_from_yaml(R"(
dimension: 3
seed: 31
container: {type: box, min: [0, 0, 0], max: [0.25, 0.2, 0.3]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)" + packer_yaml(GetParam()));
  const auto res = fp::pack<3>(scene);
  EXPECT_EQ(res.stop, fp::StopReason::FrontExhausted);
  EXPECT_GT(res.packing.size(), 300u);
  const Validity v = expect_valid<3>(res.packing, box_distance<3>(Vec3::Zero(), Vec3(0.25, 0.2, 0.3)), 0.01, 0.02,
                                     packer_yaml(GetParam()));
  if (std::get<3>(GetParam())) EXPECT_GT(v.containment.touching_walls, 0u);
  // Without wall bodies a particle touches a wall only by accident of its tangent positions.
  EXPECT_GT(volume_fraction<3>(res.packing, 0.25 * 0.2 * 0.3), 0.4);
}

TEST_P(FrontOptions, NonConvexPolygon2DStaysValid) {
  const std::vector<Vec2> U = {{0, 0}, {0.9, 0}, {0.9, 0.8}, {0.6, 0.8}, {0.6, 0.3}, {0.3, 0.3}, {0.3, 0.8}, {0, 0.8}};
  const fp::Scene scene = scene_from_yaml(R"(
dimension: 2
seed: 32
container: {type: polygon, vertices: [[0, 0], [0.9, 0], [0.9, 0.8], [0.6, 0.8], [0.6, 0.3], [0.3, 0.3], [0.3, 0.8], [0, 0.8]]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)" + packer_yaml(GetParam()));
  const auto res = fp::pack<2>(scene);
  EXPECT_EQ(res.stop, fp::StopReason::FrontExhausted);
  EXPECT_GT(res.packing.size(), 300u);
  expect_valid<2>(res.packing, polygon_distance(U), 0.01, 0.02, packer_yaml(GetParam()));
  EXPECT_GT(volume_fraction<2>(res.packing, 0.9 * 0.8 - 0.3 * 0.5), 0.6);
}

// The smallest-radius probe (on by default for narrow distributions) drops s0 after one failed
// scan; it must not cost density where it is on, and must not be on where it would (ratio 50).
TEST(FrontProbe, CostsNoDensityOnANarrowDistribution) {
  const std::string base = R"(dimension: 3
seed: 8
container: {type: box, min: [0, 0, 0], max: [0.4, 0.4, 0.4]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";
  const auto on = fp::pack<3>(scene_from_yaml(base + "packer: {probe_smallest: true}\n"));
  const auto off = fp::pack<3>(scene_from_yaml(base + "packer: {probe_smallest: false}\n"));
  const auto deflt = fp::pack<3>(scene_from_yaml(base));
  EXPECT_TRUE(bitwise_equal<3>(deflt.packing, on.packing)) << "auto must be on for r_max / r_min = 2";
  expect_valid<3>(on.packing, box_distance<3>(Vec3::Zero(), Vec3::Constant(0.4)), 0.01, 0.02, "probe on");
  EXPECT_NEAR(volume_fraction<3>(on.packing, 0.064), volume_fraction<3>(off.packing, 0.064), 0.005);
  EXPECT_LT(on.counters.solves, off.counters.solves);
}

TEST(FrontProbe, AutoIsOffForWideDistributions) {
  const std::string base = R"(dimension: 3
seed: 1
container: {type: box, min: [0, 0, 0], max: [1, 1, 1]}
particles: {radius: {distribution: uniform, min: 0.001, max: 0.05}}
)";
  const auto deflt = fp::pack<3>(scene_from_yaml(base));
  const auto off = fp::pack<3>(scene_from_yaml(base + "packer: {probe_smallest: false}\n"));
  EXPECT_TRUE(bitwise_equal<3>(deflt.packing, off.packing));
}

INSTANTIATE_TEST_SUITE_P(AllCombinations, FrontOptions,
                         ::testing::Combine(::testing::Values(std::string("closest"), std::string("random"), std::string("fifo")),
                                            ::testing::Values(std::string("closest"), std::string("first")),
                                            ::testing::Values(std::string("nearest"), std::string("index")), ::testing::Bool(),
                                            ::testing::Values(1, 4), ::testing::Values(std::string("front"), std::string("all"))),
                         [](const auto& info) {
                           const Options& o = info.param;
                           return "front_" + std::get<0>(o) + "_cand_" + std::get<1>(o) + "_pairs_" + std::get<2>(o) +
                                  (std::get<3>(o) ? "_walls" : "_nowalls") + "_pool" + std::to_string(std::get<4>(o)) + "_bodies_" +
                                  std::get<5>(o);
                         });

}  // namespace
}  // namespace fptest
