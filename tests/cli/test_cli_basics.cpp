// `frontpack` as a user meets it: --version, --help, usage errors, the summary on stdout and a
// silent stderr when it is not a terminal.
#include <gtest/gtest.h>

#include <regex>

#include "cli_test_util.hpp"
#include "frontpack/version.hpp"

namespace fptest {
namespace {

const char* kSmallScene = R"(dimension: 3
seed: 1
container: {type: box, min: [0, 0, 0], max: [0.15, 0.15, 0.15]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";

TEST(CliBasics, VersionExitsZero) {
  TempDir dir;
  const RunResult r = run_frontpack(dir, "--version");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(std::string("frontpack ") + fp::kVersion), std::string::npos) << r.out;
}

TEST(CliBasics, HelpExitsZeroAndListsPack) {
  TempDir dir;
  for (const char* args : {"--help", "-h"}) {
    const RunResult r = run_frontpack(dir, args);
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
    EXPECT_NE(r.out.find("pack"), std::string::npos) << args << ": " << r.out;
  }
  const RunResult r = run_frontpack(dir, "pack --help");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* option : {"--seed", "--format", "--output", "--record", "--quiet", "--progress", "--threads"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option << " not in: " << r.out;
}

TEST(CliBasics, UsageErrorsExitTwo) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", kSmallScene);
  for (const char* args : {"", "bogus", "bogus s.yaml", "pack", "pack s.yaml --bogus", "pack s.yaml --seed abc",
                           "pack s.yaml --format csv", "pack s.yaml extra.yaml"}) {
    const RunResult r = run_frontpack(dir, args);
    EXPECT_EQ(r.exit_code, 2) << "frontpack " << args << "\nstderr: " << r.err;
    EXPECT_FALSE(r.err.empty()) << "frontpack " << args << ": no message";
  }
  // Nothing was written by any of them.
  EXPECT_EQ(listing(dir.work()), (std::set<std::string>{"s.yaml"}));
  // A mistyped command is named, with the list of commands.
  const RunResult r = run_frontpack(dir, "pakc s.yaml");
  EXPECT_NE(r.err.find("unknown command 'pakc'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("pack"), std::string::npos) << r.err;
}

TEST(CliBasics, NegativeSeedIsRefused) {
  // A seed is an unsigned 64-bit integer; -1 must not silently become 2^64 - 1.
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", kSmallScene);
  const RunResult r = run_frontpack(dir, "pack s.yaml --seed -1 -o out.csv");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_FALSE(fs::exists(dir.work() / "out.csv"));
}

TEST(CliBasics, SummaryOnStdoutNothingOnStderr) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", kSmallScene);
  const RunResult r = run_frontpack(dir, "pack s.yaml --seed 5 -o out.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "") << "stderr is not a terminal: no progress line, no message";

  // The particle count printed is the number of rows written.
  const auto rows = lines_of(read_bytes(dir.work() / "out.csv"));
  ASSERT_GE(rows.size(), 2u);
  const std::size_t n = rows.size() - 1;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(particles\s+(\d+))"))) << r.out;
  EXPECT_EQ(std::stoul(m[1]), n);
  EXPECT_NE(r.out.find("seed 5"), std::string::npos);
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(VF container\s+0\.\d{4})"))) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(coordination z\s+\d+\.\d+ \()"))) << r.out;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(max overlap / gap\s+(\S+) /)"))) << r.out;
  EXPECT_LE(std::stod(m[1]), 1e-9);
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(time\s+pack \d+\.\d+ s)"))) << r.out;
  EXPECT_NE(r.out.find("out.csv"), std::string::npos);
}

TEST(CliBasics, QuietPrintsNothing) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", kSmallScene);
  const RunResult r = run_frontpack(dir, "pack s.yaml -q -o out.csv");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(fs::exists(dir.work() / "out.csv"));
}

