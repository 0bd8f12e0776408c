// `frontpack pack --set` and `frontpack study`: a change given on the command line is the same as
// the scene file changed; a study's runs are the command line's runs (the same packings and
// figures), a study killed and started again keeps what was done, and bad studies are refused
// before anything runs, naming the file, line and key.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <thread>

#include "cli_test_util.hpp"
#include "refusal_check.hpp"

namespace fptest {
namespace {

const char* kBase = R"(dimension: 3
seed: 1
container: {type: box, min: [0, 0, 0], max: [0.15, 0.15, 0.15]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";

/// The rows of a CSV as column -> text (quoted fields are not used by these studies' values).
std::vector<std::map<std::string, std::string>> csv_rows(const std::string& text) {
  const auto lines = lines_of(text);
  std::vector<std::map<std::string, std::string>> rows;
  if (lines.empty()) return rows;
  const auto split = [](const std::string& line) {
    std::vector<std::string> f;
    std::string cell;
    bool quoted = false;
    for (const char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) f.push_back(cell), cell.clear();
      else cell += c;
    }
    f.push_back(cell);
    return f;
  };
  const auto header = split(lines[0]);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto f = split(lines[i]);
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < header.size() && c < f.size(); ++c) row[header[c]] = f[c];
    rows.push_back(row);
  }
  return rows;
}

TEST(CliSet, AChangeOnTheCommandLineIsTheSceneFileChanged) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", kBase);
  std::string edited = kBase;
  edited.replace(edited.find("max: 0.02"), 9, "max: 0.03");
  edited.replace(edited.find("max: [0.15, 0.15, 0.15]"), 23, "max: [0.2, 0.15, 0.15]");
  write_bytes(dir.work() / "e.yaml", edited + "packer: {front: fifo}\n");
  RunResult r = run_frontpack(dir, "pack s.yaml --set particles.radius.max=0.03 --set 'container.max[0]=0.2' --set packer.front=fifo "
                                   "-q -o set.csv --record set.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_frontpack(dir, "pack e.yaml -q -o edited.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(read_bytes(dir.work() / "set.csv").size(), 1000u);
  EXPECT_EQ(read_bytes(dir.work() / "set.csv"), read_bytes(dir.work() / "edited.csv"));
  // The record says what was changed, in order.
  const std::string record = read_bytes(dir.work() / "set.json");
  EXPECT_NE(record.find("\"overrides\": [\n      \"particles.radius.max=0.03\",\n      \"container.max[0]=0.2\",\n      "
                        "\"packer.front=fifo\"\n    ]"),
            std::string::npos)
      << record.substr(0, 600);
  // validate and analyze take the same change: the packing passes against the changed scene only.
  EXPECT_EQ(run_frontpack(dir, "validate set.csv --scene s.yaml -q --set particles.radius.max=0.03 --set 'container.max[0]=0.2'").exit_code, 0);
  EXPECT_EQ(run_frontpack(dir, "validate set.csv --scene s.yaml -q").exit_code, 3);
  // A whole mapping, in YAML's flow form.
  r = run_frontpack(dir, "pack s.yaml --set 'particles={radius: {distribution: constant, value: 0.02}}' -q -o c.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const auto& line : lines_of(read_bytes(dir.work() / "c.csv")))
    if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0]))) EXPECT_NE(line.find(",0.02"), std::string::npos) << line;
}

