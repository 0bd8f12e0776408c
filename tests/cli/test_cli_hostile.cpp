// Hostile input through the command line: every case must end with exit code 2 (bad input) or
// 1 (a failure while running), a message naming the file / line / key or the path, never a
// signal, under 2 s, and with the working folder (inputs included) exactly as it was: same
// names, sizes and bytes. Plus a run killed while it writes: nothing is left behind.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <regex>
#include <thread>

#include "cli_test_util.hpp"

namespace fptest {
namespace {

using Clock = std::chrono::steady_clock;

const std::string kScene =
    "dimension: 3\n"
    "container: {type: box, min: [0, 0, 0], max: [0.1, 0.1, 0.1]}\n"
    "particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n";

/// Every entry under `dir` with its bytes ("<folder>" for folders, "-> target" for links).
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(e.path(), dir).string();
    if (e.is_symlink()) s[name] = "-> " + fs::read_symlink(e.path()).string();
    else if (e.is_directory()) s[name] = "<folder>";
    else s[name] = read_bytes(e.path());
  }
  return s;
}

/// What differs between two snapshots, by name (the bytes themselves would flood the log).
std::string differences(const std::map<std::string, std::string>& before, const std::map<std::string, std::string>& after) {
  std::string out;
  for (const auto& [name, bytes] : after) {
    const auto it = before.find(name);
    if (it == before.end()) out += "  created: " + name + " (" + std::to_string(bytes.size()) + " bytes)\n";
    else if (it->second != bytes) out += "  changed: " + name + "\n";
  }
  for (const auto& [name, bytes] : before)
    if (!after.count(name)) out += "  removed: " + name + "\n";
  return out;
}

// ---- a run killed while it writes --------------------------------------------------------

/// Starts frontpack in dir.work() with stdout/stderr to the capture folder; returns its pid.
pid_t spawn_frontpack(const TempDir& dir, const std::vector<std::string>& args) {
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

TEST(CliHostileSignals, SigintWhileWritingLeavesNoTemporary) { expect_killed_run_leaves_nothing(SIGINT); }

}  // namespace
}  // namespace fptest
