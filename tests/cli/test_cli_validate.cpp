// `frontpack validate`: a packing written by `pack` passes in every format; planted defects (an
// overlap of 1e-8 of the smaller radius, a particle 1e-8 r outside the container, a radius out of
// range, a distorted size distribution) and a file without particles fail with exit 3 and the
// offender's id; bad input exits 2. Packings of shapes: from their json output and scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cli_test_util.hpp"

namespace fptest {
namespace {

const char* kScene = R"(dimension: 3
seed: 4
container: {type: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";

struct Row {
  int id;
  double x, y, z, r;
};

std::vector<Row> read_csv(const fs::path& p) {
  std::vector<Row> rows;
  const auto lines = lines_of(read_bytes(p));
  for (std::size_t k = 1; k < lines.size(); ++k) {
    Row w{};
    if (std::sscanf(lines[k].c_str(), "%d,%lf,%lf,%lf,%lf", &w.id, &w.x, &w.y, &w.z, &w.r) == 5) rows.push_back(w);
  }
  return rows;
}

void write_csv(const fs::path& p, const std::vector<Row>& rows) {
  std::string s = "id,x,y,z,r\n";
  char buf[200];
  for (const Row& w : rows) {
    std::snprintf(buf, sizeof buf, "%d,%.17g,%.17g,%.17g,%.17g\n", w.id, w.x, w.y, w.z, w.r);
    s += buf;
  }
  write_bytes(p, s);
}

class CliValidate : public ::testing::Test {
 protected:
  void SetUp() override {
    write_bytes(dir.work() / "s.yaml", kScene);
    const RunResult r = run_frontpack(dir, "pack s.yaml -o p.csv -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    rows = read_csv(dir.work() / "p.csv");
    ASSERT_GT(rows.size(), 200u);
  }
  RunResult validate(const std::vector<Row>& changed) {
    write_csv(dir.work() / "q.csv", changed);
    return run_frontpack(dir, "validate q.csv --scene s.yaml");
  }
  TempDir dir;
  std::vector<Row> rows;
};

TEST_F(CliValidate, PackedFilesPassInEveryFormat) {
  for (const char* ext : {"csv", "txt", "data", "vtu", "json"}) {
    const std::string file = std::string("p.") + ext;
    ASSERT_EQ(run_frontpack(dir, "pack s.yaml -q -o " + file).exit_code, 0) << file;
    const RunResult r = run_frontpack(dir, "validate " + file + " --scene s.yaml");
    EXPECT_EQ(r.exit_code, 0) << file << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("result         ok"), std::string::npos) << r.out;
  }
}

TEST_F(CliValidate, PlantedOverlapOfOneEMinus8IsCaughtWithItsIds) {
  // Move particle b towards its nearest neighbour a until they overlap by 1e-8 r_min.
  std::size_t a = 0, b = 1;
  double best = 1e300;
  for (std::size_t j = 1; j < rows.size(); ++j) {
    const double d = std::hypot(rows[j].x - rows[0].x, rows[j].y - rows[0].y, rows[j].z - rows[0].z) - rows[0].r - rows[j].r;
    if (d < best) best = d, b = j;
  }
  auto changed = rows;
  const double d = std::hypot(rows[b].x - rows[a].x, rows[b].y - rows[a].y, rows[b].z - rows[a].z);
  const double target = rows[a].r + rows[b].r - 1e-8 * std::min(rows[a].r, rows[b].r);
  const double s = target / d;
  changed[b].x = rows[a].x + s * (rows[b].x - rows[a].x);
  changed[b].y = rows[a].y + s * (rows[b].y - rows[a].y);
  changed[b].z = rows[a].z + s * (rows[b].z - rows[a].z);
  const RunResult r = validate(changed);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("overlap " + std::to_string(std::min(a, b)) + "-" + std::to_string(std::max(a, b))),
            std::string::npos)
      << r.out;
}

TEST_F(CliValidate, ParticleOneEMinus8OutsideIsCaught) {
  auto changed = rows;
  changed[7].x = changed[7].r * (1.0 - 1e-8);  // protrudes 1e-8 r beyond the wall x = 0
  const RunResult r = validate(changed);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("outside 7:"), std::string::npos) << r.out;
}

TEST_F(CliValidate, RadiusOutOfRangeAndDistortedDistributionFail) {
  auto big = rows;
  big[3].r = 0.021;
  const RunResult r1 = validate(big);
  EXPECT_EQ(r1.exit_code, 3) << r1.out;
  EXPECT_NE(r1.out.find("radius_out_of_range 3:"), std::string::npos) << r1.out;
  // Every radius shrunk to its lower third: no overlap, all inside, all in range, but not U[0.01, 0.02].
  auto shrunk = rows;
  for (Row& w : shrunk) w.r = 0.01 + (w.r - 0.01) / 3;
  const RunResult r2 = validate(shrunk);
  EXPECT_EQ(r2.exit_code, 3) << r2.out;
  EXPECT_NE(r2.out.find("K-S"), std::string::npos) << r2.out;
}

TEST_F(CliValidate, AFileWithoutParticlesFails) {
  write_bytes(dir.work() / "e.csv", "id,x,y,z,r\n");
  const RunResult r = run_frontpack(dir, "validate e.csv --scene s.yaml");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.out.find("FAILED: the packing holds no particles"), std::string::npos) << r.out;
  write_bytes(dir.work() / "e.txt", "#format x_y_z_r\n");
  const RunResult q = run_frontpack(dir, "validate e.txt --scene s.yaml -q");
  EXPECT_EQ(q.exit_code, 3) << q.err;
  EXPECT_NE(q.err.find("e.txt holds no particles"), std::string::npos) << q.err;
}

