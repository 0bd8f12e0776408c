// `frontpack densify PACKING --scene SCENE -o OUT` and the scene key `densify:` after `pack`: the
// filled packing passes `frontpack validate` (every pair, the container, the radii), holds every
// sphere of the input unchanged, and is the same whichever way it was made; the summary and the
// run record say what was added and how the radii compare with the law. Bad input (a missing
// file, a scene of shapes, an unknown or out-of-range densify key, an output that would replace
// the input) exits 2 and writes nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_test_util.hpp"

namespace fptest {
namespace {

const char* kScene = R"(dimension: 3
seed: 4
container: {type: box, min: [0, 0, 0], max: [0.3, 0.3, 0.3]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.05}}
)";

class CliDensify : public ::testing::Test {
 protected:
  void SetUp() override {
    write_bytes(dir.work() / "s.yaml", kScene);
    write_bytes(dir.work() / "fit.yaml", std::string(kScene) + "densify: {radii: fit}\n");
    const RunResult r = run_frontpack(dir, "pack s.yaml -o p.csv -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  TempDir dir;
};

TEST_F(CliDensify, FillsAPackingFileWhichThenValidates) {
  const RunResult r = run_frontpack(dir, "densify p.csv --scene fit.yaml -o d.csv --record rec.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("void filling   +"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stop: given; void filling: no void fits a sphere"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("radii test"), std::string::npos) << "the radii's distance to the law is reported";
  const auto before = lines_of(read_bytes(dir.work() / "p.csv")), after = lines_of(read_bytes(dir.work() / "d.csv"));
  ASSERT_GT(after.size(), before.size() + 20);
  for (std::size_t k = 0; k < before.size(); ++k) ASSERT_EQ(after[k], before[k]) << "line " << k << ": the input is kept as it was";
  // The independent check, with the radii tested against the range only (the voids' own radii).
  const RunResult v = run_frontpack(dir, "validate d.csv --scene fit.yaml --ks-alpha 0");
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  const std::string rec = read_bytes(dir.work() / "rec.json");
  for (const char* key : {"\"densify_added\"", "\"densify_volume_fraction_before\"", "\"densify_stop\"", "\"densify_given\": 1"})
    EXPECT_NE(rec.find(key), std::string::npos) << key;
}

TEST_F(CliDensify, TheSceneKeyAfterPackGivesWhatDensifyGivesAfterPack) {
  ASSERT_EQ(run_frontpack(dir, "pack fit.yaml -o both.csv -q").exit_code, 0);
  ASSERT_EQ(run_frontpack(dir, "densify p.csv --scene fit.yaml -o d.csv -q").exit_code, 0);
  EXPECT_EQ(read_bytes(dir.work() / "both.csv"), read_bytes(dir.work() / "d.csv"));
  // Reruns are byte-identical.
  ASSERT_EQ(run_frontpack(dir, "densify p.csv --scene fit.yaml -o again.csv -q").exit_code, 0);
  EXPECT_EQ(read_bytes(dir.work() / "again.csv"), read_bytes(dir.work() / "d.csv"));
}

TEST_F(CliDensify, RadiiFromTheLawPassTheRadiiTest) {
  // Distribution mode (the default): radii drawn from the law; the packing passes the default
  // radii test of `validate`.
  write_bytes(dir.work() / "law.yaml", std::string(kScene) + "densify:\n");
  const RunResult r = run_frontpack(dir, "densify p.csv --scene law.yaml -o d.vtu");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("drawn left unplaced"), std::string::npos) << r.out;
  EXPECT_EQ(run_frontpack(dir, "validate d.vtu --scene law.yaml").exit_code, 0);
}

TEST_F(CliDensify, ASplitLawKeepsItsProportionsOrSaysItCouldNot) {
  // r in [0.01, 0.05], split at 0.015: the front packs r > 0.015, the voids take r <= 0.015 up to
  // an eighth of the whole (F(0.015) = 1/8): the packing passes the radii test of the whole law.
  write_bytes(dir.work() / "split.yaml", std::string(kScene) + "densify: {split: 0.015}\n");
  const RunResult r = run_frontpack(dir, "pack split.yaml -o s.csv");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("void filling: particle count"), std::string::npos) << "stopped at the law's proportion: " << r.out;
  std::size_t small = 0, all = 0;
  for (const std::string& line : lines_of(read_bytes(dir.work() / "s.csv"))) {
    std::vector<double> v;
    if (!parse_numbers(line, ',', v) || v.size() != 5) continue;
    ++all;
    small += v[4] <= 0.015;
  }
  EXPECT_NEAR(static_cast<double>(small), static_cast<double>(all) / 8, 1.0) << all << " spheres";
  EXPECT_EQ(run_frontpack(dir, "validate s.csv --scene split.yaml").exit_code, 0);
  // Split high, the voids cannot take their share: the radii test says so (exit 3), the files are written.
  write_bytes(dir.work() / "high.yaml", "dimension: 3\nseed: 4\ncontainer: {type: box, min: [0, 0, 0], max: [0.6, 0.6, 0.6]}\n"
                                        "particles: {radius: {distribution: uniform, min: 0.01, max: 0.05}}\n"
                                        "densify: {split: 0.04}\n");
  const RunResult high = run_frontpack(dir, "pack high.yaml -o h.csv");
  EXPECT_EQ(high.exit_code, 3) << high.out;
  EXPECT_NE(high.err.find("size test"), std::string::npos) << high.err;
}

