// Every bad input ends with exit code 2, a message naming the scene file, the line and the
// key, and no output written: a new output file is not created, an existing one is left
// byte for byte as it was, and no temporary is left behind.
#include <gtest/gtest.h>

#include <regex>

#include "cli_test_util.hpp"

namespace fptest {
namespace {

const std::string kContainer = "container: {type: box, min: [0, 0, 0], max: [0.1, 0.1, 0.1]}\n";
const std::string kParticles = "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n";
const std::string kGood = "dimension: 3\n" + kContainer + kParticles;

struct BadScene {
  std::string name;
  std::string text;  ///< also lists scene outputs, which must not be written either
  int line;          ///< 1-based line the message must point at (0: any line)
  std::string key;   ///< the key (or its parent) the message must name ("" for YAML syntax errors)
};

std::ostream& operator<<(std::ostream& os, const BadScene& b) { return os << b.name; }

const std::string kOpenMesh = source_path("tests/data/meshes/open_cube.off");

const BadScene kBadScenes[] = {
    {"UnknownTopKey", kGood + "colour: red\n", 4, "colour"},
    {"UnknownNestedKey", "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1], radius: 2}\n" + kParticles, 2,
     "container.radius"},
    {"MisspeltPackerKey", kGood + "packer:\n  front: closest\n  radius_pol: 4\n", 6, "packer.radius_pol"},
    {"WrongTypeDimension", "dimension: three\n" + kContainer + kParticles, 1, "dimension"},
    {"WrongTypeRadius", "dimension: 3\n" + kContainer + "particles:\n  radius:\n    distribution: uniform\n    min: small\n    max: 0.02\n",
     6, "particles.radius.min"},
    {"WrongTypeWalls", kGood + "packer: {walls: maybe}\n", 4, "packer.walls"},
    {"MinGreaterThanMax", "dimension: 3\n" + kContainer + "particles:\n  radius:\n    distribution: uniform\n    min: 0.02\n    max: 0.01\n",
     7, "particles.radius.max"},
    {"NormalMinGreaterThanMax",
     "dimension: 3\n" + kContainer + "particles:\n  radius: {distribution: normal, mean: 0.015, std: 0.002, min: 0.02, max: 0.01}\n", 4,
     "particles.radius.max"},
    {"ZeroRadius", "dimension: 3\n" + kContainer + "particles:\n  radius: {distribution: constant, value: 0}\n", 4,
     "particles.radius.value"},
    {"NegativeRadius", "dimension: 3\n" + kContainer + "particles:\n  radius:\n    distribution: uniform\n    min: -0.01\n    max: 0.02\n",
     6, "particles.radius.min"},
    {"NegativeBoxSize", "dimension: 3\ncontainer:\n  type: box\n  min: [0, 0, 0]\n  max: [-1, 1, 1]\n" + kParticles, 5,
     "container.max"},
    {"NegativeSphereRadius", "dimension: 3\ncontainer: {type: sphere, center: [0, 0, 0], radius: -1}\n" + kParticles, 2,
     "container.radius"},
    {"ZeroCylinderHeight",
     "dimension: 3\ncontainer:\n  type: cylinder\n  base: [0, 0, 0]\n  radius: 1\n  height: 0\n" + kParticles, 6,
     "container.height"},
    {"SelfIntersectingPolygon",
     "dimension: 2\ncontainer:\n  type: polygon\n  vertices: [[0, 0], [1, 1], [1, 0], [0, 1]]\n"
     "particles: {radius: {distribution: constant, value: 0.01}}\n",
     0, "container"},
    {"ParticlesLargerThanContainer", "dimension: 3\n" + kContainer + "particles:\n  radius: {distribution: constant, value: 0.2}\n", 4,
     "particles.radius"},
    // A sliver: its bounding box holds the particle, the polygon itself does not.
    {"ContainerTooThinForTheParticles",
     "dimension: 2\ncontainer:\n  type: polygon\n  vertices: [[0, 0], [1, 1], [0.98, 1]]\n"
     "particles: {radius: {distribution: constant, value: 0.05}}\n",
     0, "particles.radius"},
    {"OpenMesh", "dimension: 3\ncontainer:\n  type: mesh\n  file: " + kOpenMesh + "\n" + kParticles, 0, "container"},
    {"MissingMeshFile", "dimension: 3\ncontainer:\n  type: mesh\n  file: no_such_mesh.stl\n" + kParticles, 4, "container.file"},
    {"UnknownFormatInScene", kGood + "output:\n  - {format: xyz, path: a.csv}\n", 5, "output[0].format"},
    {"UnknownExtensionInScene", kGood + "output:\n  - {path: a.xyz}\n", 5, "output[0].path"},
    {"ZeroParticlesStop", kGood + "stop: {particles: 0}\n", 4, "stop.particles"},
    {"VolumeFractionAboveOne", kGood + "stop:\n  volume_fraction: 1.5\n", 5, "stop.volume_fraction"},
    {"ZeroRadiusPool", kGood + "packer: {radius_pool: 0}\n", 4, "packer.radius_pool"},
    {"UnknownFrontPick", kGood + "packer: {front: biggest}\n", 4, "packer.front"},
    {"SeedPointOutside", kGood + "packer: {seed_point: [5, 5, 5]}\n", 4, "packer.seed_point"},
    {"YamlSyntaxError", kGood + "stop: [1, 2\n", 0, ""},
    {"MissingRequiredKey", "dimension: 3\n" + kParticles, 0, "container"},
};

class CliBadScene : public ::testing::TestWithParam<BadScene> {};

/// Runs `frontpack pack bad.yaml <args>` twice: once with the output absent, once with an
/// existing output, and checks exit code, message and that nothing was written.
void expect_refused(const std::string& scene_text, const std::string& extra_args, const std::string& output,
                    const std::vector<std::string>& must_mention, bool require_line = false) {
  TempDir dir;
  write_bytes(dir.work() / "bad.yaml", scene_text);
  for (bool existing : {false, true}) {
    SCOPED_TRACE(existing ? "output file exists" : "no output file yet");
    const std::string sentinel = "precious data\n\x01\x02 not to be touched\n";
    if (existing) {
      write_bytes(dir.work() / output, sentinel);
    }
    const auto before = listing(dir.work());
    const RunResult r = run_frontpack(dir, "pack bad.yaml " + extra_args);
    EXPECT_EQ(r.exit_code, 2) << "stdout: " << r.out << "\nstderr: " << r.err;
    for (const std::string& s : must_mention) {
      EXPECT_NE(r.err.find(s), std::string::npos) << "'" << s << "' not in: " << r.err;
    }
    if (require_line) {
      EXPECT_TRUE(std::regex_search(r.err, std::regex(R"(bad\.yaml:[1-9]\d*:[1-9]\d*: )"))) << "no line:column in: " << r.err;
    }
    EXPECT_EQ(listing(dir.work()), before) << "files created or removed";
    if (existing) {
      EXPECT_EQ(read_bytes(dir.work() / output), sentinel);
    }
    EXPECT_EQ(r.out, "") << "no summary for a refused run";
  }
}

TEST_P(CliBadScene, RefusedWithLocationAndNothingWritten) {
  const BadScene& b = GetParam();
  std::vector<std::string> mention = {"bad.yaml"};
  if (b.line > 0) mention.push_back("bad.yaml:" + std::to_string(b.line) + ":");
  if (!b.key.empty()) mention.push_back("key '" + b.key);
  // With -o (replaces the scene's outputs) and without (the scene's own outputs).
  expect_refused(b.text, "-o out.csv", "out.csv", mention, true);
  expect_refused(b.text + (b.text.find("output:") == std::string::npos ? "output:\n  - {path: scene_out.csv}\n" : ""), "",
                 "scene_out.csv", mention, true);
}

INSTANTIATE_TEST_SUITE_P(AllBadScenes, CliBadScene, ::testing::ValuesIn(kBadScenes),
                         [](const auto& info) { return info.param.name; });

TEST(CliBadInput, MissingSceneFile) {
  TempDir dir;
  const RunResult r = run_frontpack(dir, "pack no_such_scene.yaml -o out.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no_such_scene.yaml"), std::string::npos) << r.err;
  EXPECT_TRUE(listing(dir.work()).empty());
}

TEST(CliBadInput, SceneIsAFolder) {
  TempDir dir;
  fs::create_directory(dir.work() / "folder.yaml");
  const RunResult r = run_frontpack(dir, "pack folder.yaml -o out.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("folder.yaml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is a folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.work() / "out.csv"));
}

