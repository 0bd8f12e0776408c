// `stop: {particles: N, scale_sizes: true}`: N spheres (disks) that fill the container, the radius
// law scaled with its shape kept (cli/scaled_sizes.hpp). Judged from the outside: exactly N
// particles, the independent validation of the file against the scene file alone (the size test
// fits the scale from the radii), a container solid fraction within 0.01 of the full packing's at
// the same scale (a scene with the scaled law written out and no stop), the same seed giving the
// same bytes, and the same verdict for the scene scaled by 2^40 and shifted by 1e9.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <tuple>

#include "cli/scaled_sizes.hpp"
#include "cli_test_util.hpp"

namespace fptest {
namespace {

std::string number(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

struct Case {
  const char* name;
  int dimension;
  std::string container;    // L: the length unit, O: the offset, both substituted
  double r_min, r_max;      // the law's range, before L
  int n;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

/// The scene text: `container(L, O)`, uniform radii [r_min, r_max] L, and the stop.
std::string scene_of(const Case& c, double unit, double offset, const std::string& stop) {
  std::string container = c.container;
  for (std::size_t at; (at = container.find('L')) != std::string::npos;) container.replace(at, 1, number(unit));
  for (std::size_t at; (at = container.find('O')) != std::string::npos;) container.replace(at, 1, number(offset));
  return "dimension: " + std::to_string(c.dimension) + "\nseed: 3\ncontainer: " + container +
         "\nparticles: {radius: {distribution: uniform, min: " + number(c.r_min * unit) + ", max: " + number(c.r_max * unit) +
         "}}\n" + stop + "\n";
}

const Case kCases[] = {
    {"cylinder", 3, "{type: cylinder, base: [O, O, O], axis: [0, 0, 1], radius: L, height: L}", 0.01, 0.02, 3000},
    {"disk", 2, "{type: disk, center: [O, O], radius: L}", 0.01, 0.03, 2000},
};

class CliScaleSizes : public ::testing::TestWithParam<Case> {};

TEST_P(CliScaleSizes, NParticlesFillTheContainer) {
  const Case& c = GetParam();
  TempDir dir;
  const std::string stop = "stop: {particles: " + std::to_string(c.n) + ", scale_sizes: true}";
  write_bytes(dir.work() / "s.yaml", scene_of(c, 1.0, 0.0, stop));
  const RunResult r = run_frontpack(dir, "pack s.yaml -o p.csv --record r.json");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("scaled sizes   radii x "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("INCOMPLETE"), std::string::npos) << r.out;
  EXPECT_EQ(lines_of(read_bytes(dir.work() / "p.csv")).size(), static_cast<std::size_t>(c.n) + 1);
  const std::string record = read_bytes(dir.work() / "r.json");
  const double scale = record_number(record, "size_scale"), phi = record_number(record, "volume_fraction_container");
  const double full = record_number(record, "size_scale_full_count");
  EXPECT_GE(full, c.n);
  EXPECT_LE(full, 1.01 * c.n);
  EXPECT_NEAR(record_number(record, "size_scale_fitted") / scale, 1.0, 0.02);

  // The file alone, against the scene file: valid, its radii the law's shape.
  const RunResult v = run_frontpack(dir, "validate p.csv --scene s.yaml");
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  const RunResult a = run_frontpack(dir, "analyze p.csv --scene s.yaml");  // the same law as validate's
  EXPECT_EQ(a.exit_code, 0) << a.err;
  EXPECT_NE(a.out.find(", scaled by "), std::string::npos) << a.out;
  EXPECT_NE(a.out.find("validate: OK"), std::string::npos) << a.out;

  // The full packing at that scale: the law written out, no stop.
  const Case scaled{c.name, c.dimension, c.container, c.r_min * scale, c.r_max * scale, 0};
  write_bytes(dir.work() / "full.yaml", scene_of(scaled, 1.0, 0.0, ""));
  ASSERT_EQ(run_frontpack(dir, "pack full.yaml -q -o full.csv --record full.json").exit_code, 0);
  EXPECT_NEAR(phi, record_number(read_bytes(dir.work() / "full.json"), "volume_fraction_container"), 0.01);

  // The same seed, the same bytes.
  ASSERT_EQ(run_frontpack(dir, "pack s.yaml -q -o again.csv").exit_code, 0);
  EXPECT_EQ(read_bytes(dir.work() / "again.csv"), read_bytes(dir.work() / "p.csv"));

  // Scaled by 2^40 and shifted by 1e9: N particles, valid, as dense.
  write_bytes(dir.work() / "far.yaml", scene_of(c, 0x1p40, 1e9, stop));
  const RunResult far = run_frontpack(dir, "pack far.yaml -q -o far.csv --record far.json");
  ASSERT_EQ(far.exit_code, 0) << far.out << far.err;
  EXPECT_EQ(lines_of(read_bytes(dir.work() / "far.csv")).size(), static_cast<std::size_t>(c.n) + 1);
  EXPECT_NEAR(record_number(read_bytes(dir.work() / "far.json"), "volume_fraction_container"), phi, 0.01);
  EXPECT_EQ(run_frontpack(dir, "validate far.csv --scene far.yaml -q").exit_code, 0);
}

INSTANTIATE_TEST_SUITE_P(Containers, CliScaleSizes, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// One sphere in a ball: the container one particle thick. Found at once, complete.
TEST(CliScaleSizesExtremes, OneParticleFillsItsContainer) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", "dimension: 3\nseed: 1\ncontainer: {type: sphere, center: [0, 0, 0], radius: 1}\n"
                                     "particles: {radius: {distribution: constant, value: 0.1}}\n"
                                     "stop: {particles: 1, scale_sizes: true}\n");
  const RunResult r = run_frontpack(dir, "pack s.yaml -o p.csv");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(lines_of(read_bytes(dir.work() / "p.csv")).size(), 2u);
  EXPECT_EQ(run_frontpack(dir, "validate p.csv --scene s.yaml -q").exit_code, 0);
}

// The verdict: a scale whose full packing holds N to N (1 + kScaleSlack) is complete; trials that
// end outside that band leave the packing incomplete, with the best scale's figures.
TEST(CliScaleSizesVerdict, OutsideTheBandIsIncomplete) {
  fp::SizeScaling s;
  s.asked = 100, s.scale = 1.25, s.trials = fp::kMaxScaleTrials;
  for (const auto [full, placed, complete] : {std::tuple<std::uint64_t, std::size_t, bool>{100, 100, true},
                                              {101, 100, true},
                                              {102, 100, false},
                                              {99, 99, false}}) {
    s.full_count = full;
    fp::PackCheck c;
    fp::add_size_scaling_lines(c, s, placed, 0.5, 1.24);
    EXPECT_EQ(c.complete(), complete) << full;
    EXPECT_NE(c.summary_lines.find("scaled sizes   radii x 1.25"), std::string::npos) << c.summary_lines;
    if (!complete) {
      ASSERT_EQ(c.cut_short.size(), 1u);
      EXPECT_NE(c.cut_short[0].find("found no scale at which 100 particles fill the container within 1 %"), std::string::npos)
          << c.cut_short[0];
      EXPECT_NE(c.cut_short[0].find("the front places " + std::to_string(full) + " when it runs empty"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace fptest
