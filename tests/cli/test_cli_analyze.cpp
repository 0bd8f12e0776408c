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

// A packing of shapes, from its json output and its scene: pack's figures (the same fraction and
// contact count as its record), and the orientation order of the body axes: 1 for capsules all of
// one fixed orientation, near 0 for random ones. --plots is refused (exit 2, nothing drawn).
TEST_F(CliAnalyze, PackingsOfShapesFromTheirJsonOutput) {
  const auto scene = [](const std::string& orientation, int n) {
    return "dimension: 3\nseed: 3\ncontainer: {type: box, min: [0, 0, 0], max: [0.4, 0.4, 0.4]}\n"
           "particles:\n  - shape: spherocylinder\n    aspect_ratio: 0.4\n"
           "    size: {distribution: uniform, min: 0.02, max: 0.03}\n    orientation: " + orientation +
           "\nstop: {particles: " + std::to_string(n) + "}\n";
  };
  const auto number_after = [](const std::string& text, const std::string& key) {
    const std::size_t at = text.find(key);
    EXPECT_NE(at, std::string::npos) << key;
    return at == std::string::npos ? -1.0 : std::stod(text.substr(at + key.size()));
  };
  write_bytes(dir.work() / "fixed.yaml", scene("{fixed: [0.9238795325112867, 0, 0.3826834323650898, 0]}", 80));
  ASSERT_EQ(run_frontpack(dir, "pack fixed.yaml -q -o fixed.json --record fixed-rec.json").exit_code, 0);
  const RunResult fixed = run_frontpack(dir, "analyze fixed.json --scene fixed.yaml --json fixed-a.json");
  ASSERT_EQ(fixed.exit_code, 0) << fixed.out << fixed.err;
  for (const char* row : {"particles of shapes", "VF container", "coordination z", "orientation order", "validate: OK"})
    EXPECT_NE(fixed.out.find(row), std::string::npos) << row << " not in\n" << fixed.out;
  const std::string a = read_bytes(dir.work() / "fixed-a.json"), rec = read_bytes(dir.work() / "fixed-rec.json");
  EXPECT_NEAR(number_after(a, "\"orientation_order\": "), 1.0, 1e-12) << a;
  EXPECT_NEAR(number_after(a, "\"volume_fraction_container\": "), number_after(rec, "\"volume_fraction_container\": "), 1e-12);
  EXPECT_EQ(number_after(a, "\"contacts\": "), number_after(rec, "\"contacts\": "));

  write_bytes(dir.work() / "random.yaml", scene("random", 400));
  ASSERT_EQ(run_frontpack(dir, "pack random.yaml -q -o random.json").exit_code, 0);
  ASSERT_EQ(run_frontpack(dir, "analyze random.json --scene random.yaml --json random-a.json -q").exit_code, 0);
  const double s = number_after(read_bytes(dir.work() / "random-a.json"), "\"orientation_order\": ");
  EXPECT_GE(s, 0.0);
  EXPECT_LT(s, 0.15);  // isotropic: the largest eigenvalue's bias is ~1/sqrt(N)

  fs::create_directories(dir.work() / "plots");
  const RunResult plots = run_frontpack(dir, "analyze random.json --scene random.yaml --plots plots");
  EXPECT_EQ(plots.exit_code, 2) << plots.out << plots.err;
  EXPECT_NE(plots.err.find("option --plots"), std::string::npos) << plots.err;
  EXPECT_TRUE(fs::is_empty(dir.work() / "plots"));
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
