// `least_squares:` (paper 001) end to end: after the front and on a packing given to `frontpack
// densify` (alone: no void filling unless `densify:` asks), the summary line and the record's
// figures, `frontpack validate` passing the output at the stage's tolerance, every particle kept,
// byte-identical reruns; bad keys exit 2 and write nothing.
#include <gtest/gtest.h>

#include <string>

#include "cli_test_util.hpp"

namespace fptest {
namespace {

const char* kBox = "dimension: 3\nseed: 2\ncontainer: {type: box, min: [0, 0, 0], max: [0.4, 0.4, 0.4]}\n"
                   "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n";

TEST(CliLeastSquares, AfterTheFrontItDensifiesAndValidates) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", std::string(kBox) + "least_squares: {radii: range}\n");
  write_bytes(dir.work() / "plain.yaml", kBox);
  ASSERT_EQ(run_frontpack(dir, "pack plain.yaml -o plain.csv -q --record plain.json").exit_code, 0);
  const RunResult r = run_frontpack(dir, "pack s.yaml -o s.csv --record rec.json");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("least squares  radii in the law's range"), std::string::npos) << r.out;
  const std::string rec = read_bytes(dir.work() / "rec.json");
  const double before = record_number(rec, "least_squares_volume_fraction_before");
  const double after = record_number(rec, "least_squares_volume_fraction_after");
  EXPECT_NEAR(before, record_number(read_bytes(dir.work() / "plain.json"), "volume_fraction_container"), 1e-12);
  EXPECT_NEAR(after, record_number(rec, "volume_fraction_container"), 1e-12);
  EXPECT_GT(after, before + 0.01);
  EXPECT_EQ(lines_of(read_bytes(dir.work() / "s.csv")).size(), lines_of(read_bytes(dir.work() / "plain.csv")).size())
      << "every particle kept";
  const RunResult v = run_frontpack(dir, "validate s.csv --scene s.yaml");
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  EXPECT_NE(v.out.find("0 beyond 1e-06 of the smaller radius"), std::string::npos) << v.out;
  ASSERT_EQ(run_frontpack(dir, "pack s.yaml -o again.csv -q").exit_code, 0);
  EXPECT_EQ(read_bytes(dir.work() / "again.csv"), read_bytes(dir.work() / "s.csv"));
}

TEST(CliLeastSquares, OnAGivenPackingAloneWithFixedRadii) {
  TempDir dir;
  write_bytes(dir.work() / "plain.yaml", std::string(kBox) + "target: {solid_fraction: 0.4}\n");
  ASSERT_EQ(run_frontpack(dir, "pack plain.yaml -o p.csv -q").exit_code, 0);
  write_bytes(dir.work() / "f.yaml", std::string(kBox) + "least_squares: {radii: fixed}\n");
  const RunResult r = run_frontpack(dir, "densify p.csv --scene f.yaml -o f.csv --record rec.json");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("least squares  radii fixed"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("void filling"), std::string::npos) << "least_squares alone: no void filling\n" << r.out;
  const std::string rec = read_bytes(dir.work() / "rec.json");
  EXPECT_NEAR(record_number(rec, "least_squares_volume_fraction_after"), 0.4, 0.005);
  EXPECT_EQ(record_number(rec, "least_squares_radii_grown"), 0.0);
  EXPECT_GT(record_number(rec, "least_squares_mean_move"), 0.0);
  EXPECT_EQ(lines_of(read_bytes(dir.work() / "f.csv")).size(), lines_of(read_bytes(dir.work() / "p.csv")).size());
  EXPECT_EQ(run_frontpack(dir, "validate f.csv --scene f.yaml").exit_code, 0);
}

/// A mesh container (its facets are the walls of Eq. 3 and of the overlap removal): sound, denser.
TEST(CliLeastSquares, InAMeshContainer) {
  TempDir dir;
  write_bytes(dir.work() / "m.yaml", "dimension: 3\nseed: 1\ncontainer: {type: mesh, file: " +
                                         source_path("tests/data/meshes/octahedron_binary.stl") +
                                         "}\nparticles: {radius: {distribution: uniform, min: 0.03, max: 0.06}}\n"
                                         "least_squares: {}\n");
  const RunResult r = run_frontpack(dir, "pack m.yaml -o m.csv -q --record rec.json");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string rec = read_bytes(dir.work() / "rec.json");
  EXPECT_GT(record_number(rec, "least_squares_volume_fraction_after"),
            record_number(rec, "least_squares_volume_fraction_before") + 0.01);
  EXPECT_GT(record_number(rec, "least_squares_wall_terms"), 100.0);
  const RunResult v = run_frontpack(dir, "validate m.csv --scene m.yaml");
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
}

TEST(CliLeastSquares, BadKeysAreRefusedAndWriteNothing) {
  TempDir dir;
  const std::pair<std::string, const char*> cases[] = {
      {std::string(kBox) + "least_squares: {radii: all}\n", "key 'least_squares.radii'"},
      {std::string(kBox) + "least_squares: {tolerance: 0.5}\n", "must be a number in (0, 0.01]"},
      {std::string(kBox) + "least_squares: {edge_gap: -1}\n", "key 'least_squares.edge_gap'"},
      {std::string(kBox) + "least_squares: {evaluations: 0}\n", "must be an integer from 1"},
      {std::string(kBox) + "least_squares: {speed: 2}\n", "unknown key"},
      {"dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\nparticles:\n"
       "  - {shape: ellipsoid, aspect_ratio: 0.5, size: {distribution: constant, value: 0.05}}\n"
       "least_squares: {}\n",
       "needs a scene of spheres"},
  };
  for (const auto& [scene, message] : cases) expect_refused(dir, scene, message);
}

}  // namespace
}  // namespace fptest