TEST(CliBadInput, UnknownFormatOption) {
  expect_refused(kGood, "--format xyz -o out.csv", "out.csv", {"xyz"});
}

TEST(CliBadInput, UnknownOutputExtension) {
  expect_refused(kGood, "-o out.xyz", "out.xyz", {"out.xyz"});
}

TEST(CliBadInput, OutputFolderDoesNotExist) {
  TempDir dir;
  write_bytes(dir.work() / "good.yaml", kGood);
  const RunResult r = run_frontpack(dir, "pack good.yaml -o no_such_folder/out.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no_such_folder"), std::string::npos) << r.err;
  EXPECT_EQ(listing(dir.work()), (std::set<std::string>{"good.yaml"})) << "the folder must not be created";
}

TEST(CliBadInput, SceneOutputFolderDoesNotExist) {
  expect_refused(kGood + "output:\n  - {path: a.csv}\n  - {path: no_such_folder/b.csv}\n", "", "a.csv",
                 {"no_such_folder"});
}

TEST(CliBadInput, RecordFolderDoesNotExist) {
  // Checked before packing: the packing output is not written either.
  expect_refused(kGood, "-o out.csv --record no_such_folder/rec.json", "out.csv", {"no_such_folder"});
}

TEST(CliBadInput, OutputIsAFolder) {
  TempDir dir;
  write_bytes(dir.work() / "good.yaml", kGood);
  fs::create_directory(dir.work() / "out.csv");
  const RunResult r = run_frontpack(dir, "pack good.yaml -o out.csv");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(fs::is_directory(dir.work() / "out.csv"));
}

}  // namespace
}  // namespace fptest
