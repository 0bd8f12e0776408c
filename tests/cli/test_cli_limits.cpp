// Limits checked before any work (core/io/scene_limits.hpp, the length rule of the scene
// parser): a scene that would exhaust the particle ids or the memory, a pool too large for its
// particle count, or lengths whose volumes are no ordinary doubles is refused with exit 2 at the
// key to change, in under 2 s, with nothing written. And the scenes the rule lets through pack
// and pass their validation.
#include <gtest/gtest.h>

#include <chrono>

#include <string>

#include "cli_test_util.hpp"
#include "refusal_check.hpp"

namespace fptest {
namespace {

std::string box_scene(const std::string& side, const std::string& radii = "{distribution: uniform, min: 0.01, max: 0.02}") {
  return "dimension: 3\n"
         "container: {type: box, min: [0, 0, 0], max: [" + side + ", " + side + ", " + side + "]}\n"
         "particles: {radius: " + radii + "}\n";
}

/// A folder holding `s.yaml` with `text` and an existing output that must stay untouched.
auto scene(const std::string& text) {
  return [=](const fs::path& w) {
    write_bytes(w / "s.yaml", text);
    write_bytes(w / "old.csv", "an existing output, not to be touched\n");
  };
}

// A few more than 2 GB at 200 bytes per sphere: 0.74 x 216 / (4/3 pi E[r^3]) = 1.0e7 spheres.
const std::string kTwoGigabytes = box_scene("6");
const std::string kOneGigabyteAddressSpace = "ulimit -v 1000000";

// AddressSanitizer reserves about 16 TB of address space for its shadow at start, so a program
// built with it cannot start under any ulimit -v (scripts/sanitize.sh runs these tests too).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif
#define SKIP_UNDER_ADDRESS_SANITIZER()                                                             \
  if (kAddressSanitizer) GTEST_SKIP() << "ulimit -v cannot start a program built with AddressSanitizer"

TEST(CliLimits, ContainerOfTenToTheElevenSpheresWithoutAStop) {
  expect_refused(scene(box_scene("100")), "pack s.yaml -o old.csv", 2,
                 {"s.yaml:2:", "key 'container'", "4.71e+10 particles", "32-bit ids", "stop: {particles: N}"});
}

TEST(CliLimits, MoreMemoryThanTheProcessMayUse) {
  SKIP_UNDER_ADDRESS_SANITIZER();
  expect_refused(scene(kTwoGigabytes), "pack s.yaml -o old.csv", 2,
                 {"s.yaml:2:", "key 'container'", "200 bytes per particle", "ulimit -v", "particles fit"}, kOneGigabyteAddressSpace);
}

TEST(CliLimits, TheSameSceneWithAStopCountPacksUnderTheSameLimit) {
  SKIP_UNDER_ADDRESS_SANITIZER();
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", kTwoGigabytes + "stop: {particles: 500}\n");
  const RunResult r = run_frontpack(dir, "pack s.yaml -o out.csv", kOneGigabyteAddressSpace);
  EXPECT_EQ(r.exit_code, kIncomplete) << r.err;  // the count stop leaves the container unfilled
  EXPECT_NE(r.out.find("validation     ok"), std::string::npos) << r.out;
  EXPECT_EQ(lines_of(read_bytes(dir.work() / "out.csv")).size(), 501u);  // header + 500 particles
}

TEST(CliLimits, StopCountBeyondThirtyTwoBitIds) {
  expect_refused(scene(box_scene("100") + "stop: {particles: 3000000000}\n"), "pack s.yaml -o old.csv", 2,
                 {"s.yaml:4:", "key 'stop.particles'", "32-bit ids", "lower it"});
}

TEST(CliLimits, VolumeFractionThatNeedsTooMuchMemory) {
  SKIP_UNDER_ADDRESS_SANITIZER();
  expect_refused(scene(kTwoGigabytes + "stop:\n  volume_fraction: 0.5\n"), "pack s.yaml -o old.csv", 2,
                 {"s.yaml:5:", "key 'stop.volume_fraction'", "ulimit -v"}, kOneGigabyteAddressSpace);
}

TEST(CliLimits, ATimeLimitDoesNotBoundTheCount) {
  expect_refused(scene(box_scene("100") + "stop: {time: 10}\n"), "pack s.yaml -o old.csv", 2,
                 {"key 'container'", "a time limit does not bound the count"});
}

TEST(CliLimits, NonSphericalParticlesAreCountedByTheirOwnVolume) {
  const std::string capsules =
      "dimension: 3\n"
      "container: {type: box, min: [0, 0, 0], max: [1000, 1000, 1000]}\n"
      "particles:\n  - {shape: spherocylinder, aspect_ratio: 0.5, size: {distribution: uniform, min: 0.1, max: 0.2}}\n";
  expect_refused(scene(capsules), "pack s.yaml -o old.csv", 2, {"s.yaml:2:", "key 'container'", "32-bit ids"});
}

TEST(CliLimits, ContainerExtentBeyondTenToTheHundred) {
  expect_refused(scene(box_scene("1e300")), "pack s.yaml -o old.csv", 2,
                 {"s.yaml:2:", "key 'container'", "(1e+300) is outside [1e-100, 1e+100]", "other units"});
}

TEST(CliLimits, ContainerExtentThatOverflows) {
  const std::string text = "dimension: 3\n"
                           "container: {type: box, min: [-1e308, -1e308, -1e308], max: [1e308, 1e308, 1e308]}\n"
                           "particles: {radius: {distribution: uniform, min: 1e306, max: 2e306}}\n";
  expect_refused(scene(text), "pack s.yaml -o old.csv", 2, {"s.yaml:2:", "key 'container'", "(inf) is outside"});
}

TEST(CliLimits, ContainerTooSmallForOrdinaryVolumes) {
  expect_refused(scene(box_scene("2e-150", "{distribution: uniform, min: 1e-152, max: 2e-152}")), "pack s.yaml -o old.csv", 2,
                 {"s.yaml:2:", "key 'container'", "(2e-150) is outside", "volumes (its cube)"});
}

TEST(CliLimits, ParticlesTooSmallForOrdinaryVolumes) {
  expect_refused(scene(box_scene("1", "{distribution: constant, value: 1e-120}")), "pack s.yaml -o old.csv", 2,
                 {"s.yaml:3:", "key 'particles'", "smallest particle size (1e-120)"});
}

TEST(CliLimits, RectangleBeyondTenToTheHundredSpeaksOfAreas) {
  const std::string text = "dimension: 2\n"
                           "container: {type: rectangle, min: [0, 0], max: [1e101, 1]}\n"
                           "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n";
  expect_refused(scene(text), "pack s.yaml -o old.csv", 2, {"key 'container'", "areas (its square)"});
}

TEST(CliLimits, PoolBeyondItsMaximum) {
  expect_refused(scene(box_scene("0.2") + "packer: {radius_pool: 1025}\n"), "pack s.yaml -o old.csv", 2,
                 {"s.yaml:4:", "key 'packer.radius_pool'", "from 1 to 1024"});
}

TEST(CliLimits, PoolTooLargeForTheParticlesTheContainerHolds) {
  // 0.2 cube: about 377 spheres at most; the 64 radii left in the pool would fail the radii test.
  expect_refused(scene(box_scene("0.2") + "packer: {radius_pool: 64}\n"), "pack s.yaml -o old.csv", 2,
                 {"s.yaml:4:", "key 'packer.radius_pool'", "377 particles", "radii test"});
}

/// Packs `text` with a few seeds: each run must exit `code` (0; 4 when a stop leaves the
/// container unfilled) with its validation ok.
void expect_packs_and_validates(const std::string& text, int code = 0) {
  for (const char* seed : {"1", "2", "3"}) {
    TempDir dir;
    write_bytes(dir.work() / "s.yaml", text);
    const RunResult r = run_frontpack(dir, std::string("pack s.yaml -o out.csv --seed ") + seed);
    EXPECT_EQ(r.exit_code, code) << "seed " << seed << ": " << r.err;
    EXPECT_NE(r.out.find("validation     ok"), std::string::npos) << "seed " << seed << ": " << r.out;
  }
}

TEST(CliLimits, APoolTheRuleAcceptsPassesTheValidation) { expect_packs_and_validates(box_scene("0.2") + "packer: {radius_pool: 16}\n"); }

TEST(CliLimits, TheDefaultPoolInAContainerOfAFewParticles) { expect_packs_and_validates(box_scene("0.06")); }

TEST(CliLimits, AHugeContainerWithAStopCountPacks) {
  expect_packs_and_validates(box_scene("1e17") + "stop: {particles: 2000}\n", kIncomplete);
}

/// A cluster template of n members spread at random (fixed seed) over a cube of side 2.
std::string cluster_scene(int n, const std::string& stop) {
  std::string centers, radii;
  std::uint64_t x = 12345;
  auto next = [&] {  // a small LCG: the scene is the same on every machine
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(x >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < n; ++i) {
    centers += std::string(i ? ", " : "") + "[" + std::to_string(2 * next() - 1) + ", " + std::to_string(2 * next() - 1) + ", " +
               std::to_string(2 * next() - 1) + "]";
    radii += std::string(i ? ", " : "") + std::to_string(0.2 + 0.2 * next());
  }
  return "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [6, 6, 6]}\nstop: " + stop +
         "\nparticles:\n  - shape: cluster\n    centers: [" + centers + "]\n    radii: [" + radii +
         "]\n    size: {distribution: uniform, min: 0.5, max: 1}\n";
}

TEST(CliLimits, ClusterMembersAreLimited) {
  expect_refused(scene(cluster_scene(201, "{time: 1}")), "pack s.yaml -o old.csv", 2,
                 {"key 'particles[0].centers'", "at most 200 members (got 201)"});
}

// Each pick of clusters of 20 members takes seconds of contact problems: the time stop is
// checked before every solve, not only between picks (a 20 s stop once ended at 98 s).
TEST(CliLimits, ATimeStopEndsAPickOfLargeClusters) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", cluster_scene(20, "{time: 1}"));
  const auto t0 = std::chrono::steady_clock::now();
  const RunResult r = run_frontpack(dir, "pack s.yaml -o p.csv --record r.json");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(r.exit_code, kIncomplete) << r.err;
  EXPECT_NE(r.out.find("time limit"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("the time limit (stop.time: 1 s) ended the packing before it filled the container"), std::string::npos)
      << r.err;
  EXPECT_LT(record_number(read_bytes(dir.work() / "r.json"), "pack"), 1.5) << "the pack phase (timings.pack) overran the 1 s stop";
  EXPECT_LT(seconds, 20.0);  // the whole process: the scene's check, the validation, the writing
}

// Shapes the container cannot hold are the scene's mistake: exit 2 at the scene's particles.
TEST(CliLimits, ShapesTooBigForTheBoxAreBadInput) {
  const std::string box = "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\nparticles:\n";
  expect_refused(scene(box + "  - {shape: polyhedron, preset: cube, size: {distribution: uniform, min: 2, max: 3}}\n"),
                 "pack s.yaml -o old.csv", 2, {"s.yaml:4:3: key 'particles'", "cannot hold a first particle"});
  // A flat tetrahedron sized on its inscribed radius is huge: the same refusal, with the key.
  expect_refused(scene(box + "  - {shape: polyhedron, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1e-9]], "
                             "size_on: inscribed_radius, size: {distribution: uniform, min: 0.3, max: 0.5}}\n"),
                 "pack s.yaml -o old.csv", 2, {"key 'particles'", "cannot hold a first particle"});
}

// The graded stacking's list is checked against the container before it is made.
TEST(CliLimits, AStackingListBeyondTheContainerIsRefused) {
  const std::string stacking = box_scene("0.1") + "packer: {method: stacking}\nstop: {particles: ";
  expect_refused(scene(stacking + "100000}\n"), "pack s.yaml -o old.csv", 2,
                 {"key 'stop.particles'", "the graded stacking places a list of 1e+05 particles, more than the container can hold"});
  expect_refused(scene(stacking + "3000000000}\n"), "pack s.yaml -o old.csv", 2, {"key 'stop.particles'", "graded stacking"});
}

}  // namespace
}  // namespace fptest
