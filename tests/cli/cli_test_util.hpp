#pragma once
// Drives the built `frontpack` binary: each run gets the working folder it is given and its
// stdout/stderr captured to files in a separate folder (so stderr is never a terminal and the
// working folder holds only what frontpack wrote).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <cmath>
#include <string>
#include <vector>

namespace fptest {

namespace fs = std::filesystem;

inline std::string frontpack_binary() { return std::string(FRONTPACK_BINARY_DIR) + "/cli/frontpack"; }
inline std::string source_path(const std::string& relative) { return std::string(FRONTPACK_SOURCE_DIR) + "/" + relative; }

inline std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void write_bytes(const fs::path& p, const std::string& s) {
  std::ofstream out(p, std::ios::binary);
  out << s;
  ASSERT_TRUE(out.good()) << p;
}

/// A fresh folder under the system temp folder, removed with everything in it at the end.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "frontpack-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    if (info) name += std::string("-") + info->name();
    for (char& c : name)
      if (c == '/') c = '_';
    path_ = fs::temp_directory_path() / name;
    fs::remove_all(path_);
    fs::create_directories(path_ / "work");
    fs::create_directories(path_ / "capture");
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// Where frontpack runs and writes.
  fs::path work() const { return path_ / "work"; }
  fs::path capture() const { return path_ / "capture"; }

 private:
  fs::path path_;
};

/// frontpack's exit code for a valid packing that is not the packing of the container its scene
/// asks for: a stop (time, particle count, volume fraction) ended the front before it filled the
/// container, a target was missed, or the packer placed nearly nothing.
inline constexpr int kIncomplete = 4;

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

/// Single-quotes an argument for /bin/sh.
inline std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// Runs a Python check (Debian's python3, which has vtk and json) with the file paths as argv.
inline int python_check(const std::string& code, const std::vector<fs::path>& args) {
  std::string cmd = "/usr/bin/python3 -c " + quoted(code);
  for (const auto& a : args) cmd += " " + quoted(a.string());
  return std::system(cmd.c_str());
}

/// Runs `frontpack <args>` in dir.work(), after the shell command `before` if one is given (e.g.
/// "ulimit -v 1000000"); args are already quoted where needed.
inline RunResult run_frontpack(const TempDir& dir, const std::string& args, const std::string& before = "") {
  const fs::path out = dir.capture() / "stdout", err = dir.capture() / "stderr";
  const std::string cmd = "cd " + quoted(dir.work().string()) + " && " + (before.empty() ? "" : before + " && ") +
                          quoted(frontpack_binary()) + " " + args +
                          " > " + quoted(out.string()) + " 2> " + quoted(err.string()) + " < /dev/null";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_bytes(out);
  r.err = read_bytes(err);
  return r;
}

/// Names of the entries of a folder (recursively), for "nothing else was created" checks.
inline std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) names.insert(fs::relative(e.path(), dir).string());
  return names;
}

/// The number after `"key": ` in a run record's text (its first occurrence); NaN when absent.
inline double record_number(const std::string& record, const std::string& key) {
  const std::string quoted = "\"" + key + "\": ";
  const auto at = record.find(quoted);
  return at == std::string::npos ? std::nan("") : std::stod(record.substr(at + quoted.size()));
}

/// `frontpack pack bad.yaml -o out.csv` on `scene`: refused with exit 2, `message` on stderr,
/// nothing written.
inline void expect_refused(const TempDir& dir, const std::string& scene, const std::string& message) {
  write_bytes(dir.work() / "bad.yaml", scene);
  const RunResult r = run_frontpack(dir, "pack bad.yaml -o out.csv");
  EXPECT_EQ(r.exit_code, 2) << scene;
  EXPECT_NE(r.err.find(message), std::string::npos) << scene << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.work() / "out.csv")) << scene;
}

/// Splits text into lines (without the newline characters).
inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// Whitespace- or comma-separated doubles of a line; false if any field is not a number.
bool parse_numbers(const std::string& line, char separator, std::vector<double>& out);

}  // namespace fptest