// Several -o in one run: each file in the format of its extension, the scene before or after
// them; the packing the same in every file (the csv and the json's particles agree).
TEST(CliBasics, SeveralOutputsEachInTheFormatOfItsExtension) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", "dimension: 3\nseed: 4\ncontainer: {type: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}\n"
                                     "particles: {radius: {distribution: uniform, min: 0.02, max: 0.03}}\n");
  const RunResult r = run_frontpack(dir, "pack -o p.csv s.yaml -o p.vtu -o p.json");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  for (const char* line : {"output         p.csv (csv)", "output         p.vtu (vtu)", "output         p.json (json)"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
  EXPECT_EQ(read_bytes(dir.work() / "p.vtu").rfind("<?xml", 0), 0u);
  EXPECT_NE(read_bytes(dir.work() / "p.json").find("\"particles\""), std::string::npos);
  ASSERT_EQ(run_frontpack(dir, "pack s.yaml -q -o alone.csv").exit_code, 0);
  EXPECT_EQ(read_bytes(dir.work() / "alone.csv"), read_bytes(dir.work() / "p.csv"));
}

// One rule for relative paths: a path written in the scene file (its outputs, its mesh) is
// relative to the scene file's folder; a path on the command line to the working directory.
TEST(CliBasics, PathsInTheSceneAreTheScenesAndOnTheCommandLineTheWorkingDirectorys) {
  TempDir dir;
  fs::create_directories(dir.work() / "scenes" / "out");
  fs::create_directories(dir.work() / "elsewhere");
  fs::copy_file(source_path("tests/data/meshes/cube.stl"), dir.work() / "scenes" / "cube.stl");
  write_bytes(dir.work() / "scenes" / "s.yaml", "dimension: 3\nseed: 4\ncontainer: {type: mesh, file: cube.stl, scale: 0.2}\n"
                                                "particles: {radius: {distribution: uniform, min: 0.02, max: 0.03}}\n"
                                                "output:\n  - {path: out/p.csv}\n  - {path: ../top.csv}\n");
  // From the repository's root, from the scene's folder and from a third one: the same files.
  for (const char* from : {".", "scenes", "elsewhere"}) {
    const std::string scene = std::string(from) == "." ? "scenes/s.yaml" : std::string(from) == "scenes" ? "s.yaml" : "../scenes/s.yaml";
    const RunResult r = run_frontpack(dir, "pack " + scene, std::string("cd ") + from);
    ASSERT_EQ(r.exit_code, 0) << from << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("out/p.csv (csv)"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(dir.work() / "scenes" / "out" / "p.csv")) << from;
    EXPECT_TRUE(fs::exists(dir.work() / "top.csv")) << from;
    if (std::string(from) != "scenes") EXPECT_FALSE(fs::exists(dir.work() / from / "out")) << from;
    EXPECT_EQ(read_bytes(dir.work() / "scenes" / "out" / "p.csv"), read_bytes(dir.work() / "top.csv"));
    fs::remove(dir.work() / "scenes" / "out" / "p.csv");
    fs::remove(dir.work() / "top.csv");
  }
  // -o and --record: the working directory's.
  const RunResult r = run_frontpack(dir, "pack ../scenes/s.yaml -o here.csv --record here.json", "cd elsewhere");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.work() / "elsewhere" / "here.csv"));
  EXPECT_TRUE(fs::exists(dir.work() / "elsewhere" / "here.json"));
  EXPECT_FALSE(fs::exists(dir.work() / "scenes" / "here.csv"));
}

TEST(CliBasics, ProgressFlagWritesToStderrOnly) {
  // --progress forces the progress line even into a file; it appears every 0.5 s, and the
  // time limit keeps the run at 0.8 s (which leaves the packing incomplete).
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", R"(dimension: 3
container: {type: box, min: [0, 0, 0], max: [3, 3, 3]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
stop: {time: 0.8}
)");
  const RunResult r = run_frontpack(dir, "pack s.yaml --progress -o out.csv");
  EXPECT_EQ(r.exit_code, kIncomplete) << r.err;
  EXPECT_NE(r.err.find("packed"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("packed "), std::string::npos);
}

TEST(CliBasics, RunRecordIsWritten) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", kSmallScene);
  const RunResult r = run_frontpack(dir, "pack s.yaml -q -o out.csv --record rec.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string py = "import json,sys; d=json.load(open(sys.argv[1])); "
                         "assert d['seed'] == 1 and d['n'] > 0 and 'particles' not in d, d.keys()";
  EXPECT_EQ(std::system(("/usr/bin/python3 -c " + quoted(py) + " " + quoted((dir.work() / "rec.json").string())).c_str()), 0);
}

TEST(CliBasics, ThreadsWriteTheSameBytesForEveryCount) {
  // -j 2 and -j 3 grow the same blocks, and -j 1 too when the scene gives the block edge. Each
  // run validates its packing (exit 0); the record counts the blocks.
  TempDir dir;
  const std::string plain = R"(dimension: 3
seed: 3
container: {type: box, min: [0, 0, 0], max: [0.4, 0.4, 0.4]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";
  write_bytes(dir.work() / "plain.yaml", plain);
  write_bytes(dir.work() / "s.yaml", plain + "packer: {block_edge: 0.16}\n");
  const RunResult a = run_frontpack(dir, "pack s.yaml -j 2 -q -o a.csv --record a.json");
  const RunResult b = run_frontpack(dir, "pack s.yaml --threads 3 -q -o b.csv");
  const RunResult c = run_frontpack(dir, "pack s.yaml -j 1 -q -o c.csv");
  const RunResult d = run_frontpack(dir, "pack plain.yaml -q -o d.csv");
  for (const RunResult* r : {&a, &b, &c, &d}) ASSERT_EQ(r->exit_code, 0) << r->err;
  EXPECT_EQ(read_bytes(dir.work() / "a.csv"), read_bytes(dir.work() / "b.csv"));
  EXPECT_EQ(read_bytes(dir.work() / "a.csv"), read_bytes(dir.work() / "c.csv"));
  EXPECT_NE(read_bytes(dir.work() / "a.csv"), read_bytes(dir.work() / "d.csv")) << "-j 1 is the single front";
  EXPECT_NE(read_bytes(dir.work() / "a.json").find("\"blocks\": 8"), std::string::npos);
  // A negative or absurd thread count is a usage error; nothing is written.
  for (const char* args : {"pack s.yaml -j -1 -o x.csv", "pack s.yaml -j 99999 -o x.csv", "pack s.yaml -j two -o x.csv"}) {
    const RunResult r = run_frontpack(dir, args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir.work() / "x.csv"));
}

}  // namespace
}  // namespace fptest
