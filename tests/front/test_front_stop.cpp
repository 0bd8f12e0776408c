// Stop criteria: a particle count is met exactly, a volume fraction stops at the first particle
// that reaches it, a time limit stops a long run early. Every stopped packing is still valid.
#include <gtest/gtest.h>

#include <chrono>

#include "front_checks.hpp"

namespace fptest {
namespace {

const char* kBox3D = R"(
dimension: 3
seed: 5
container: {type: box, min: [0, 0, 0], max: [0.4, 0.4, 0.4]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";
const char* kRect2D = R"(
dimension: 2
seed: 5
container: {type: rectangle, min: [0, 0], max: [1.2, 1.2]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";

template <int D>
void expect_exact_count(const std::string& base, std::uint64_t n) {
  SCOPED_TRACE(std::to_string(D) + "D, particles: " + std::to_string(n));
  const fp::Scene scene = scene_from_yaml(base + "stop: {particles: " + std::to_string(n) + "}\n");
  const auto res = fp::pack<D>(scene);
  EXPECT_EQ(res.packing.size(), n);
  EXPECT_EQ(res.stop, fp::StopReason::ParticleCount);
  if constexpr (D == 3) expect_valid<3>(res.packing, box_distance<3>(Vec3::Zero(), Vec3::Constant(0.4)), 0.01, 0.02, "box");
  else expect_valid<2>(res.packing, box_distance<2>(Vec2::Zero(), Vec2::Constant(1.2)), 0.01, 0.02, "rectangle");
}

TEST(FrontStop, ParticleCountIsExact3D) {
  for (std::uint64_t n : {4, 100, 1234}) expect_exact_count<3>(kBox3D, n);
}
TEST(FrontStop, ParticleCountIsExact2D) {
  for (std::uint64_t n : {3, 100, 1234}) expect_exact_count<2>(kRect2D, n);
}
// Fewer particles than the initial cluster (D mutually tangent particles).
TEST(FrontStop, ParticleCountBelowTheInitialCluster) {
  for (std::uint64_t n : {1, 2}) expect_exact_count<3>(kBox3D, n);
  expect_exact_count<2>(kRect2D, 1);
}

/// Stops at the first particle whose addition reaches phi: the packing without its last
/// particle is below phi, with it at or above. Sums in placement order, like a user would.
template <int D>
void expect_stops_at_fraction(const std::string& base, double measure, double phi) {
  SCOPED_TRACE(std::to_string(D) + "D, volume_fraction: " + std::to_string(phi));
  std::ostringstream s;
  s.precision(17);
  s << base << "stop: {volume_fraction: " << phi << "}\n";
  const auto res = fp::pack<D>(scene_from_yaml(s.str()));
  const auto& P = res.packing;
  ASSERT_GE(P.size(), 1u);
  EXPECT_EQ(res.stop, fp::StopReason::VolumeFraction);
  double before = 0;
  for (std::size_t i = 0; i + 1 < P.size(); ++i) before += fp::ball_measure<D>(P.radii[i]);
  const double all = before + fp::ball_measure<D>(P.radii.back());
  EXPECT_LT(before, phi * measure) << "did not stop at the first particle reaching phi (" << P.size() << " particles)";
  EXPECT_GE(all, phi * measure);
}

TEST(FrontStop, VolumeFractionStopsAtTheFirstParticleReachingIt) {
  for (double phi : {0.05, 0.3, 0.5}) expect_stops_at_fraction<3>(kBox3D, 0.064, phi);
  for (double phi : {0.05, 0.4, 0.7}) expect_stops_at_fraction<2>(kRect2D, 1.44, phi);
}

TEST(FrontStop, VolumeFractionReachedByTheInitialCluster) {
  // One particle of the box already holds > 0.1 % of its volume.
  expect_stops_at_fraction<3>(kBox3D, 0.064, 0.0005);
  expect_stops_at_fraction<2>(kRect2D, 1.44, 0.0002);
}

TEST(FrontStop, VolumeFractionNeverReachedEndsWithTheFront) {
  const auto res = fp::pack<3>(scene_from_yaml(std::string(kBox3D) + "stop: {volume_fraction: 0.9}\n"));
  EXPECT_EQ(res.stop, fp::StopReason::FrontExhausted);
}

TEST(FrontStop, TimeLimitStopsEarly) {
  // The 1,000,000-sphere scene would take seconds; 0.2 s must stop it long before.
  const fp::Scene scene = fp::load_scene(std::string(FRONTPACK_SOURCE_DIR) + "/scenes/million.yaml");
  fp::Scene limited = scene;
  limited.stop.time_limit_seconds = 0.2;
  const auto t0 = std::chrono::steady_clock::now();
  const auto res = fp::pack<3>(limited);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(res.stop, fp::StopReason::TimeLimit);
  EXPECT_GE(res.seconds, 0.2);
  EXPECT_LT(wall, 1.5);
  EXPECT_GT(res.packing.size(), 100u);
  EXPECT_LT(res.packing.size(), 1000000u);
  const auto ov = overlaps<3>(res.packing);
  EXPECT_LE(ov.max_over_rmin, kOverlapTol);
}

}  // namespace
}  // namespace fptest
