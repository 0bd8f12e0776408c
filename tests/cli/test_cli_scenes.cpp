// The named scenes of scenes/: the small ones are packed end to end by the binary (validation
// included: exit 3 if the packing fails it); every scene, the large ones included, loads.
#include <gtest/gtest.h>

#include "cli_test_util.hpp"
#include "core/io/scene_yaml.hpp"

namespace fptest {
namespace {

class CliNamedScene : public ::testing::TestWithParam<std::string> {};

TEST_P(CliNamedScene, PacksWithExitZero) {
  const std::string path = source_path("scenes/" + GetParam() + ".yaml");
  if (!fs::exists(path)) GTEST_SKIP() << path << " is not in the repository (yet)";
  TempDir dir;
  const RunResult r = run_frontpack(dir, "pack " + quoted(path) + " -o " + GetParam() + ".csv");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("validation     ok"), std::string::npos) << r.out;
  // -o replaces the scene's own outputs (demo lists five under out/): only the one file.
  EXPECT_EQ(listing(dir.work()), (std::set<std::string>{GetParam() + ".csv"}));
  EXPECT_GT(lines_of(read_bytes(dir.work() / (GetParam() + ".csv"))).size(), 100u);
}

INSTANTIATE_TEST_SUITE_P(SmallScenes, CliNamedScene,
                         ::testing::Values("demo", "valera-cube", "cylinder", "ratio7", "mesh"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

TEST(NamedScenes, EverySceneLoads) {
  int count = 0;
  for (const auto& e : fs::directory_iterator(source_path("scenes"))) {
    if (e.path().extension() != ".yaml") continue;
    ++count;
    SCOPED_TRACE(e.path().string());
    EXPECT_NO_THROW({
      const fp::Scene s = fp::load_scene(e.path().string());
      EXPECT_TRUE(s.dimension == 2 ? s.container2 != nullptr : s.container3 != nullptr);
      EXPECT_TRUE(s.radii != nullptr || !s.particle_templates.empty());
    });
  }
  EXPECT_GE(count, 7);
}

TEST(NamedScenes, LargeScenesSayWhatTheyPromise) {
  // Too big to pack in a test: check what they ask for instead.
  const fp::Scene million = fp::load_scene(source_path("scenes/million.yaml"));
  EXPECT_EQ(million.dimension, 3);
  ASSERT_TRUE(million.stop.max_particles.has_value());
  EXPECT_EQ(*million.stop.max_particles, 1000000u);
  // The box holds a million spheres at a plausible volume fraction (< 0.64).
  const double vf_million = 1e6 * 4.0 / 3.0 * fp::kPi * (0.02 * 0.02 * 0.02 * 0.02 - 0.01 * 0.01 * 0.01 * 0.01) /
                            (4 * 0.01) / million.container3->measure();
  EXPECT_LT(vf_million, 0.64);

  const fp::Scene disks = fp::load_scene(source_path("scenes/disks-million.yaml"));
  EXPECT_EQ(disks.dimension, 2);
  ASSERT_TRUE(disks.stop.max_particles.has_value());
  EXPECT_EQ(*disks.stop.max_particles, 1000000u);
  EXPECT_NE(disks.container2, nullptr);

  const fp::Scene db = fp::load_scene(source_path("scenes/valera-db.yaml"));
  EXPECT_EQ(db.dimension, 3);
  EXPECT_DOUBLE_EQ(db.radii->r_min(), 2.0);
  EXPECT_DOUBLE_EQ(db.radii->r_max(), 8.0);
  EXPECT_NEAR(db.radii->mean(), 3.531, 1e-3);  // the paper's D_B mean, as the scene's comment says
}

}  // namespace
}  // namespace fptest