// A packing that fails its verdict (exit 3) never replaces a file: the old output stays, a new
// path (the record here) is written with the verdict in it.
TEST_F(CliDensify, AFailedVerdictKeepsExistingFiles) {
  write_bytes(dir.work() / "high.yaml", "dimension: 3\nseed: 4\ncontainer: {type: box, min: [0, 0, 0], max: [0.6, 0.6, 0.6]}\n"
                                        "particles: {radius: {distribution: uniform, min: 0.01, max: 0.05}}\n"
                                        "densify: {split: 0.04}\n");
  write_bytes(dir.work() / "h.csv", "a good packing of an earlier run\n");
  const RunResult r = run_frontpack(dir, "pack high.yaml -o h.csv --record r.json");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_EQ(read_bytes(dir.work() / "h.csv"), "a good packing of an earlier run\n");
  EXPECT_NE(r.err.find("'h.csv' is not written: it holds a file, which is kept"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("h.csv (csv; not written: the file there is kept)"), std::string::npos) << r.out;
  const std::string record = read_bytes(dir.work() / "r.json");
  EXPECT_NE(record.find("\"validation\": \"FAILED"), std::string::npos) << record.substr(0, 2000);
}

TEST_F(CliDensify, BadInputExitsTwoAndWritesNothing) {
  const auto nothing_new = [&](const RunResult& r, const std::string& what, const std::string& message) {
    EXPECT_EQ(r.exit_code, 2) << what << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << what << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir.work() / "out.csv")) << what;
  };
  nothing_new(run_frontpack(dir, "densify missing.csv --scene fit.yaml -o out.csv"), "missing packing", "missing.csv");
  nothing_new(run_frontpack(dir, "densify p.csv --scene fit.yaml -o p.csv"), "output replaces the input", "p.csv");
  write_bytes(dir.work() / "typo.yaml", std::string(kScene) + "densify: {radius: fit}\n");
  nothing_new(run_frontpack(dir, "densify p.csv --scene typo.yaml -o out.csv"), "unknown key", "typo.yaml:5");
  write_bytes(dir.work() / "z.yaml", std::string(kScene) + "densify: {z_min: 5}\n");
  nothing_new(run_frontpack(dir, "densify p.csv --scene z.yaml -o out.csv"), "z_min", "densify.z_min");
  nothing_new(run_frontpack(dir, "pack z.yaml -o out.csv"), "z_min in pack", "must be an integer from 1 to 4");
  write_bytes(dir.work() / "split.yaml", std::string(kScene) + "densify: {split: 0.06}\n");
  nothing_new(run_frontpack(dir, "pack split.yaml -o out.csv"), "split beyond the law", "densify");
  write_bytes(dir.work() / "splitfit.yaml", std::string(kScene) + "densify: {radii: fit, split: 0.02}\n");
  nothing_new(run_frontpack(dir, "pack splitfit.yaml -o out.csv"), "split with fit", "needs 'radii: distribution'");
  write_bytes(dir.work() / "scaled.yaml", std::string(kScene) + "stop: {particles: 50, scale_sizes: true}\n");
  nothing_new(run_frontpack(dir, "densify p.csv --scene scaled.yaml -o out.csv"), "scaled law", "stop.scale_sizes");
  write_bytes(dir.work() / "eps.yaml", std::string(kScene) + "densify: {overlap: -0.1}\n");
  nothing_new(run_frontpack(dir, "densify p.csv --scene eps.yaml -o out.csv"), "overlap", "densify.overlap");
  write_bytes(dir.work() / "shapes.yaml",
              "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [0.3, 0.3, 0.3]}\n"
              "particles: [{shape: spherocylinder, aspect_ratio: 2, size: {distribution: constant, value: 0.02}}]\n"
              "densify: {radii: fit}\n");
  nothing_new(run_frontpack(dir, "pack shapes.yaml -o out.csv"), "shapes", "needs a scene of spheres");
  write_bytes(dir.work() / "flat.yaml",
              "dimension: 2\ncontainer: {type: rectangle, min: [0, 0], max: [0.3, 0.3]}\n"
              "particles: {radius: {distribution: uniform, min: 0.01, max: 0.05}}\n");
  nothing_new(run_frontpack(dir, "densify p.csv --scene flat.yaml -o out.csv"), "dimensions", "3D packing");
  // A packing that fails validate's verdict is not densified (the least squares once repaired an
  // overlap silently; the void filling ran on anything and failed at the end, exit 3).
  const std::pair<const char*, const char*> invalid[] = {
      {"id,x,y,z,r\n0,0.1,0.1,0.1,0.03\n1,0.11,0.1,0.1,0.03\n", "overlap 0-1"},
      {"id,x,y,z,r\n0,0.1,0.1,0.1,0.03\n1,5,0.1,0.1,0.03\n", "outside 1"},
      {"id,x,y,z,r\n0,0.1,0.1,0.1,0.03\n1,nan,0.1,0.1,0.03\n", "non_finite 1"},
      {"id,x,y,z,r\n0,0.1,0.1,0.1,0.03\n1,0.2,0.2,0.2,0.09\n", "radius_out_of_range 1"},
      {"id,x,y,z,r\n", "holds no particles"},
  };
  write_bytes(dir.work() / "ls.yaml", std::string(kScene) + "least_squares: {radii: fixed}\n");
  for (const auto& [csv, worst] : invalid) {
    write_bytes(dir.work() / "bad.csv", csv);
    for (const char* scene : {"s.yaml", "ls.yaml"}) {
      const RunResult r = run_frontpack(dir, std::string("densify bad.csv --scene ") + scene + " -o out.csv");
      nothing_new(r, std::string(worst) + " " + scene, "'bad.csv' is not a valid packing of the scene");
      EXPECT_NE(r.err.find(worst), std::string::npos) << r.err;
    }
  }
}

}  // namespace
}  // namespace fptest