TEST_F(CliValidate, ASceneOfShapesIsRefused) {
  write_bytes(dir.work() / "shapes.yaml",
              "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}\n"
              "particles:\n  - shape: spherocylinder\n    aspect_ratio: 0.5\n"
              "    size: {distribution: uniform, min: 0.01, max: 0.02}\n");
  const RunResult r = run_frontpack(dir, "validate p.csv --scene shapes.yaml");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("non-spherical"), std::string::npos) << r.err;
}

// A packing of shapes (the files `pack` writes for a scene of capsules), given to validate and to
// analyze: refused with exit code 2 and a message that says why (not a layout error), each format.
// No radius pool: a count stop leaves the pool's drafts unplaced, the smaller ones more often,
// which skews the size test of 10 particles (this is not what the test is about). The count stop
// leaves the packing incomplete (exit 4), and its files written.
TEST_F(CliValidate, PackingsOfShapesAreRefusedWithTheReason) {
  write_bytes(dir.work() / "caps.yaml",
              "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}\n"
              "particles:\n  - shape: spherocylinder\n    aspect_ratio: 0.5\n"
              "    size: {distribution: uniform, min: 0.02, max: 0.03}\nstop: {particles: 10}\npacker: {radius_pool: 1}\n");
  const struct { const char* file; const char* why; } cases[] = {
      {"caps.csv", "'shape_id' column"}, {"caps.json", "'shapes' list"}, {"caps.vtu", "'quaternion' array"}};
  for (const auto& c : cases) {
    ASSERT_EQ(run_frontpack(dir, std::string("pack caps.yaml -q -o ") + c.file).exit_code, kIncomplete) << c.file;
    for (const std::string& command : {std::string("analyze ") + c.file, std::string("validate ") + c.file + " --scene s.yaml"}) {
      const RunResult r = run_frontpack(dir, command);
      EXPECT_EQ(r.exit_code, 2) << command << r.out << r.err;
      EXPECT_NE(r.err.find("holds non-spherical particles"), std::string::npos) << command << r.err;
      EXPECT_NE(r.err.find(c.why), std::string::npos) << command << r.err;
    }
  }
}

