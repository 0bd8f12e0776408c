// Same scene and seed => the same packing, bit for bit; another seed => another packing.
#include <gtest/gtest.h>

#include "front_checks.hpp"

namespace fptest {
namespace {

template <int D>
void expect_deterministic(const std::string& yaml) {
  fp::Scene scene = scene_from_yaml(yaml);
  const auto a = fp::pack<D>(scene).packing;
  const auto b = fp::pack<D>(scene_from_yaml(yaml)).packing;  // a fresh parse: nothing cached
  ASSERT_GT(a.size(), 100u);
  EXPECT_TRUE(bitwise_equal<D>(a, b)) << "two runs with seed " << scene.seed << " differ";

  scene.seed += 1;
  const auto c = fp::pack<D>(scene).packing;
  EXPECT_FALSE(bitwise_equal<D>(a, c)) << "seeds " << scene.seed - 1 << " and " << scene.seed << " give the same packing";
  // Not just a different length: the first radii differ (they are drawn from the seed).
  EXPECT_NE(a.radii[0], c.radii[0]);
}

TEST(FrontDeterminism, Box3DDefaults) {
  expect_deterministic<3>(R"(
dimension: 3
seed: 12345678901234
container: {type: box, min: [0, 0, 0], max: [0.3, 0.3, 0.3]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)");
}

TEST(FrontDeterminism, CylinderRandomFrontWithPool) {
  // front: random draws from the same generator as the radii.
  expect_deterministic<3>(R"(
dimension: 3
seed: 77
container: {type: cylinder, base: [0, 0, 0], axis: [0, 1, 1], radius: 0.12, height: 0.3}
particles: {radius: {distribution: lognormal, median: 0.012, sigma: 0.3, min: 0.006, max: 0.03}}
packer: {front: random, candidate: first, radius_pool: 4}
)");
}

TEST(FrontDeterminism, MeshFifo) {
  expect_deterministic<3>(R"(
dimension: 3
seed: 3
container: {type: mesh, file: l_prism.off}
particles: {radius: {distribution: uniform, min: 0.012, max: 0.02}}
packer: {front: fifo, pair_order: index}
)");
}

TEST(FrontDeterminism, PolygonRandom2D) {
  expect_deterministic<2>(R"(
dimension: 2
seed: 18446744073709551615
container: {type: polygon, vertices: [[0, 0], [1, 0], [1, 0.5], [0.5, 0.5], [0.5, 1], [0, 1]]}
particles: {radius: {distribution: histogram, edges: [0.005, 0.01, 0.02], weights: [2, 1]}}
packer: {front: random, radius_pool: 4}
)");
}

TEST(FrontDeterminism, Disk2DGradation) {
  expect_deterministic<2>(R"(
dimension: 2
seed: 0
container: {type: disk, center: [0, 0], radius: 0.5}
particles: {radius: {distribution: gradation, curve: [[0.02, 0], [0.04, 50], [0.06, 100]]}}
)");
}

}  // namespace
}  // namespace fptest
