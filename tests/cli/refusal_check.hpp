#pragma once
// The checks of a refused run (hostile input, limits): exit code, message, no summary, under 2 s,
// and the working folder (inputs included) byte for byte as it was.
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "cli_test_util.hpp"

namespace fptest {

/// Every entry under `dir` with its bytes ("<folder>" for folders, "-> target" for links).
inline std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(e.path(), dir).string();
    if (e.is_symlink()) s[name] = "-> " + fs::read_symlink(e.path()).string();
    else if (e.is_directory()) s[name] = "<folder>";
    else if (!e.is_regular_file()) s[name] = "<special>";  // a FIFO would block a read
    else s[name] = read_bytes(e.path());
  }
  return s;
}

/// What differs between two snapshots, by name (the bytes themselves would flood the log).
inline std::string differences(const std::map<std::string, std::string>& before, const std::map<std::string, std::string>& after) {
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

/// Runs `frontpack <args>` in a folder prepared by `setup` (after the shell command `before`,
/// e.g. "ulimit -v 1000000", if one is given), and checks the refusal: exit code, every
/// `mention` in stderr, no summary, under 2 s, and the folder byte for byte as before.
template <typename Setup>
void expect_refused(Setup setup, const std::string& args, int exit_code, const std::vector<std::string>& mention,
                    const std::string& before_run = "") {
  TempDir dir;
  setup(dir.work());
  const auto before = snapshot(dir.work());
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const RunResult r = run_frontpack(dir, args, before_run);
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  EXPECT_EQ(r.exit_code, exit_code) << "(-1: killed by a signal) stderr: " << r.err;
  for (const std::string& m : mention) EXPECT_NE(r.err.find(m), std::string::npos) << "'" << m << "' not in: " << r.err;
  for (const char* internal : {"std::", "filesystem error", "filesystem_error", "bad_alloc", "YAML::", "CGAL", "terminate called"})
    EXPECT_EQ(r.err.find(internal), std::string::npos) << "internal name in: " << r.err;
  EXPECT_EQ(r.out, "") << "no summary for a refused run";
  EXPECT_LT(seconds, 2.0);
  const auto after = snapshot(dir.work());
  EXPECT_TRUE(after == before) << differences(before, after);
}

}  // namespace fptest
