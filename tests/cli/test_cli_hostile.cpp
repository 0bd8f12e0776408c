// Hostile input through the command line: every case must end with exit code 2 (bad input) or
// 1 (a failure while running), a message naming the file / line / key or the path, never a
// signal, under 2 s, and with the working folder (inputs included) exactly as it was: same
// names, sizes and bytes. Plus a run killed while it writes: nothing is left behind.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <map>
#include <regex>
#include <thread>

#include "cli_test_util.hpp"
#include "refusal_check.hpp"

namespace fptest {
namespace {

using Clock = std::chrono::steady_clock;

const std::string kScene =
    "dimension: 3\n"
    "container: {type: box, min: [0, 0, 0], max: [0.1, 0.1, 0.1]}\n"
    "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n";

/// Starts frontpack in dir.work() with stdout/stderr to the capture folder, and with a file
/// size limit (RLIMIT_FSIZE, bytes) if one is given; returns its pid.
pid_t spawn_frontpack(const TempDir& dir, const std::vector<std::string>& args, rlim_t file_size_limit = 0) {
  const std::string out = (dir.capture() / "stdout").string(), err = (dir.capture() / "stderr").string();
  const std::string binary = frontpack_binary(), work = dir.work().string();
  std::vector<std::string> argv_s = {binary};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  const pid_t pid = fork();
  if (pid == 0) {
    // The test runner's dispositions must not leak in (an ignored SIGINT stays ignored).
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (o < 0 || e < 0 || chdir(work.c_str()) != 0) _exit(127);
    if (file_size_limit > 0) {
      const rlimit limit{file_size_limit, file_size_limit};
      if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(127);
    }
    dup2(o, 1);
    dup2(e, 2);
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(binary.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

/// A folder holding the scene `s.yaml` (kScene + `extra`) and whatever `more` adds.
auto with_scene(const std::string& extra = "", std::function<void(const fs::path&)> more = {}) {
  return [=](const fs::path& w) {
    write_bytes(w / "s.yaml", kScene + extra);
    write_bytes(w / "old.csv", "an existing output, not to be touched\n");
    if (more) more(w);
  };
}

const std::string kCapsules =
    "dimension: 3\n"
    "container: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
    "particles:\n  - {shape: spherocylinder, aspect_ratio: 0.5, size: {distribution: uniform, min: 0.1, max: 0.2}}\n";
const std::string kBallShapes =
    "dimension: 3\n"
    "container: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
    "particles:\n  - {shape: sphere, size: {distribution: uniform, min: 0.1, max: 0.2}}\n";

TEST(CliHostileOutputs, OutputIsTheScene) {
  expect_refused(with_scene(), "pack s.yaml -o s.yaml --format csv", 2, {"'s.yaml'", "scene file", "option -o"});
}

TEST(CliHostileOutputs, OutputIsTheSceneThroughDotDot) {
  expect_refused(with_scene("", [](const fs::path& w) { fs::create_directory(w / "sub"); }),
                 "pack s.yaml -o sub/../s.yaml --format csv", 2, {"'sub/../s.yaml'", "scene file"});
}

TEST(CliHostileOutputs, OutputIsTheSceneThroughASymbolicLink) {
  expect_refused(with_scene("", [](const fs::path& w) { fs::create_symlink("s.yaml", w / "link.csv"); }),
                 "pack s.yaml -o link.csv", 2, {"'link.csv'", "scene file"});
}

TEST(CliHostileOutputs, OutputIsTheSceneThroughAHardLink) {
  expect_refused(with_scene("", [](const fs::path& w) { fs::create_hard_link(w / "s.yaml", w / "hard.csv"); }),
                 "pack s.yaml -o hard.csv", 2, {"'hard.csv'", "scene file"});
}

TEST(CliHostileOutputs, SceneOutputListNamesTheScene) {
  expect_refused(with_scene("output:\n  - {path: old.csv}\n  - {format: csv, path: ./s.yaml}\n"), "pack s.yaml", 2,
                 {"s.yaml:6:", "key 'output[1].path'", "output 's.yaml' is the scene file", "scene file"});
}

TEST(CliHostileOutputs, OutputIsTheContainerMesh) {
  const std::string mesh = "dimension: 3\ncontainer: {type: mesh, file: cube.stl}\n"
                           "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n";
  expect_refused(
      [&](const fs::path& w) {
        write_bytes(w / "m.yaml", mesh);
        fs::copy_file(source_path("tests/data/meshes/cube.stl"), w / "cube.stl");
      },
      "pack m.yaml -o cube.stl --format csv", 2, {"'cube.stl'", "mesh file", "container.file"});
}

TEST(CliHostileOutputs, TwoOutputsAreTheSameFile) {
  expect_refused(with_scene("output:\n  - {path: old.csv}\n  - {path: sub/../old.csv}\n",
                            [](const fs::path& w) { fs::create_directory(w / "sub"); }),
                 "pack s.yaml", 2, {"s.yaml:6:", "key 'output[1].path'", "same file as output 'old.csv'"});
}

TEST(CliHostileOutputs, TwoNewOutputsAreTheSameFile) {
  expect_refused(with_scene("output:\n  - {path: new.csv}\n  - {format: yade, path: ./new.csv}\n"), "pack s.yaml", 2,
                 {"s.yaml:6:", "output 'new.csv' is the same file as output 'new.csv'"});
}

TEST(CliHostileOutputs, RecordIsAnOutput) {
  expect_refused(with_scene(), "pack s.yaml -o old.csv --record ./old.csv", 2, {"option --record", "'./old.csv'", "same file"});
}

TEST(CliHostileOutputs, OutputIsTheSurfacesSideFileOfAnother) {
  expect_refused(
      [](const fs::path& w) {
        write_bytes(w / "c.yaml", kCapsules + "output:\n  - {path: c.vtu}\n  - {path: c.surfaces.vtu}\n");
      },
      "pack c.yaml", 2, {"c.yaml:6:", "'c.surfaces.vtu'", "side file of output 'c.vtu'"});
}

TEST(CliHostileOutputs, OutputIsTheMultisphereSideFileOfAnother) {
  expect_refused(
      [](const fs::path& w) {
        write_bytes(w / "b.yaml", kBallShapes + "output:\n  - {path: b.multisphere.txt}\n  - {path: b.data}\n");
      },
      "pack b.yaml", 2, {"b.yaml:6:", "'b.multisphere.txt'", "side file of output 'b.data'"});
}

TEST(CliHostileOutputs, RecordIsASideFile) {
  expect_refused([](const fs::path& w) { write_bytes(w / "c.yaml", kCapsules); }, "pack c.yaml -o c.vtu --record c.surfaces.vtu",
                 2, {"option --record", "'c.surfaces.vtu'", "side file of output 'c.vtu'"});
}

TEST(CliHostileOutputs, SideFileIsTheScene) {
  expect_refused([](const fs::path& w) { write_bytes(w / "c.surfaces.vtu", kCapsules); }, "pack c.surfaces.vtu -o c.vtu", 2,
                 {"'c.surfaces.vtu'", "side file", "scene file"});
}

TEST(CliHostileOutputs, NulByteInAnOutputPath) {
  expect_refused(with_scene("output:\n  - {path: \"a\\0b.csv\"}\n"), "pack s.yaml", 2,
                 {"s.yaml:5:", "key 'output[0].path'", "NUL"});
}

TEST(CliHostileOutputs, NulByteInTheMeshPath) {
  const std::string mesh = "dimension: 3\ncontainer: {type: mesh, file: \"cube.stl\\0.off\"}\n"
                           "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n";
  expect_refused(
      [&](const fs::path& w) {
        write_bytes(w / "m.yaml", mesh);
        fs::copy_file(source_path("tests/data/meshes/cube.stl"), w / "cube.stl");
      },
      "pack m.yaml -o out.csv", 2, {"m.yaml:2:", "key 'container.file'", "NUL"});
}

TEST(CliHostileOutputs, FileNameLongerThanNameMax) {
  const std::string name = std::string(300, 'x') + ".csv";
  expect_refused(with_scene(), "pack s.yaml -o " + name, 2, {"'" + name + "'", "NAME_MAX"});
}

TEST(CliHostileOutputs, FileNameThatLeavesNoRoomForTheTemporary) {
  const std::string name = std::string(246, 'x') + ".csv";  // 250 bytes: legal, but "<name>.tmp-<pid>" is not
  expect_refused(with_scene(), "pack s.yaml -o " + name, 2, {"'" + name + "'", "temporary"});
}

TEST(CliHostileOutputs, FolderNameLongerThanNameMax) {
  const std::string name = std::string(300, 'd') + "/a.csv";
  expect_refused(with_scene(), "pack s.yaml -o " + name, 2, {"'" + name + "'", "folder name", "NAME_MAX"});
}

TEST(CliHostileOutputs, PathLongerThanPathMax) {
  std::string name;
  while (name.size() < 4200) name += "d/";
  name += "a.csv";
  expect_refused(with_scene(), "pack s.yaml -o " + name, 2, {"PATH_MAX"});
}

TEST(CliHostileOutputs, RecordNameLongerThanNameMax) {
  const std::string name = std::string(300, 'r') + ".json";
  expect_refused(with_scene(), "pack s.yaml -o a.csv --record " + name, 2, {"option --record", "NAME_MAX"});
}

TEST(CliHostileOutputs, OutputFolderNotWritable) {
  if (access("/proc/self", W_OK) == 0) GTEST_SKIP() << "/proc/self is writable here";
  expect_refused(with_scene(), "pack s.yaml -o old.csv --record /proc/self/r.json", 2, {"'/proc/self'", "not writable"});
}

TEST(CliHostileOutputs, OutputIsNotARegularFile) {
  expect_refused(with_scene("", [](const fs::path& w) { ASSERT_EQ(mkfifo((w / "fifo.csv").c_str(), 0644), 0); }),
                 "pack s.yaml -o fifo.csv", 2, {"'fifo.csv'", "not a regular file"});
}

TEST(CliHostileOutputs, OutputInAFileInsteadOfAFolder) {
  expect_refused(with_scene(), "pack s.yaml -o old.csv/a.csv", 2, {"'old.csv'", "not a folder"});
}

TEST(CliHostileOutputs, MoreOutputsThanCanBeWrittenAtOnce) {
  std::string list = "output:\n";
  for (int k = 0; k < 200; ++k) list += "  - {path: o" + std::to_string(k) + ".csv}\n";
  expect_refused(with_scene(list), "pack s.yaml", 2, {"s.yaml:", "key 'output[128].path'", "at most 128"});
}

TEST(CliHostileOutputs, AnalyzeJsonIsThePacking) {
  expect_refused([](const fs::path& w) { write_bytes(w / "g.csv", "id,x,y,z,r\n0,0.5,0.5,0.5,0.1\n1,0.8,0.5,0.5,0.1\n"); },
                 "analyze g.csv --json g.csv", 2, {"option --json", "'g.csv'", "packing file"});
}

TEST(CliHostileOutputs, AnalyzeJsonIsTheScene) {
  expect_refused(with_scene("", [](const fs::path& w) {
                   write_bytes(w / "g.csv", "id,x,y,z,r\n0,0.05,0.05,0.05,0.015\n");
                 }),
                 "analyze g.csv --scene s.yaml --json ./s.yaml", 2, {"option --json", "'./s.yaml'", "scene file"});
}

TEST(CliHostileOutputs, AnalyzePlotWouldReplaceThePacking) {
  expect_refused(
      [](const fs::path& w) {
        fs::create_directory(w / "figs");
        write_bytes(w / "figs" / "rdf.png", "id,x,y,z,r\n0,0.5,0.5,0.5,0.1\n1,0.8,0.5,0.5,0.1\n");
      },
      "analyze figs/rdf.png --format csv --plots figs", 2, {"option --plots", "'figs/rdf.png'", "packing file"});
}

TEST(CliHostileOutputs, AnalyzeJsonIsAPlot) {
  expect_refused(
      [](const fs::path& w) {
        fs::create_directory(w / "figs");
        write_bytes(w / "g.csv", "id,x,y,z,r\n0,0.5,0.5,0.5,0.1\n1,0.8,0.5,0.5,0.1\n");
      },
      "analyze g.csv --plots figs --json figs/vf_curve.png", 2, {"option --plots", "same file as analysis JSON"});
}

// ---- inputs that are not scene files ----------------------------------------------------

TEST(CliHostileInputs, SceneIsDevZero) {
  expect_refused([](const fs::path&) {}, "pack /dev/zero -o a.csv", 2, {"/dev/zero", "not a regular file"});
}

TEST(CliHostileInputs, SceneIsAPipe) {
  expect_refused([](const fs::path& w) { ASSERT_EQ(mkfifo((w / "s.yaml").c_str(), 0644), 0); }, "pack s.yaml -o a.csv", 2,
                 {"s.yaml", "not a regular file"});
}

// 100 MB under an unknown key: yaml-cpp would build the list for over a minute, then run out
// of memory; the size cap refuses it before reading.
TEST(CliHostileInputs, SceneOfHundredMegabytes) {
  expect_refused(
      [](const fs::path& w) {
        std::string text = kScene + "junk: [";
        text.reserve(100u << 20);
        while (text.size() < (100u << 20)) text += "1, ";
        write_bytes(w / "s.yaml", text + "1]\n");
      },
      "pack s.yaml -o a.csv", 2, {"s.yaml", "limited to 16 MiB"});
}

TEST(CliHostileInputs, MeshIsDevZero) {
  expect_refused(with_scene("", [](const fs::path& w) {
                   write_bytes(w / "m.yaml", "dimension: 3\ncontainer: {type: mesh, file: /dev/zero}\n"
                                             "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n");
                 }),
                 "pack m.yaml -o a.csv", 2, {"m.yaml:2:", "key 'container.file'", "/dev/zero", "not a regular file"});
}

TEST(CliHostileInputs, AnalyzedPackingIsDevZero) {
  expect_refused([](const fs::path&) {}, "analyze /dev/zero --format csv", 2, {"/dev/zero", "not a regular file"});
}

TEST(CliHostileInputs, ValidatedPackingIsAPipe) {
  expect_refused(with_scene("", [](const fs::path& w) { ASSERT_EQ(mkfifo((w / "p.csv").c_str(), 0644), 0); }),
                 "validate p.csv --scene s.yaml", 2, {"p.csv", "not a regular file"});
}

// ---- names the file system refuses, everywhere a path is taken ---------------------------

TEST(CliHostileNames, SceneNameLongerThanNameMax) {
  const std::string name = std::string(300, 's') + ".yaml";
  expect_refused([](const fs::path&) {}, "pack " + name + " -o a.csv", 2, {name, "cannot read the scene file"});
}

TEST(CliHostileNames, PackingNameLongerThanNameMax) {
  const std::string name = std::string(300, 'p') + ".csv";
  expect_refused(with_scene(), "validate " + name + " --scene s.yaml", 2, {name});
  expect_refused(with_scene(), "analyze " + name, 2, {name});
}

TEST(CliHostileNames, PlotsFolderNameLongerThanNameMax) {
  expect_refused(with_scene("", [](const fs::path& w) { write_bytes(w / "g.csv", "id,x,y,z,r\n0,0.5,0.5,0.5,0.1\n"); }),
                 "analyze g.csv --plots " + std::string(300, 'f'), 2, {"option --plots", "does not exist"});
}

// A run-time failure (exit 1): the interpreter cannot exist; nothing is drawn, nothing is left.
TEST(CliHostileNames, PythonPathLongerThanNameMax) {
  expect_refused(
      [](const fs::path& w) {
        write_bytes(w / "g.csv", "id,x,y,z,r\n0,0.5,0.5,0.5,0.1\n1,0.8,0.5,0.5,0.1\n");
        fs::create_directory(w / "figs");
      },
      "analyze g.csv -q --plots figs --python /" + std::string(300, 'y'), 1, {"no plots", "not found"});
}

// ---- meshes --------------------------------------------------------------------------------

const std::string kCubeVertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
const std::string kCubeFaces = "3 0 3 2\n3 0 2 1\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n"
                               "3 4 5 6\n3 4 6 7\n";

/// A folder with m.yaml filling the mesh `file`, written with `text` (or copied from tests/data/meshes).
auto with_mesh(const std::string& file, const std::string& text) {
  return [=](const fs::path& w) {
    write_bytes(w / "m.yaml", "dimension: 3\ncontainer: {type: mesh, file: " + file +
                                  "}\nparticles: {radius: {distribution: uniform, min: 0.1, max: 0.2}}\n");
    if (text.empty()) fs::copy_file(source_path("tests/data/meshes/" + file), w / file);
    else write_bytes(w / file, text);
  };
}

TEST(CliHostileMeshes, OffVertexLineWithAnExtraNumber) {
  std::string v = kCubeVertices;
  v.replace(v.find("1 1 0\n"), 6, "1 1 0 5\n");
  expect_refused(with_mesh("c.off", "OFF\n8 12 0\n" + v + kCubeFaces), "pack m.yaml -o a.csv", 2,
                 {"m.yaml:2:", "'c.off'", "line 5:", "vertex 2 has 4 numbers"});
}

TEST(CliHostileMeshes, OffHeaderClaimingTwoBillionVertices) {
  expect_refused(with_mesh("c.off", "OFF\n2000000000 12 0\n" + kCubeVertices + kCubeFaces), "pack m.yaml -o a.csv", 2,
                 {"'c.off'", "line 2:", "2000000000 vertices"});
}

TEST(CliHostileMeshes, SelfIntersectingMesh) {
  expect_refused(with_mesh("self_intersecting.off", ""), "pack m.yaml -o a.csv", 2,
                 {"m.yaml:2:", "key 'container'", "'self_intersecting.off'", "intersects itself"});
}

TEST(CliHostileMeshes, TwoClosedMeshesThatOverlap) {
  expect_refused(with_mesh("overlapping_cubes.off", ""), "pack m.yaml -o a.csv", 2,
                 {"m.yaml:2:", "'overlapping_cubes.off'", "intersects itself"});
}

TEST(CliHostileMeshes, TheCubeItselfIsAccepted) {  // the cases above differ from it by one token
  TempDir dir;
  with_mesh("c.off", "OFF\n8 12 0\n" + kCubeVertices + kCubeFaces)(dir.work());
  const RunResult r = run_frontpack(dir, "pack m.yaml -q -o a.csv");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// ---- seeds ---------------------------------------------------------------------------------

TEST(CliHostileSeeds, SeedBeyondTwoToTheSixtyFour) {
  expect_refused(with_scene(), "pack s.yaml -o a.csv --seed 18446744073709551616", 2, {"--seed", "2^64-1"});
  expect_refused(with_scene(), "pack s.yaml -o a.csv --seed 99999999999999999999999", 2, {"--seed", "2^64-1"});
}

TEST(CliHostileSeeds, HexadecimalSeedRefusedOnTheCommandLineAndInTheScene) {
  expect_refused(with_scene(), "pack s.yaml -o a.csv --seed 0x10", 2, {"--seed", "decimal", "0x10"});
  expect_refused(with_scene("seed: 0x10\n"), "pack s.yaml -o a.csv", 2, {"s.yaml:4:", "key 'seed'"});
}

TEST(CliHostileSeeds, LeadingZerosAreDecimalOnTheCommandLineAndInTheScene) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", kScene);
  write_bytes(dir.work() / "z.yaml", kScene + "seed: 042\n");
  ASSERT_EQ(run_frontpack(dir, "pack s.yaml -q --seed 042 -o a.csv --record a.json").exit_code, 0);
  ASSERT_EQ(run_frontpack(dir, "pack s.yaml -q --seed 42 -o b.csv").exit_code, 0);
  ASSERT_EQ(run_frontpack(dir, "pack z.yaml -q -o c.csv --record c.json").exit_code, 0);
  ASSERT_EQ(run_frontpack(dir, "pack s.yaml -q --seed 34 -o octal.csv").exit_code, 0);
  EXPECT_NE(read_bytes(dir.work() / "a.json").find("\"seed\": 42,"), std::string::npos);
  EXPECT_NE(read_bytes(dir.work() / "c.json").find("\"seed\": 42,"), std::string::npos);
  EXPECT_EQ(read_bytes(dir.work() / "a.csv"), read_bytes(dir.work() / "b.csv"));
  EXPECT_EQ(read_bytes(dir.work() / "c.csv"), read_bytes(dir.work() / "b.csv"));
  EXPECT_NE(read_bytes(dir.work() / "octal.csv"), read_bytes(dir.work() / "b.csv")) << "seeds 34 and 42 must differ";
}

// A VTU whose NumberOfPoints makes the byte counts wrap round 2^64 to those of one particle:
// the reader compared the wrapped sizes and then reserved 2^61 particles.
TEST(CliHostileInputs, VtuWithANumberOfPointsThatWrapsRound) {
  expect_refused(
      [](const fs::path& w) {
        write_bytes(w / "one.yaml", kScene + "stop: {particles: 1}\n");
        ASSERT_EQ(std::system(("cd " + quoted(w.string()) + " && " + quoted(frontpack_binary()) +
                               " pack one.yaml -q -o one.vtu").c_str()),
                  kIncomplete << 8);  // system()'s status: exit 4, the count stop
        std::string vtu = read_bytes(w / "one.vtu");
        const std::string one = "NumberOfPoints=\"1\"";
        ASSERT_NE(vtu.find(one), std::string::npos);
        vtu.replace(vtu.find(one), one.size(), "NumberOfPoints=\"2305843009213693953\"");  // 2^61 + 1
        write_bytes(w / "crafted.vtu", vtu);
        fs::remove(w / "one.vtu");
      },
      "analyze crafted.vtu", 2, {"crafted.vtu", "runs past the end"});
}

// ---- several outputs, one of which cannot be written -------------------------------------

// The second output passes the file-size limit (what a full disk does); the first one, complete
// by then, must not replace the existing file either: all or nothing.
TEST(CliHostileOutputs, OutputSetIsAllOrNothing) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml",
              "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
              "particles: {radius: {distribution: uniform, min: 0.02, max: 0.04}}\nstop: {particles: 2000}\n"
              "output:\n  - {path: o.vtu}\n  - {path: o.data}\n");
  write_bytes(dir.work() / "o.vtu", "an older packing\n");
  const auto before = snapshot(dir.work());
  // vtu: 57 bytes per particle, lammps: about 90.
  const pid_t pid = spawn_frontpack(dir, {"pack", "s.yaml", "-q", "--record", "o.record.json"}, 150 * 1000);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  const std::string err = read_bytes(dir.capture() / "stderr");
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 1) << err;
  EXPECT_NE(err.find("'o.data'"), std::string::npos) << err;
  EXPECT_NE(err.find("write error"), std::string::npos) << err;
  const auto after = snapshot(dir.work());
  EXPECT_TRUE(after == before) << differences(before, after);
}

// ---- a run killed while it writes --------------------------------------------------------

bool has_temporary(const fs::path& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

// A packing of tens of thousands of spheres in five formats: the write phase takes tens of
// milliseconds, during which the temporaries exist. The test polls for them, then sends the
// signal; a run that finished first is repeated with more particles.
void expect_killed_run_leaves_nothing(int sig) {
  TempDir dir;
  for (std::uint64_t n = 30000; n <= 240000; n *= 2) {
    SCOPED_TRACE("particles " + std::to_string(n));
    for (const auto& e : fs::directory_iterator(dir.work())) fs::remove_all(e.path());
    write_bytes(dir.work() / "big.yaml",
                "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
                "particles: {radius: {distribution: uniform, min: 0.004, max: 0.008}}\n"
                "stop: {particles: " + std::to_string(n) + "}\n"
                "output:\n  - {path: o.vtu}\n  - {path: o.json}\n  - {path: o.csv}\n  - {path: o.txt}\n"
                "  - {path: o.data}\n");
    write_bytes(dir.work() / "o.csv", "an older packing, not to be touched\n");
    const auto before = snapshot(dir.work());
    const pid_t pid = spawn_frontpack(dir, {"pack", "big.yaml", "-q", "--record", "o.record.json"});
    ASSERT_GT(pid, 0);
    bool signalled = false;
    int status = 0;
    const auto deadline = Clock::now() + std::chrono::seconds(120);
    for (;;) {
      const pid_t w = waitpid(pid, &status, WNOHANG);
      ASSERT_NE(w, -1);
      if (w == pid) break;
      if (!signalled && has_temporary(dir.work())) {
        ASSERT_EQ(kill(pid, sig), 0);
        signalled = true;
      }
      if (Clock::now() > deadline) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        FAIL() << "frontpack did not finish";
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    const auto after = snapshot(dir.work());
    if (!signalled || !WIFSIGNALED(status)) {
      ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_bytes(dir.capture() / "stderr");
      continue;  // finished before the temporaries were seen, or before the signal arrived
    }
    EXPECT_EQ(WTERMSIG(status), sig) << "killed by the signal it was sent, as without a handler";
    if (after.count("o.vtu")) {
      // The signal came after the renames (they run with the signal held): every output is new.
      for (const char* f : {"o.vtu", "o.json", "o.txt", "o.data", "o.record.json"}) EXPECT_TRUE(after.count(f)) << f;
      EXPECT_FALSE(has_temporary(dir.work()));
      continue;
    }
    EXPECT_TRUE(after == before) << differences(before, after);
    return;
  }
  FAIL() << "never caught frontpack while it was writing";
}

TEST(CliHostileSignals, SigtermWhileWritingLeavesNoTemporary) { expect_killed_run_leaves_nothing(SIGTERM); }

// The command line's own refusals in frontpack's words: one "frontpack: error:" line, the
// option named, a long value cut to its first 80 characters; nothing written.
TEST(CliHostileParser, RefusalsInOurWords) {
  expect_refused(with_scene(), "pack s.yaml -o a.csv -o b.csv --format csv", 2,
                 {"frontpack: error: --format names the format of one -o", "from its extension"});
  expect_refused(with_scene(), "pack s.yaml -o a.csv -o ./a.csv", 2, {"is the same file as output 'a.csv'"});
  expect_refused(with_scene(), "pack s.yaml --seed 1 --seed 2 -o a.csv", 2, {"frontpack: error: --seed is given 2 times; it takes one"});
  expect_refused(with_scene(), "pack", 2, {"frontpack: error: missing the argument SCENE"});
  expect_refused(with_scene(), "pack s.yaml extra", 2, {"frontpack: error: unexpected argument extra", "frontpack pack --help"});
  expect_refused(with_scene(), "pack s.yaml --nonsense", 2, {"frontpack: error: unexpected argument --nonsense"});
  expect_refused(with_scene(), "pack s.yaml -j 99999", 2, {"frontpack: error: --threads must be from 0 to 4096 (got 99999)"});
  expect_refused(with_scene(), "validate old.csv", 2, {"frontpack: error: missing the option --scene"});
  for (const char* bad : {"nan", "-1", "inf", "1e400", "0.5x"})
    expect_refused(with_scene(), std::string("validate old.csv --scene s.yaml --tolerance ") + bad, 2,
                   {"frontpack: error: --tolerance", "a number in [0, 1)"});
  expect_refused(with_scene(), "analyze old.csv --tolerance nan", 2, {"frontpack: error: --tolerance"});
}

TEST(CliHostileParser, LongValuesAreCut) {
  const std::string x(100000, 'x');  // below one argument's limit (128 KiB)
  for (const std::string& arg : {"--set " + x, "--set seed=" + x, "--set 'seed=[" + x + "'"}) {
    TempDir dir;
    with_scene()(dir.work());
    const RunResult r = run_frontpack(dir, "pack s.yaml " + arg);
    EXPECT_EQ(r.exit_code, 2) << arg.substr(0, 20);
    EXPECT_NE(r.err.find("characters)"), std::string::npos) << r.err.substr(0, 300);
    EXPECT_LT(r.err.size(), 1000u) << r.err.substr(0, 300);
  }
}

TEST(CliHostileParser, SecondYamlDocumentsAreRefused) {
  expect_refused(with_scene("---\nseed: 2\n"), "pack s.yaml -o new.csv", 2,
                 {"s.yaml:5:1", "a second YAML document (after '---')"});
  expect_refused(with_scene(), "pack s.yaml -o new.csv --set 'seed=1\n---\nseed: 2'", 2,
                 {"second YAML document", "give one value"});
}

TEST(CliHostileSignals, SigintWhileWritingLeavesNoTemporary) { expect_killed_run_leaves_nothing(SIGINT); }

}  // namespace
}  // namespace fptest