// A packing of shapes, from its json output and its scene: the same verdict as pack's (ok, with
// the contacts pack counted); a particle moved onto another fails with exit code 3; 1e9 from the
// origin it still passes (positions re-read exactly); other formats are refused.
TEST_F(CliValidate, PackingsOfShapesFromTheirJsonOutput) {
  const auto scene = [](const std::string& lo, const std::string& hi) {
    return "dimension: 3\ncontainer: {type: box, min: [" + lo + ", " + lo + ", " + lo + "], max: [" + hi + ", " + hi + ", " + hi +
           "]}\nparticles:\n  - shape: spherocylinder\n    aspect_ratio: 0.5\n"
           "    size: {distribution: uniform, min: 0.02, max: 0.03}\n  - shape: cluster\n    centers: [[0, 0, 0], [1, 0, 0]]\n"
           "    radii: [0.6, 0.6]\n    size: {distribution: uniform, min: 0.02, max: 0.03}\nstop: {particles: 60}\n";
  };
  write_bytes(dir.work() / "caps.yaml", scene("0", "0.2"));
  ASSERT_EQ(run_frontpack(dir, "pack caps.yaml -q -o caps.json --record rec.json").exit_code, kIncomplete);  // the count stop
  const RunResult ok = run_frontpack(dir, "validate caps.json --scene caps.yaml");
  EXPECT_EQ(ok.exit_code, 0) << ok.out << ok.err;
  EXPECT_NE(ok.out.find("particles of shapes"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("particles      60;"), std::string::npos) << ok.out;
  const std::string record = read_bytes(dir.work() / "rec.json");
  const std::size_t at = record.find("\"contacts\": ");
  ASSERT_NE(at, std::string::npos);
  const std::string contacts = record.substr(at + 12, record.find_first_of(",\n}", at + 12) - at - 12);
  EXPECT_NE(ok.out.find("contacts       " + contacts + ","), std::string::npos) << "pack counted " << contacts << "\n" << ok.out;

  // Particle 1 moved onto particle 0: an overlap the validator must find.
  std::string text = read_bytes(dir.work() / "caps.json");
  const auto position_of = [&](int id) {
    const std::size_t line = text.find("{\"id\": " + std::to_string(id) + ",");
    const std::size_t from = text.find("\"position\": [", line), to = text.find(']', from);
    return std::make_pair(from, to + 1 - from);
  };
  const auto [from0, length0] = position_of(0);
  const std::string first = text.substr(from0, length0);
  const auto [from1, length1] = position_of(1);
  text.replace(from1, length1, first);
  write_bytes(dir.work() / "moved.json", text);
  const RunResult bad = run_frontpack(dir, "validate moved.json --scene caps.yaml");
  EXPECT_EQ(bad.exit_code, 3) << bad.out << bad.err;
  EXPECT_NE(bad.out.find("FAILED"), std::string::npos) << bad.out;
  const std::size_t worst = bad.out.find("worst offenders");  // the worst first: the planted pair
  ASSERT_NE(worst, std::string::npos) << bad.out;
  EXPECT_EQ(bad.out.find("    overlap 0-1: ", worst), bad.out.find('\n', worst) + 1) << bad.out;

  write_bytes(dir.work() / "far.yaml", scene("1000000000", "1000000000.2"));
  ASSERT_EQ(run_frontpack(dir, "pack far.yaml -q -o far.json").exit_code, kIncomplete);
  const RunResult far = run_frontpack(dir, "validate far.json --scene far.yaml");
  EXPECT_EQ(far.exit_code, 0) << far.out << far.err;

  // A scene with fewer templates than the file names: bad input.
  std::string one_template = scene("0", "0.2");
  one_template.erase(one_template.find("  - shape: cluster"), one_template.find("stop:") - one_template.find("  - shape: cluster"));
  write_bytes(dir.work() / "one.yaml", one_template);
  const RunResult ids = run_frontpack(dir, "validate caps.json --scene one.yaml");
  EXPECT_EQ(ids.exit_code, 2) << ids.out << ids.err;
  EXPECT_NE(ids.err.find("shape_id is 1 but one.yaml has 1 particle templates"), std::string::npos) << ids.err;

  ASSERT_EQ(run_frontpack(dir, "pack caps.yaml -q -o caps.csv").exit_code, kIncomplete);
  const RunResult csv = run_frontpack(dir, "validate caps.csv --scene caps.yaml");
  EXPECT_EQ(csv.exit_code, 2) << csv.out << csv.err;
  EXPECT_NE(csv.err.find("give the packing's json output"), std::string::npos) << csv.err;
}

TEST_F(CliValidate, BadInputExitsTwo) {
  EXPECT_EQ(run_frontpack(dir, "validate missing.csv --scene s.yaml").exit_code, 2);
  EXPECT_EQ(run_frontpack(dir, "validate p.csv").exit_code, 2);  // --scene is required
  write_bytes(dir.work() / "s2.yaml", "dimension: 2\ncontainer: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
                                      "particles: {radius: {distribution: constant, value: 0.1}}\n");
  const RunResult r = run_frontpack(dir, "validate p.csv --scene s2.yaml");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("3D packing"), std::string::npos) << r.err;
  write_bytes(dir.work() / "broken.csv", "id,x,y,z,r\n0,0.1,0.1,zero,0.01\n");
  const RunResult r2 = run_frontpack(dir, "validate broken.csv --scene s.yaml");
  EXPECT_EQ(r2.exit_code, 2);
  EXPECT_NE(r2.err.find("broken.csv"), std::string::npos) << r2.err;
}

}  // namespace
}  // namespace fptest
