// `frontpack analyze`: the table, the JSON (byte-identical for the same packing), the figures
// through Debian's python3-matplotlib, and the failure paths (no interpreter: exit 1 with the
// numeric analysis still written; bad input: exit 2, nothing written).
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
                                   "vf_curve.png"}));
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