TEST(CliSet, ABadChangeNamesTheArgumentAndWritesNothing) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", kBase);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--set packer.front=fifoo", "--set packer.front=fifoo: key 'packer.front': unknown value 'fifoo' (did you mean 'fifo'?)"},
      {"--set 'container.min[5]=1'", "key 'container.min[5]': 'container.min' has no item [5] (it has 3)"},
      {"--set particles.radius.mx=0.03", "--set particles.radius.mx=0.03: key 'particles.radius.mx': unknown key (did you mean 'max'?)"},
      {"--set dimension=2", "s.yaml:3:19: key 'container.type': 'box' is a 3D container but the scene has dimension: 2"},
      {"--set dimension=2", "(in the scene as changed by dimension=2)"},
      {"--set foo", "expected KEY=VALUE"},
      {"--set 'a..b=1'", "is not a scene key"},
      {"--set 'packer.front='", "--set packer.front=: key 'packer.front': no value given"},
      {"--set 'stop={particles: [1'", "is not YAML"},
      {"--set 'seed.x=1'", "'seed' is not a mapping, so it has no key 'x'"},
  };
  for (const auto& [args, message] : cases) {
    const RunResult r = run_frontpack(dir, "pack s.yaml -o out.csv " + args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_EQ(listing(dir.work()), (std::set<std::string>{"s.yaml"}));
}

/// A 3 x 3 parameter grid x 3 seeds.
const char* kStudy = R"(scene: base.yaml
seeds: [1, 2, 3]
parameters:
  - key: particles.radius.max
    name: r_max
    values: [0.02, 0.025, 0.03]
  - name: front
    cases:
      closest: {packer.front: closest}
      random: {packer.front: random}
      fifo_flat: {packer.front: fifo, container.max: [0.2, 0.2, 0.1]}
jobs: 2
plots:
  - {x: r_max, y: counters.solves}
)";

TEST(CliStudy, ThreeByThreeByThreeSeedsAreTheCommandLinesRuns) {
  TempDir dir;
  write_bytes(dir.work() / "base.yaml", kBase);
  write_bytes(dir.work() / "s.yaml", kStudy);
  const RunResult list = run_frontpack(dir, "study s.yaml --list");
  EXPECT_EQ(list.exit_code, 0) << list.err;
  EXPECT_NE(list.out.find("to run  r_max=0.025,front=fifo_flat,seed=2\n"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("27 runs, 0 kept from before, 27 to run"), std::string::npos) << list.out;
  EXPECT_FALSE(fs::exists(dir.work() / "s.out"));  // listed, nothing run or made
  const RunResult r = run_frontpack(dir, "study s.yaml");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("27 runs (0 kept from before, 27 run now), 0 invalid, 0 incomplete, 0 failed"), std::string::npos) << r.out;
  const auto rows = csv_rows(read_bytes(dir.work() / "s.out/results.csv"));
  const auto full = csv_rows(read_bytes(dir.work() / "s.out/results-full.csv"));
  ASSERT_EQ(rows.size(), 27u);
  ASSERT_EQ(full.size(), 27u);
  // The grid in order (the last parameter fastest, then the seeds), each run checked against
  // the same change given to `frontpack pack`: the same packing, byte for byte, and the CSV's
  // figures are its record's.
  const char* fronts[] = {"closest", "random", "fifo_flat"};
  const char* changes[] = {"--set packer.front=closest", "--set packer.front=random",
                           "--set packer.front=fifo --set 'container.max=[0.2, 0.2, 0.1]'"};
  const char* r_max[] = {"0.02", "0.025", "0.03"};
  std::size_t i = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int seed = 1; seed <= 3; ++seed, ++i) {
        const auto& row = rows[i];
        const std::string name = std::string("r_max=") + r_max[a] + ",front=" + fronts[b] + ",seed=" + std::to_string(seed);
        EXPECT_EQ(row.at("run"), name);
        EXPECT_EQ(row.at("r_max"), r_max[a]);
        EXPECT_EQ(row.at("front"), fronts[b]);
        EXPECT_EQ(row.at("seed"), std::to_string(seed));
        EXPECT_EQ(row.at("status"), "ok");
        const RunResult p = run_frontpack(dir, std::string("pack base.yaml -q -o p.csv --record p.json --seed ") + std::to_string(seed) +
                                                   " --set particles.radius.max=" + r_max[a] + " " + changes[b]);
        ASSERT_EQ(p.exit_code, 0) << p.err;
        EXPECT_EQ(read_bytes(dir.work() / "p.csv"), read_bytes(dir.work() / "s.out/runs" / name / "packing.csv")) << name;
        // The full table holds the record's figures exactly; the short one to 5 significant digits.
        const std::string record = read_bytes(dir.work() / "p.json");
        const double vf = record_number(record, "volume_fraction_container");
        EXPECT_EQ(std::stod(full[i].at("metrics.volume_fraction_container")), vf) << name;
        EXPECT_EQ(std::stod(full[i].at("metrics.mean_coordination")), record_number(record, "mean_coordination")) << name;
        EXPECT_EQ(std::stoul(row.at("n")), static_cast<unsigned long>(record_number(record, "n"))) << name;
        char five[32];
        std::snprintf(five, sizeof five, "%.5g", vf);
        EXPECT_EQ(row.at("metrics.volume_fraction_container"), five) << name;
      }
  // The standard figures and the one asked for, when matplotlib is there.
  if (!fs::exists("/usr/bin/python3") || std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0) {
    GTEST_SKIP() << "figures not checked: /usr/bin/python3 with matplotlib is missing";
  }
  for (const char* figure : {"r_max.png", "front.png", "rate_vs_vf.png", "counters.solves_vs_r_max.png"}) {
    const std::string png = read_bytes(dir.work() / "s.out/plots" / figure);
    EXPECT_GT(png.size(), 10000u) << figure;
    EXPECT_EQ(png.substr(0, 4), "\x89PNG") << figure;
  }
}

