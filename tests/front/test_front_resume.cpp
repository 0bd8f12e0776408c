// When the front runs empty while the container still has room, growth resumes in the voids
// (AdvancingFront::resume_at_voids): a wide size distribution whose early front used to die
// (r_max/r_min = 50, seeds found by experiment) and a container whose second chamber no particle
// can reach through the neck both end up filled, and stay valid.
#include <gtest/gtest.h>

#include "front_checks.hpp"

namespace fptest {
namespace {

class Ratio50Seeds : public ::testing::TestWithParam<int> {};

TEST_P(Ratio50Seeds, FillsTheBox) {
  // Before voids were resumed, seeds 3 and 8 stopped at 59 and 48 particles in this box.
  const fp::Scene scene = scene_from_yaml("dimension: 3\nseed: " + std::to_string(GetParam()) + R"(
container: {type: box, min: [0, 0, 0], max: [1, 1, 1]}
particles: {radius: {distribution: uniform, min: 0.001, max: 0.05}}
)");
  const auto res = fp::pack<3>(scene);
  EXPECT_EQ(res.stop, fp::StopReason::FrontExhausted);
  expect_valid<3>(res.packing, box_distance<3>(Vec3::Zero(), Vec3::Ones()), 0.001, 0.05, "ratio 50");
  EXPECT_GT(volume_fraction<3>(res.packing, 1.0), 0.5) << res.packing.size() << " particles";
}

INSTANTIATE_TEST_SUITE_P(EarlyDeaths, Ratio50Seeds, ::testing::Values(3, 8, 9, 11, 12));

TEST(FrontResume, SecondChamberBehindANarrowNeckIsFilled) {
  // Two 0.5 x 0.5 rooms joined by a corridor 0.015 wide: no disk (r >= 0.01) passes, so growth
  // from the first room never reaches the second; a void there restarts it.
  const std::vector<Vec2> V = {{0, 0},     {0.5, 0},     {0.5, 0.2425}, {0.6, 0.2425}, {0.6, 0},   {1.1, 0},
                               {1.1, 0.5}, {0.6, 0.5},   {0.6, 0.2575}, {0.5, 0.2575}, {0.5, 0.5}, {0, 0.5}};
  std::string yaml = "dimension: 2\nseed: 5\ncontainer:\n  type: polygon\n  vertices: [";
  for (std::size_t k = 0; k < V.size(); ++k)
    yaml += (k ? ", [" : "[") + std::to_string(V[k].x()) + ", " + std::to_string(V[k].y()) + "]";
  yaml += "]\nparticles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\npacker: {seed_point: [0.25, 0.25]}\n";
  const auto res = fp::pack<2>(scene_from_yaml(yaml));
  expect_valid<2>(res.packing, polygon_distance(V), 0.01, 0.02, "two rooms");
  double area[2] = {0, 0};
  for (std::size_t i = 0; i < res.packing.size(); ++i)
    area[res.packing.centers[i].x() > 0.55 ? 1 : 0] += fp::kPi * res.packing.radii[i] * res.packing.radii[i];
  EXPECT_GT(area[0] / 0.25, 0.7);
  EXPECT_GT(area[1] / 0.25, 0.7) << "the second room was not filled";
  EXPECT_GE(res.counters.voids_seeded, 1u);
}

}  // namespace
}  // namespace fptest
