// `frontpack analyze`: the table, the JSON (byte-identical for the same packing), the figures
// through Debian's python3-matplotlib, and the failure paths (no interpreter: exit 1 with the
// numeric analysis still written; bad input: exit 2, nothing written); packings of shapes.
#include <gtest/gtest.h>

#include "cli_test_util.hpp"

namespace fptest {
namespace {

const char* kScene = R"(dimension: 3
seed: 9
container: {type: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";

class CliAnalyze : public ::testing::Test {
 protected:
  void SetUp() override {
    write_bytes(dir.work() / "s.yaml", kScene);
    ASSERT_EQ(run_frontpack(dir, "pack s.yaml -q -o p.csv").exit_code, 0);
  }
  TempDir dir;
};

TEST_F(CliAnalyze, TableAndJsonWithTheScene) {
  const RunResult r = run_frontpack(dir, "analyze p.csv --scene s.yaml --json a.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* row : {"VF reference ball", "VF container", "coordination z", "fabric per contact", "K-S centres x",
                          "radii test", "g(r)", "validate: OK"})
    EXPECT_NE(r.out.find(row), std::string::npos) << row << " not in\n" << r.out;
  const std::string json = read_bytes(dir.work() / "a.json");
  for (const char* key : {"\"volume_fraction\"", "\"coordination\"", "\"fabric\"", "\"homogeneity\"", "\"radii_fit\"",
                          "\"relative_projections\"", "\"rdf\"", "\"validation\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
  // Same packing, same bytes.
  ASSERT_EQ(run_frontpack(dir, "analyze p.csv --scene s.yaml --json b.json -q").exit_code, 0);
  EXPECT_EQ(json, read_bytes(dir.work() / "b.json"));
}

// A packing of shapes, from its json output and its scene: the analysis of sphere packings
// (every table row, every JSON section), the very one `pack` recorded under "analysis" (one
// analysis), the orientation order of the body axes (1 for capsules all of one fixed
// orientation, near 0 for random ones), and the figures.
TEST_F(CliAnalyze, PackingsOfShapesFromTheirJsonOutput) {
  const auto scene = [](const std::string& orientation, int n) {
    return "dimension: 3\nseed: 3\ncontainer: {type: box, min: [0, 0, 0], max: [0.4, 0.4, 0.4]}\n"
           "particles:\n  - shape: spherocylinder\n    aspect_ratio: 0.4\n"
           "    size: {distribution: uniform, min: 0.02, max: 0.03}\n    orientation: " + orientation +
           "\nstop: {particles: " + std::to_string(n) + "}\n";
  };
  const auto python = [&](const std::string& code) {
    const std::string cmd = "cd '" + dir.work().string() + "' && /usr/bin/python3 -c \"" + code + "\"";
    return std::system(cmd.c_str());
  };
  write_bytes(dir.work() / "fixed.yaml", scene("{fixed: [0.9238795325112867, 0, 0.3826834323650898, 0]}", 80));
  ASSERT_EQ(run_frontpack(dir, "pack fixed.yaml -q -o fixed.json --record fixed-rec.json").exit_code, kIncomplete);  // the count stop
  const RunResult fixed = run_frontpack(dir, "analyze fixed.json --scene fixed.yaml --json fixed-a.json");
  ASSERT_EQ(fixed.exit_code, 0) << fixed.out << fixed.err;
  for (const char* row : {"particles of shapes", "r_eq in", "VF reference ball", "VF container", "VF core", "coordination z",
                          "fabric per contact", "K-S centres", "K-S projections", "radii test", "g(r)", "orientation order",
                          "validate: OK"})
    EXPECT_NE(fixed.out.find(row), std::string::npos) << row << " not in\n" << fixed.out;
  // The json output stores quaternions, so a re-read rotation (and what follows from it) may
  // differ from the packed one in the last bits: figures agree to 1e-9, counts exactly.
  EXPECT_EQ(python("import json, math; a = json.load(open('fixed-a.json')); r = json.load(open('fixed-rec.json')); "
                   "same = lambda x, y: all(same(x[k], y[k]) for k in x) and x.keys() == y.keys() if isinstance(x, dict) else "
                   "(len(x) == len(y) and all(map(same, x, y))) if isinstance(x, list) else "
                   "math.isclose(x, y, rel_tol=1e-9, abs_tol=1e-12) if isinstance(x, float) and isinstance(y, float) else x == y; "
                   "assert same(a, r['analysis']), 'analyze and pack differ'; "
                   "assert abs(a['orientation']['order'] - 1) < 1e-12, a['orientation']; "
                   "assert a['coordination']['contacts'] == r['counters']['contacts'] > 0; "
                   "assert abs(a['volume_fraction']['container']['value'] - r['metrics']['volume_fraction_container']) < 1e-15; "
                   "assert a['volume_fraction']['core']['value'] > a['volume_fraction']['container']['value']; "
                   "assert a['radii']['name'] == 'r_eq' and a['templates'] == [{'family': 'spherocylinder', 'count': 80}]"),
            0);

  write_bytes(dir.work() / "random.yaml", scene("random", 400));
  ASSERT_EQ(run_frontpack(dir, "pack random.yaml -q -o random.json").exit_code, kIncomplete);
  ASSERT_EQ(run_frontpack(dir, "analyze random.json --scene random.yaml --json random-a.json -q").exit_code, 0);
  EXPECT_EQ(python("import json; a = json.load(open('random-a.json')); s = a['orientation']['order']; "
                   "assert 0 <= s < 0.15, s"),  // isotropic: the largest eigenvalue's bias is ~1/sqrt(N)
            0);

  if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0)
    GTEST_SKIP() << "python3-matplotlib is not installed (scripts/install-deps.sh --test installs it)";
  fs::create_directories(dir.work() / "plots");
  const RunResult plots = run_frontpack(dir, "analyze random.json --scene random.yaml --plots plots -q");
  EXPECT_EQ(plots.exit_code, 0) << plots.out << plots.err;
  EXPECT_EQ(listing(dir.work() / "plots"),
            (std::set<std::string>{"coordination.png", "fabric.png", "partial_coordination.png", "radii.png", "rdf.png",
                                   "vf_curve.png", "wall_profile.png", "section_xy.png", "section_xz.png", "section_yz.png"}));
}

TEST_F(CliAnalyze, WithoutASceneTheBoundingBoxStandsIn) {
  const RunResult r = run_frontpack(dir, "analyze p.csv --json a.json -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_NE(read_bytes(dir.work() / "a.json").find("\"from_particles\": true"), std::string::npos);
}

TEST_F(CliAnalyze, PlotsAreDrawn) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0)
    GTEST_SKIP() << "python3-matplotlib is not installed (scripts/install-deps.sh --test installs it)";
  fs::create_directory(dir.work() / "figs");
  const RunResult r = run_frontpack(dir, "analyze p.csv --scene s.yaml --plots figs -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(listing(dir.work() / "figs"),
            (std::set<std::string>{"coordination.png", "fabric.png", "partial_coordination.png", "radii.png", "rdf.png",
                                   "vf_curve.png", "wall_profile.png", "section_xy.png", "section_xz.png", "section_yz.png"}));
  for (const auto& e : fs::directory_iterator(dir.work() / "figs")) EXPECT_GT(fs::file_size(e.path()), 5000u);
}

TEST_F(CliAnalyze, MissingPythonIsAClearErrorAndTheNumbersStillCome) {
  fs::create_directory(dir.work() / "figs");
  const RunResult r = run_frontpack(dir, "analyze p.csv --scene s.yaml --json a.json --plots figs --python /no/python3");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("python3-matplotlib"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("VF reference ball"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir.work() / "a.json"));
  EXPECT_TRUE(fs::is_empty(dir.work() / "figs"));
}

TEST_F(CliAnalyze, BadInputExitsTwoAndWritesNothing) {
  EXPECT_EQ(run_frontpack(dir, "analyze missing.csv --json a.json").exit_code, 2);
  EXPECT_EQ(run_frontpack(dir, "analyze p.csv --plots no_such_dir --json a.json").exit_code, 2);
  EXPECT_EQ(run_frontpack(dir, "analyze p.csv --json no_such_dir/a.json").exit_code, 2);
  EXPECT_FALSE(fs::exists(dir.work() / "a.json"));
}

}  // namespace
}  // namespace fptest