ino_t inode(const fs::path& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 ? st.st_ino : 0;
}

TEST(CliStudy, KilledAndStartedAgainItKeepsWhatWasDone) {
  TempDir dir;
  write_bytes(dir.work() / "base.yaml", kBase);
  // Nine runs of some 0.2 s each, one at a time: the study is killed in the middle.
  write_bytes(dir.work() / "s.yaml", "scene: base.yaml\nseeds: 3\njobs: 1\nparameters:\n  - key: container.max\n"
                                     "    values: [[0.4, 0.4, 0.4], [0.45, 0.4, 0.4], [0.5, 0.4, 0.4]]\n");
  write_bytes(dir.work() / "whole.yaml", "scene: base.yaml\nseeds: 3\noutput: whole\nparameters:\n  - key: container.max\n"
                                         "    values: [[0.4, 0.4, 0.4], [0.45, 0.4, 0.4], [0.5, 0.4, 0.4]]\n");
  const std::string start = "cd " + quoted(dir.work().string()) + " && setsid " + quoted(frontpack_binary()) +
                            " study s.yaml --no-plots > first.txt 2>&1 < /dev/null & echo $! > " + quoted((dir.capture() / "pid").string());
  ASSERT_EQ(std::system(start.c_str()), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const pid_t pid = std::stoi(read_bytes(dir.capture() / "pid"));
  const auto records = [&] {
    std::vector<fs::path> done;
    if (fs::exists(dir.work() / "s.out/runs"))
      for (const auto& e : fs::directory_iterator(dir.work() / "s.out/runs"))
        if (fs::exists(e.path() / "record.json")) done.push_back(e.path() / "record.json");
    return done;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (records().size() < 3 && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(-pid, SIGKILL);  // the study and the run it was waiting for
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const std::vector<fs::path> before = records();
  ASSERT_GE(before.size(), 3u);
  ASSERT_LT(before.size(), 9u) << "the study ended before it was killed: make its runs longer";
  std::map<fs::path, ino_t> inodes;
  for (const auto& p : before) inodes[p] = inode(p);
  // The table so far has the runs that had ended (the last one may have ended unseen), no others.
  const auto so_far = csv_rows(read_bytes(dir.work() / "s.out/results.csv"));
  EXPECT_GE(so_far.size() + 1, before.size());
  EXPECT_LE(so_far.size(), before.size());
  for (const auto& row : so_far) EXPECT_EQ(row.at("status"), "ok") << row.at("run");

  const RunResult again = run_frontpack(dir, "study s.yaml --no-plots");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("9 runs (" + std::to_string(before.size()) + " kept from before, " + std::to_string(9 - before.size()) + " run now)"),
            std::string::npos)
      << again.out;
  for (const auto& [p, ino] : inodes) EXPECT_EQ(inode(p), ino) << p << " was written again";
  // What it ends with is what an uninterrupted study gives: the same packings.
  ASSERT_EQ(run_frontpack(dir, "study whole.yaml --no-plots -q").exit_code, 0);
  const auto rows = csv_rows(read_bytes(dir.work() / "s.out/results.csv"));
  const auto whole = csv_rows(read_bytes(dir.work() / "whole/results.csv"));
  ASSERT_EQ(rows.size(), 9u);
  ASSERT_EQ(whole.size(), 9u);
  for (std::size_t i = 0; i < 9; ++i) {
    EXPECT_EQ(rows[i].at("run"), whole[i].at("run"));
    EXPECT_EQ(rows[i].at("metrics.volume_fraction_container"), whole[i].at("metrics.volume_fraction_container"));
    EXPECT_EQ(read_bytes(dir.work() / "s.out/runs" / rows[i].at("run") / "packing.csv"),
              read_bytes(dir.work() / "whole/runs" / rows[i].at("run") / "packing.csv"));
  }
  // A third start keeps all; a changed base scene keeps none.
  EXPECT_NE(run_frontpack(dir, "study s.yaml --no-plots").out.find("9 runs (9 kept from before, 0 run now)"), std::string::npos);
  write_bytes(dir.work() / "base.yaml", std::string(kBase) + "packer: {front: fifo}\n");
  EXPECT_NE(run_frontpack(dir, "study s.yaml --no-plots").out.find("9 runs (0 kept from before, 9 run now)"), std::string::npos);
}

TEST(CliStudy, KillingTheStudyStopsItsRunsAndLeavesNoTemporary) {
  TempDir dir;
  // A name no other test uses: the runs are found by their command line (pgrep -f).
  write_bytes(dir.work() / "base-sigterm.yaml", kBase);
  // Runs of about a second (some 60,000 spheres each), two at once, killed as soon as they start.
  write_bytes(dir.work() / "s.yaml", "scene: base-sigterm.yaml\nseeds: 2\njobs: 2\nparameters:\n  - key: container.max\n"
                                     "    values: [[1.5, 1, 1], [1.6, 1, 1]]\n");
  // SIGTERM to the study's process only (not its group): it passes the signal on to its runs.
  const std::string start = "cd " + quoted(dir.work().string()) + " && { " + quoted(frontpack_binary()) +
                            " study s.yaml --no-plots > first.txt 2>&1 < /dev/null & echo $! > " +
                            quoted((dir.capture() / "pid").string()) + "; }";
  ASSERT_EQ(std::system(start.c_str()), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const pid_t pid = std::stoi(read_bytes(dir.capture() / "pid"));
  const auto runs_alive = [&] {
    // [b]: the shell running pgrep has the pattern in its own command line, not what it matches
    return std::system("pgrep -f 'frontpack pack [b]ase-sigterm.yaml' > /dev/null") == 0;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!runs_alive() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(runs_alive()) << "no run started";
  ::kill(pid, SIGTERM);
  const auto stop = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  const auto study_alive = [&] {  // a zombie (no one may reap it in a container) counts as ended
    const std::string stat = read_bytes("/proc/" + std::to_string(pid) + "/stat");
    const auto close = stat.rfind(')');
    return close != std::string::npos && close + 2 < stat.size() && stat[close + 2] != 'Z';
  };
  while ((study_alive() || runs_alive()) && std::chrono::steady_clock::now() < stop)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(runs_alive()) << "a run outlived the study";
  std::size_t records = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir.work() / "s.out")) {
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path() << " left behind";
    records += e.path().filename() == "record.json";
  }
  EXPECT_EQ(records, 0u) << "the runs went on to their end";
  const RunResult again = run_frontpack(dir, "study s.yaml --no-plots --list");
  EXPECT_NE(again.out.find("4 runs, 0 kept from before, 4 to run"), std::string::npos) << again.out;
}

TEST(CliStudy, AParameterMayChangeTheBaseSceneItself) {
  TempDir dir;
  fs::create_directories(dir.work() / "scenes");
  write_bytes(dir.work() / "scenes/a.yaml", kBase);
  write_bytes(dir.work() / "scenes/b.yaml", "dimension: 2\ncontainer: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
                                            "particles: {radius: {distribution: uniform, min: 0.02, max: 0.03}}\n");
  fs::create_directories(dir.work() / "studies");
  write_bytes(dir.work() / "studies/s.yaml", "scene: ../scenes/a.yaml\nparameters:\n  - name: scene\n    cases:\n"
                                             "      a: {scene: ../scenes/a.yaml}\n      b-fifo: {scene: ../scenes/b.yaml, packer.front: fifo}\n"
                                             "  - key: packer.radius_pool\n    values: [1, 2]\n");
  const RunResult r = run_frontpack(dir, "study studies/s.yaml --no-plots");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(read_bytes(dir.work() / "studies/s.out/results-full.csv"));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].at("dimension"), "3");
  EXPECT_EQ(rows[2].at("dimension"), "2");
  for (const auto& row : rows) {
    const bool b = row.at("scene") == "b-fifo";
    const RunResult p = run_frontpack(dir, std::string("pack scenes/") + (b ? "b" : "a") + ".yaml -q -o p.csv --set packer.radius_pool=" +
                                                row.at("packer.radius_pool") + (b ? " --set packer.front=fifo" : ""));
    ASSERT_EQ(p.exit_code, 0) << p.err;
    EXPECT_EQ(read_bytes(dir.work() / "p.csv"), read_bytes(dir.work() / "studies/s.out/runs" / row.at("run") / "packing.csv")) << row.at("run");
  }
  // A run's record is of its own base scene: changing b.yaml reruns b's runs only.
  write_bytes(dir.work() / "scenes/b.yaml", read_bytes(dir.work() / "scenes/b.yaml") + "seed: 5\n");
  EXPECT_NE(run_frontpack(dir, "study studies/s.yaml --no-plots").out.find("4 runs (2 kept from before, 2 run now)"), std::string::npos);
}

