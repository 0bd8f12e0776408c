// `target: {solid_fraction | porosity | void_ratio}` end to end: the container at the target
// (within 0.005, in fact half a sphere), the same in every cell away from the walls (sd <= 0.02
// over the analysis' cells of 8 mean diameters, 2 r_max inside), the radii passing their test, `frontpack validate` passing the
// output, byte-identical reruns, the three spellings one target, shifted and scaled scenes packing
// alike; a target above what the packer reaches is said with the value reached; bad keys exit 2
// and write nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli_test_util.hpp"

namespace fptest {
namespace {


std::string box_scene(const std::string& extra, double lo = 0.0, double side = 0.5, double r = 0.01) {
  auto num = [](double x) {
    char b[64];
    std::snprintf(b, sizeof b, "%.17g", x);
    return std::string(b);
  };
  return "dimension: 3\nseed: 2\ncontainer: {type: box, min: [" + num(lo) + ", " + num(lo) + ", " + num(lo) + "], max: [" +
         num(lo + side) + ", " + num(lo + side) + ", " + num(lo + side) + "]}\nparticles: {radius: {distribution: uniform, min: " +
         num(r) + ", max: " + num(2 * r) + "}}\n" + extra;
}

TEST(CliTarget, TheWholeContainerAtTheTargetInEveryCell) {
  TempDir dir;
  // A box of 30 mean diameters: 8 cells of 8 diameters 2 r_max from the walls. Its front packs 0.595.
  for (const double phi : {0.40, 0.50, 0.585}) {
    const std::string name = "t" + std::to_string(static_cast<int>(phi * 1000));
    write_bytes(dir.work() / (name + ".yaml"), box_scene("target: {solid_fraction: " + std::to_string(phi) + "}\n", 0.0, 0.9));
    const RunResult r = run_frontpack(dir, "pack " + name + ".yaml -o " + name + ".csv --record " + name + ".json");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;  // exit 0: the validation, the radii test included, passed
    EXPECT_NE(r.out.find("thinned to the target"), std::string::npos) << r.out;
    const std::string rec = read_bytes(dir.work() / (name + ".json"));
    EXPECT_NEAR(record_number(rec, "volume_fraction_container"), phi, 0.005) << phi;
    EXPECT_LE(record_number(rec, "volume_fraction_cells_std"), 0.02) << phi;
    EXPECT_GT(record_number(rec, "radii_pvalue"), 0.01) << phi;
    EXPECT_EQ(record_number(rec, "thinning_lost_every_contact"), 0.0) << "no sphere left floating at " << phi;
    // The independent check of the output file.
    const RunResult v = run_frontpack(dir, "validate " + name + ".csv --scene " + name + ".yaml");
    EXPECT_EQ(v.exit_code, 0) << v.out;
  }
  // Byte-identical reruns.
  ASSERT_EQ(run_frontpack(dir, "pack t400.yaml -o again.csv -q").exit_code, 0);
  EXPECT_EQ(read_bytes(dir.work() / "again.csv"), read_bytes(dir.work() / "t400.csv"));
}

TEST(CliTarget, PorosityAndVoidRatioAreTheSameTarget) {
  TempDir dir;
  write_bytes(dir.work() / "phi.yaml", box_scene("target: {solid_fraction: 0.4}\n", 0.0, 0.3));
  write_bytes(dir.work() / "n.yaml", box_scene("target: {porosity: 0.6}\n", 0.0, 0.3));
  write_bytes(dir.work() / "e.yaml", box_scene("target: {void_ratio: 1.5}\n", 0.0, 0.3));
  for (const char* s : {"phi", "n", "e"})
    ASSERT_EQ(run_frontpack(dir, std::string("pack ") + s + ".yaml -o " + s + ".csv -q").exit_code, 0) << s;
  EXPECT_EQ(read_bytes(dir.work() / "n.csv"), read_bytes(dir.work() / "phi.csv"));
  EXPECT_EQ(read_bytes(dir.work() / "e.csv"), read_bytes(dir.work() / "phi.csv"));
}

TEST(CliTarget, ShiftedAndScaledScenesReachItAlike) {
  TempDir dir;
  write_bytes(dir.work() / "plain.yaml", box_scene("target: {solid_fraction: 0.45}\n", 0.0, 0.3));
  write_bytes(dir.work() / "far.yaml", box_scene("target: {solid_fraction: 0.45}\n", 1e9, 0.3));
  write_bytes(dir.work() / "tiny.yaml", box_scene("target: {solid_fraction: 0.45}\n", 0.0, 0.3 * 0x1p-60, 0.01 * 0x1p-60));
  write_bytes(dir.work() / "huge.yaml", box_scene("target: {solid_fraction: 0.45}\n", 0.0, 0.3 * 0x1p60, 0.01 * 0x1p60));
  std::size_t plain = 0;
  for (const char* s : {"plain", "far", "tiny", "huge"}) {
    const RunResult r = run_frontpack(dir, std::string("pack ") + s + ".yaml -o " + s + ".csv --record " + s + ".json");
    ASSERT_EQ(r.exit_code, 0) << s << r.out << r.err;
    EXPECT_NEAR(record_number(read_bytes(dir.work() / (std::string(s) + ".json")), "volume_fraction_container"), 0.45, 0.005) << s;
    const std::size_t n = lines_of(read_bytes(dir.work() / (std::string(s) + ".csv"))).size();
    if (plain == 0) plain = n;
    if (std::string(s) == "far") EXPECT_NEAR(static_cast<double>(n), static_cast<double>(plain), 0.01 * plain) << s;
    else EXPECT_EQ(n, plain) << s << ": a power-of-two scale packs the same spheres";
  }
}

TEST(CliTarget, DisksAndACylinder) {
  TempDir dir;
  write_bytes(dir.work() / "disks.yaml",
              "dimension: 2\nseed: 3\ncontainer: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
              "particles: {radius: {distribution: uniform, min: 0.005, max: 0.01}}\ntarget: {solid_fraction: 0.6}\n");
  write_bytes(dir.work() / "cyl.yaml",
              "dimension: 3\nseed: 3\ncontainer: {type: cylinder, base: [0, 0, 0], axis: [0, 0, 1], radius: 0.3, height: 0.8}\n"
              "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\ntarget: {porosity: 0.5}\n");
  for (const auto& [s, phi] : {std::pair<const char*, double>{"disks", 0.6}, {"cyl", 0.5}}) {
    const RunResult r = run_frontpack(dir, std::string("pack ") + s + ".yaml -o " + s + ".csv --record " + s + ".json");
    ASSERT_EQ(r.exit_code, 0) << s << r.out << r.err;
    const std::string rec = read_bytes(dir.work() / (std::string(s) + ".json"));
    EXPECT_NEAR(record_number(rec, "volume_fraction_container"), phi, 0.005) << s;
    EXPECT_LE(record_number(rec, "volume_fraction_cells_std"), 0.02) << s;
    EXPECT_EQ(run_frontpack(dir, std::string("validate ") + s + ".csv --scene " + s + ".yaml").exit_code, 0) << s;
  }
}

TEST(CliTarget, ShapesToo) {
  // Hexagons and triangles (two templates): thinned by their own contacts (the narrow phase),
  // each template's share and sizes kept (the validation's size tests), the output valid.
  TempDir dir;
  write_bytes(dir.work() / "poly.yaml",
              "dimension: 2\nseed: 1\ncontainer: {type: rectangle, min: [0, 0], max: [40, 40]}\nparticles:\n"
              "  - {shape: polygon, sides: 6, size: {distribution: uniform, min: 0.5, max: 1}, fraction: 3}\n"
              "  - {shape: polygon, vertices: [[0, 0], [2, 0], [0, 1]], size: {distribution: uniform, min: 0.5, max: 1}, fraction: 1}\n"
              "target: {solid_fraction: 0.45}\n");
  const RunResult r = run_frontpack(dir, "pack poly.yaml -o poly.json --record rec.json");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("thinned to the target"), std::string::npos) << r.out;
  EXPECT_NEAR(record_number(read_bytes(dir.work() / "rec.json"), "volume_fraction_container"), 0.45, 0.005);
  EXPECT_EQ(run_frontpack(dir, "validate poly.json --scene poly.yaml").exit_code, 0);
  ASSERT_EQ(run_frontpack(dir, "pack poly.yaml -o again.json -q").exit_code, 0);
  // The same particles (the file's record holds timings, which differ).
  const std::string a = read_bytes(dir.work() / "again.json"), b = read_bytes(dir.work() / "poly.json");
  ASSERT_NE(b.find("\"particles\": ["), std::string::npos);
  EXPECT_EQ(a.substr(a.find("\"particles\": [")), b.substr(b.find("\"particles\": [")));
}

// A target above what the packer reaches is missed: the packing is valid but incomplete (exit 4),
// said in the summary, on stderr and in the record; new files are written, an old one is kept.
TEST(CliTarget, AboveWhatThePackerReachesIsSaid) {
  TempDir dir;
  write_bytes(dir.work() / "high.yaml", box_scene("target: {solid_fraction: 0.8}\n", 0.0, 0.3));
  write_bytes(dir.work() / "old.csv", "an earlier packing\n");
  const RunResult r = run_frontpack(dir, "pack high.yaml -o high.csv --record high.json");
  ASSERT_EQ(r.exit_code, kIncomplete) << r.err;
  EXPECT_NE(r.out.find("volume fraction 0.8 not reached: 0.5"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("INCOMPLETE     the target volume fraction 0.8 was not reached: 0.5"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("the packing is valid but incomplete: the target volume fraction 0.8 was not reached"),
            std::string::npos) << r.err;
  const std::string record = read_bytes(dir.work() / "high.json");
  EXPECT_NE(record.find("\"target_volume_fraction\": \"not reached\""), std::string::npos);
  EXPECT_NE(record.find("\"incomplete\": \"the target volume fraction 0.8 was not reached"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir.work() / "high.csv"));
  EXPECT_EQ(run_frontpack(dir, "pack high.yaml -o old.csv -q").exit_code, kIncomplete);
  EXPECT_EQ(read_bytes(dir.work() / "old.csv"), "an earlier packing\n");
}

TEST(CliTarget, BadTargetsAreRefusedAndWriteNothing) {
  TempDir dir;
  const std::pair<const char*, const char*> cases[] = {
      {"target: {solid_fraction: 0.4}\nstop: {volume_fraction: 0.4}\n", "give one of 'target'"},
      {"target: {}\n", "exactly one of solid_fraction"},
      {"target: {solid_fraction: 0.4, porosity: 0.6}\n", "exactly one of solid_fraction"},
      {"target: {void_ratio: -1}\n", "must be a positive number"},
      {"target: {porosity: 1.5}\n", "must be in (0, 1)"},
      {"target: {density: 0.5}\n", "density"},
      {"target: 0.5\n", "target"},
      // Targets no particle survives: refused with the key, not thinned down to a packing of none.
      {"target: {solid_fraction: 1e-9}\n", "key 'target': a solid fraction of 1e-09"},
      {"target: {void_ratio: 1e300}\n", "less than one particle"},
      {"target: {porosity: 0.9999999999}\n", "no particle would be kept"},
  };
  for (const auto& [extra, message] : cases) {
    write_bytes(dir.work() / "bad.yaml", box_scene(extra, 0.0, 0.2));
    const RunResult r = run_frontpack(dir, "pack bad.yaml -o out.csv");
    EXPECT_EQ(r.exit_code, 2) << extra;
    EXPECT_NE(r.err.find(message), std::string::npos) << extra << r.err;
    EXPECT_NE(r.err.find("bad.yaml:"), std::string::npos) << "the file and line are named: " << r.err;
    EXPECT_FALSE(fs::exists(dir.work() / "out.csv")) << extra;
  }
}

}  // namespace
}  // namespace fptest
