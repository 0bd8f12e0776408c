// The JSON run record: key order, exact doubles, determinism, embedded particles.
#include <gtest/gtest.h>

#include <cmath>

#include "core/io/packing_readers.hpp"
#include "core/io/run_record.hpp"
#include "core/sampling/rng.hpp"
#include "tests/io/io_test_util.hpp"

namespace fp {
namespace {

RunRecord record() {
  RunRecord r;
  r.version = "0.1.0";
  r.scene_path = "scenes/demo.yaml";
  r.scene_text = "dimension: 3\nseed: 42\n# caf\xe9 in Latin-1, not UTF-8\n";
  r.seed = 42;
  r.dimension = 3;
  r.n = 2;
  r.container_description = "box [0,0.9]^3";
  r.distribution_description = "uniform [0.01, 0.02]";
  Aabb<3> b;
  b.lo = Vec3(0, 0, 0);
  b.hi = Vec3(0.9, 0.9, 0.9);
  r.bounds = b;
  r.density = 2650;
  r.timings = {{"pack", 0.1}, {"analyze", 0.2}};
  r.metrics = {{"vf", 0.1 + 0.2}, {"nan_metric", std::nan("")}};
  r.counters = {{"z", 18446744073709551615ULL}, {"a", 1}};
  r.info = {{"zeta", "first"}, {"alpha", "second"}};
  return r;
}

std::size_t pos(const std::string& text, const std::string& needle) {
  const std::size_t p = text.find(needle);
  EXPECT_NE(p, std::string::npos) << "missing " << needle << " in\n" << text;
  return p;
}

TEST(RunRecord, KeysInInsertionOrderAndValuesExact) {
  const std::string j = run_record_json(record());
  const char* keys[] = {"\"frontpack_version\"", "\"dimension\"", "\"seed\"", "\"n\"", "\"scene\"",
                        "\"container\"", "\"distribution\"", "\"bounds\"", "\"density\"", "\"timings\"",
                        "\"pack\"", "\"analyze\"", "\"metrics\"", "\"counters\"", "\"z\"", "\"a\"", "\"info\"",
                        "\"zeta\"", "\"alpha\""};
  std::size_t last = 0;
  for (const char* k : keys) {
    const std::size_t p = pos(j, k);
    EXPECT_GT(p, last) << k;
    last = p;
  }
  EXPECT_NE(j.find("0.30000000000000004"), std::string::npos) << j;  // 0.1 + 0.2, not rounded
  EXPECT_NE(j.find("18446744073709551615"), std::string::npos);      // full uint64
  EXPECT_NE(j.find("\"nan_metric\": null"), std::string::npos) << j;
  EXPECT_NE(j.find("\"seed\": 42"), std::string::npos);
  EXPECT_EQ(j.find("\"particles\""), std::string::npos);
  EXPECT_EQ(j.back(), '\n');
}

TEST(RunRecord, IdenticalInputGivesIdenticalBytes) {
  EXPECT_EQ(run_record_json(record()), run_record_json(record()));
  Packing<3> p;
  p.add(Vec3(0.1, 0.2, 0.3), 0.01);
  RunRecord r = record();
  r.embed_particles = true;
  EXPECT_EQ(run_record_json(r, p), run_record_json(r, p));
}

TEST(RunRecord, InvalidUtf8InSceneTextDoesNotThrow) {
  EXPECT_NO_THROW(run_record_json(record()));
}

TEST(RunRecord, EmbeddedParticlesRoundTripExactly) {
  Rng rng(3);
  Packing<3> p;
  for (int i = 0; i < 100; ++i) p.add(Vec3(rng.uniform01(), rng.uniform(-1, 1), rng.uniform01() * 1e-9), rng.uniform01());
  RunRecord r = record();
  EXPECT_EQ(run_record_json(r, p), run_record_json(r));  // flag off: record only
  r.embed_particles = true;
  const std::string text = run_record_json(r, p);
  const Packing<3> back = packing_from_json<3>(text, "mem.json");
  ASSERT_EQ(back.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(back.centers[i], p.centers[i]);
    EXPECT_EQ(back.radii[i], p.radii[i]);
  }
  // Still the record before the particles.
  EXPECT_LT(pos(text, "\"info\""), pos(text, "\"particles\""));
  EXPECT_EQ(run_record_dimension(text, "mem.json"), 3);
}

TEST(RunRecord, RecordOnlyFileHasNoParticlesToRead) {
  test::TempDir dir;
  const std::string path = dir.file("record.json");
  write_run_record(path, record());
  try {
    read_packing<3>(OutputFormat::Json, path);
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("particles"), std::string::npos);
  }
}

TEST(RunRecord, MissingBoundsIsNull) {
  RunRecord r = record();
  r.bounds.reset();
  EXPECT_NE(run_record_json(r).find("\"bounds\": null"), std::string::npos);
}

}  // namespace
}  // namespace fp