TEST(CliStudy, ABadStudyIsRefusedBeforeAnyRun) {
  TempDir dir;
  write_bytes(dir.work() / "base.yaml", kBase);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"scene: base.yaml\nseed: 3\n", "s.yaml:2:1: key 'seed': unknown key (did you mean 'seeds'?)"},
      {"scene: nothere.yaml\n", "nothere.yaml"},
      {"scene: base.yaml\nparameters:\n  - key: packer.front\n    values: [closest, fifoo]\n",
       "s.yaml:4:23: key 'packer.front': unknown value 'fifoo' (did you mean 'fifo'?)"},
      {"scene: base.yaml\nparameters:\n  - key: packer.front\n    values: [closest, fifoo]\n", "run front=fifoo,seed=1"},
      {"scene: base.yaml\nparameters:\n  - name: c\n    cases:\n      a: {particles.radius.max: -1}\n",
       "s.yaml:5:33: key 'particles.radius.max': must be positive"},
      {"scene: base.yaml\nparameters:\n  - key: packer.front\n    values: [fifo, fifo]\n", "the value 'fifo' is given twice"},
      {"scene: base.yaml\nparameters:\n  - key: a..b\n    values: [1]\n", "s.yaml:3:10: key 'parameters[0].key': 'a..b' is not a scene key"},
      {"scene: base.yaml\nseeds: 0\n", "a count of seeds is 1 .."},
      {"scene: base.yaml\nplots: [{x: nope, y: n}]\n", "'nope' is not one of the study's parameters"},
  };
  for (const auto& [study, message] : cases) {
    write_bytes(dir.work() / "s.yaml", study);
    const RunResult r = run_frontpack(dir, "study s.yaml");
    EXPECT_EQ(r.exit_code, 2) << study << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << study << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir.work() / "s.out/runs")) << study;
  }
}

// A study never writes over what it reads: its table, figures or a run's files on the base scene
// (or the study file) are refused before anything is written, the folder as it was.
TEST(CliStudy, AnOutputThatIsAnInputIsRefusedAndNothingChanges) {
  const auto with = [](const std::string& scene_at, const std::string& study_at, const std::string& study) {
    return [=](const fs::path& w) {
      fs::create_directories((w / scene_at).parent_path());
      fs::create_directories((w / study_at).parent_path());
      write_bytes(w / scene_at, kBase);
      write_bytes(w / study_at, study);
    };
  };
  // The base scene kept as the study's own table (it used to be replaced, and the study exit 0).
  expect_refused(with("o/results.csv", "s.yaml", "scene: o/results.csv\noutput: o\n"), "study s.yaml", 2,
                 {"results table 'o/results.csv' is the scene file 'o/results.csv'", "run seed=1",
                  "frontpack never writes over what it reads"});
  expect_refused(with("o/results.csv", "s.yaml", "scene: o/results.csv\noutput: o\n"), "study s.yaml --no-plots --list", 2,
                 {"results table 'o/results.csv' is the scene file"});
  // A run's record (removed before the run starts), its log and its packing.
  for (const char* file : {"record.json", "log.txt", "packing.csv"})
    expect_refused(with(std::string("o/runs/seed=1/") + file, "s.yaml", std::string("scene: o/runs/seed=1/") + file + "\noutput: o\n"),
                   "study s.yaml --no-plots", 2, {std::string("'o/runs/seed=1/") + file + "' is the scene file"});
  // The study file itself, and a scene in the figures' folder (the script names the figures).
  expect_refused(with("base.yaml", "o/results.csv", "scene: ../base.yaml\noutput: .\n"), "study o/results.csv", 2,
                 {"results table 'o/results.csv' is the study file 'o/results.csv'"});
  expect_refused(with("o/plots/base.yaml", "s.yaml", "scene: o/plots/base.yaml\noutput: o\n"), "study s.yaml", 2,
                 {"the figures' folder 'o/plots' holds the scene file 'o/plots/base.yaml'"});
  // Through another name of the same file: a hard link.
  expect_refused(
      [&](const fs::path& w) {
        with("base.yaml", "s.yaml", "scene: base.yaml\noutput: o\n")(w);
        fs::create_directories(w / "o");
        fs::create_hard_link(w / "base.yaml", w / "o/results.csv");
      },
      "study s.yaml", 2, {"results table 'o/results.csv' is the scene file 'base.yaml'"});
  // An output folder that is a file, or under one ("Not a directory", exit 1, after the checks).
  for (const char* output : {"afile", "afile/sub"})
    expect_refused(
        [&](const fs::path& w) {
          with("base.yaml", "s.yaml", std::string("scene: base.yaml\noutput: ") + output + "\n")(w);
          write_bytes(w / "afile", "not a folder\n");
        },
        "study s.yaml --no-plots", 2, {"afile' is a file, not a folder; give 'output:' a folder"});
}

TEST(CliStudy, AFailedRunIsReportedAndTheOthersKept) {
  TempDir dir;
  write_bytes(dir.work() / "base.yaml", kBase);
  // r_max 0.2 cannot fit the box: refused by the scene check before any run.
  write_bytes(dir.work() / "s.yaml", "scene: base.yaml\nparameters:\n  - key: particles.radius.max\n    values: [0.02, 0.2]\n");
  RunResult r = run_frontpack(dir, "study s.yaml --no-plots");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(fs::exists(dir.work() / "s.out/runs"));
  // A run that fails while running (its packing cannot be written: a folder is in the way) is
  // a row with its message; the study exits 1 and the other runs are there.
  write_bytes(dir.work() / "s.yaml", "scene: base.yaml\nparameters:\n  - key: particles.radius.max\n    values: [0.02, 0.025]\n");
  fs::create_directories(dir.work() / "s.out/runs/max=0.025,seed=1/packing.csv");
  r = run_frontpack(dir, "study s.yaml --no-plots");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("1 of 2 runs failed"), std::string::npos) << r.err;
  const auto rows = csv_rows(read_bytes(dir.work() / "s.out/results.csv"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("status"), "ok");
  EXPECT_EQ(rows[1].at("status"), "failed");
  EXPECT_NE(rows[1].at("message").find("exit"), std::string::npos) << rows[1].at("message");
}

// A run that places nearly nothing (a stacking with every try at 0: exit 4) is a row marked
// incomplete with its reason; the study exits 4.
TEST(CliStudy, AnIncompleteRunIsMarkedSo) {
  TempDir dir;
  write_bytes(dir.work() / "base.yaml", std::string(kBase) + "target: {solid_fraction: 0.4}\n");
  write_bytes(dir.work() / "s.yaml",
              "scene: base.yaml\nparameters:\n  - key: packer\n    values: ['{method: stacking}', '{method: stacking, random_tries: 0, "
              "near_tries: 0, two_contact_tries: 0, nuclei: 0, voids: false}']\n    name: stacking\n");
  const RunResult r = run_frontpack(dir, "study s.yaml --no-plots");
  EXPECT_EQ(r.exit_code, 4) << r.out << r.err;
  EXPECT_NE(r.out.find("0 invalid, 1 incomplete, 0 failed"), std::string::npos) << r.out;
  const auto rows = csv_rows(read_bytes(dir.work() / "s.out/results.csv"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("status"), "ok") << rows[0].at("message");
  EXPECT_EQ(rows[1].at("status"), "incomplete");
  EXPECT_NE(rows[1].at("message").find("the graded stacking placed"), std::string::npos) << rows[1].at("message");
}

// A number put into a list and into a computed value: the runs are those of `pack --set` with
// the values written out, their names read as the values do, the plots get a numeric axis for a
// list of numbers, and results.csv holds the main figures (results-full.csv every one).
TEST(CliStudy, AValuePutIntoListsAndExpressionsIsTheCommandLinesRun) {
  TempDir dir;
  write_bytes(dir.work() / "base.yaml", kBase);
  write_bytes(dir.work() / "s.yaml", "scene: base.yaml\n"
                                     "parameters:\n"
                                     "  - name: ratio\n"
                                     "    values: [1.5, 2]\n"
                                     "    set:\n"
                                     "      particles.radius: {distribution: uniform, min: 0.01, max: '${0.01 * ratio}'}\n"
                                     "  - key: container.max\n"
                                     "    values: [[0.15, 0.15, 0.15], [0.15, 0.15, 0.2]]\n");
  const RunResult r = run_frontpack(dir, "study s.yaml");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("s.out/results.csv (main figures; every figure in s.out/results-full.csv)"), std::string::npos) << r.out;
  const std::string short_text = read_bytes(dir.work() / "s.out/results.csv");
  EXPECT_EQ(lines_of(short_text).at(0),
            "run,ratio,container.max,seed,status,n,metrics.volume_fraction_container,metrics.volume_fraction_core,"
            "metrics.volume_fraction_reference_sphere,metrics.mean_coordination,metrics.rattler_fraction,"
            "metrics.max_overlap_over_smaller_radius,metrics.particles_per_second,timings.pack,message");
  const auto rows = csv_rows(short_text);
  const auto full = csv_rows(read_bytes(dir.work() / "s.out/results-full.csv"));
  ASSERT_EQ(rows.size(), 4u);
  ASSERT_EQ(full.size(), 4u);
  EXPECT_GT(full[0].size(), 3 * rows[0].size());  // every counter, timing and figure of the analysis
  const char* names[] = {"ratio=1.5,max=0.15_0.15_0.15,seed=1", "ratio=1.5,max=0.15_0.15_0.2,seed=1",
                         "ratio=2,max=0.15_0.15_0.15,seed=1", "ratio=2,max=0.15_0.15_0.2,seed=1"};
  const char* r_max[] = {"0.015", "0.015", "0.02", "0.02"};
  const char* box[] = {"[0.15, 0.15, 0.15]", "[0.15, 0.15, 0.2]", "[0.15, 0.15, 0.15]", "[0.15, 0.15, 0.2]"};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(rows[i].at("run"), names[i]);
    EXPECT_EQ(rows[i].at("container.max"), box[i]);
    EXPECT_EQ(full[i].at("run"), names[i]);
    EXPECT_NEAR(std::stod(rows[i].at("metrics.volume_fraction_container")), std::stod(full[i].at("metrics.volume_fraction_container")), 5e-5);
    const RunResult p = run_frontpack(dir, std::string("pack base.yaml -q -o p.csv --set particles.radius.max=") + r_max[i] +
                                               " --set 'container.max=" + box[i] + "'");
    ASSERT_EQ(p.exit_code, 0) << p.err;
    EXPECT_EQ(read_bytes(dir.work() / "p.csv"), read_bytes(dir.work() / "s.out/runs" / names[i] / "packing.csv")) << names[i];
  }
  // The plots' axis: the ratio's numbers, and the box's one varying entry.
  const std::string request = read_bytes(dir.work() / "s.out/plots.json");
  EXPECT_NE(request.find("\"axis_label\": \"container.max [0.15, 0.15, x]\""), std::string::npos) << request;
  EXPECT_NE(request.find("\"axis\": [\n        0.15,\n        0.2\n      ]"), std::string::npos) << request;
  EXPECT_NE(request.find("\"axis\": [\n        1.5,\n        2.0\n      ]"), std::string::npos) << request;
}

}  // namespace
}  // namespace fptest
