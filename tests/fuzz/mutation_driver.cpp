// A fuzzing main for the harnesses of tests/fuzz (LLVMFuzzerTestOneInput) that needs no clang:
// a seeded, deterministic mutation loop (mutator.hpp) over a seed corpus, so the harnesses run in
// the ordinary g++ build and in ctest. Without libFuzzer's coverage feedback it finds less per
// input, but it runs everywhere the tests run.
//
//   fuzz_<target> --corpus DIR [--dict FILE] [--iterations N] [--seconds S] [--seed N]
//                 [--timeout S] [--findings DIR] [--max-len BYTES]
//   fuzz_<target> --replay FILE|DIR ...     run these inputs once each (a folder: all its files)
//
// A finding is any crash of the harness: a violated property (the harness aborts), a signal, a
// sanitizer report, an input running longer than --timeout, or a single allocation beyond
// kAllocationLimit. The input is written to <findings>/<target>-<hash> and the command that
// replays it is printed. Exit status: 0 when every input passed; on a finding the harness's own
// (SIGABRT, a sanitizer's 1, or 1 for a timeout); 2 on bad usage.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "dictionary.hpp"
#include "fuzz_support.hpp"
#include "mutator.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) __attribute__((weak));
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

#if defined(__SANITIZE_ADDRESS__)
#define FP_FUZZ_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FP_FUZZ_ASAN 1
#endif
#endif

namespace {

/// One allocation larger than this, from an input of at most 64 KiB, is a finding (a count or a
/// size taken from the input without a check); libFuzzer's -malloc_limit_mb does the same.
constexpr std::size_t kAllocationLimit = std::size_t(256) << 20;

// What the crash paths need, set before each input (they run in signal handlers: no allocation).
const std::uint8_t* g_input = nullptr;
std::size_t g_input_size = 0;
const char* g_replaying = nullptr;  // the file being replayed, or null while mutating
char g_findings[4096] = ".";
char g_target[256] = "fuzz";
char g_self[4096] = "";
volatile sig_atomic_t g_reported = 0;

void say(const char* text) { (void)!::write(STDERR_FILENO, text, std::strlen(text)); }

/// Saves the current input (async-signal-safe) and says how to replay it.
void report_finding(const char* why) {
  if (g_reported || g_input == nullptr) return;
  g_reported = 1;
  say("\nmutation_driver: finding: ");
  say(why);
  if (g_replaying != nullptr) {
    say(" while replaying ");
    say(g_replaying);
    say("\n");
    return;
  }
  std::uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a of the input names it
  for (std::size_t i = 0; i < g_input_size; ++i) hash = (hash ^ g_input[i]) * 0x100000001b3ULL;
  char path[4096 + 300];
  char hex[17];
  for (int k = 0; k < 16; ++k) hex[k] = "0123456789abcdef"[(hash >> (60 - 4 * k)) & 0xf];
  hex[16] = '\0';
  path[0] = '\0';
  std::strncat(path, g_findings, 4096);
  std::strcat(path, "/");
  std::strncat(path, g_target, 255);
  std::strcat(path, "-");
  std::strcat(path, hex);
  const int fd = ::open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    for (std::size_t done = 0; done < g_input_size;) {
      const ssize_t n = ::write(fd, g_input + done, g_input_size - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::close(fd);
  }
  say("\nmutation_driver: the input is saved as ");
  say(path);
  say("\nmutation_driver: replay it with: ");
  say(g_self);
  say(" --replay ");
  say(path);
  say("\nmutation_driver: once fixed, add it to tests/fuzz/regressions/<target>/ (replayed by ctest)\n");
}

const char* signal_name(int sig) {
  switch (sig) {
    case SIGALRM: return "the input ran longer than --timeout (a hang?)";
    case SIGABRT: return "SIGABRT (a violated property or a failed assertion, above)";
    case SIGSEGV: return "SIGSEGV (invalid memory access)";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE (arithmetic error)";
    case SIGILL: return "SIGILL (illegal instruction, e.g. __builtin_trap)";
    default: return "a signal";
  }
}

void on_signal(int sig) {
  report_finding(signal_name(sig));
  if (sig == SIGALRM) _exit(1);
  signal(sig, SIG_DFL);
  raise(sig);
}

void on_sanitizer_death() { report_finding("a sanitizer report (above)"); }

void install_crash_handlers() {
  static char alternate_stack[1 << 16];  // a stack overflow still gets its report
  stack_t ss{};
  ss.ss_sp = alternate_stack;
  ss.ss_size = sizeof alternate_stack;
  sigaltstack(&ss, nullptr);
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sa.sa_flags = SA_ONSTACK;
  sigemptyset(&sa.sa_mask);
  std::vector<int> signals = {SIGABRT, SIGALRM};
#ifndef FP_FUZZ_ASAN  // under ASan its own handler reports these, then the death callback runs
  signals.insert(signals.end(), {SIGSEGV, SIGBUS, SIGFPE, SIGILL});
#endif
  for (const int sig : signals) sigaction(sig, &sa, nullptr);
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(on_sanitizer_death);
}

struct Options {
  std::vector<std::string> corpus;
  std::string dictionary;
  std::uint64_t iterations = 1000;
  double seconds = 0;  // 0: no time limit
  std::uint64_t seed = 1;
  unsigned timeout = 10;
  std::string findings = "fuzz-findings";
  std::size_t max_len = fp::fuzz::kMaxInputBytes;
  std::vector<std::string> replay;
};

[[noreturn]] void usage(const std::string& problem) {
  std::fprintf(stderr,
               "%s\nusage: %s --corpus DIR [--corpus DIR ...] [--dict FILE] [--iterations N] [--seconds S] [--seed N]\n"
               "          [--timeout S] [--findings DIR] [--max-len BYTES]\n"
               "       %s --replay FILE|DIR ...\n",
               problem.c_str(), g_self, g_self);
  std::exit(2);
}

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage("missing value after " + a);
      return argv[++i];
    };
    auto number = [&]() -> double {
      const std::string v = value();
      char* end = nullptr;
      const double d = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0' || !(d >= 0 && d < 1e19)) usage("bad number '" + v + "' after " + a);
      return d;
    };
    if (a == "--corpus") o.corpus.push_back(value());
    else if (a == "--dict") o.dictionary = value();
    else if (a == "--iterations") o.iterations = static_cast<std::uint64_t>(number());
    else if (a == "--seconds") o.seconds = number();
    else if (a == "--seed") o.seed = static_cast<std::uint64_t>(number());
    else if (a == "--timeout") o.timeout = static_cast<unsigned>(std::max(1.0, number()));
    else if (a == "--findings") o.findings = value();
    else if (a == "--max-len") o.max_len = static_cast<std::size_t>(std::max(1.0, number()));
    else if (a == "--replay") {
      while (i + 1 < argc && std::strncmp(argv[i + 1], "--", 2) != 0) o.replay.emplace_back(argv[++i]);
      if (o.replay.empty()) usage("--replay needs files or folders");
    } else usage("unknown option " + a);
  }
  if (o.replay.empty() && o.corpus.empty()) usage("give --corpus or --replay");
  return o;
}

/// The files of a folder (sorted by name: deterministic), or the file itself. README.md is not
/// an input (it documents the folder).
std::vector<std::string> inputs_at(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) usage("no such file or folder: " + path);
  if (!fs::is_directory(path, ec)) return {path};
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(path))
    if (e.is_regular_file() && e.path().filename() != "README.md") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) usage("cannot read " + path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void run_one(const std::string& input, unsigned timeout) {
  g_input = reinterpret_cast<const std::uint8_t*>(input.data());
  g_input_size = input.size();
  alarm(timeout);
  LLVMFuzzerTestOneInput(g_input, g_input_size);
  alarm(0);
  g_input = nullptr;
}

}  // namespace

#ifndef FP_FUZZ_ASAN
// Outside ASan (which has max_allocation_size_mb, set below) the allocation limit is checked here.
void* operator new(std::size_t size) {
  if (size > kAllocationLimit && g_input != nullptr) {
    char text[96];
    std::snprintf(text, sizeof text, "one allocation of %zu bytes (limit %zu)", size, kAllocationLimit);
    report_finding(text);
    std::abort();
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return operator new(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#else
extern "C" const char* __asan_default_options() { return "max_allocation_size_mb=256:allocator_may_return_null=0"; }
#endif

int main(int argc, char** argv) {
  {
    std::error_code ec;
    const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
    std::snprintf(g_self, sizeof g_self, "%s", ec ? argv[0] : self.c_str());
    std::snprintf(g_target, sizeof g_target, "%s", std::filesystem::path(g_self).filename().c_str());
  }
  const Options o = parse_options(argc, argv);
  if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
  install_crash_handlers();

  if (!o.replay.empty()) {
    std::size_t count = 0;
    for (const auto& path : o.replay)
      for (const auto& file : inputs_at(path)) {
        const std::string input = read_file(file);
        g_replaying = file.c_str();
        run_one(input, o.timeout);
        ++count;
      }
    std::printf("%s: replayed %zu inputs, every one passed\n", g_target, count);
    return 0;
  }

  std::vector<std::string> corpus;
  for (const auto& dir : o.corpus)
    for (const auto& file : inputs_at(dir)) corpus.push_back(read_file(file));
  if (corpus.empty()) usage("the corpus is empty");
  std::vector<std::string> dictionary;
  if (!o.dictionary.empty()) {
    try {
      dictionary = fp::fuzz::read_dictionary(o.dictionary);
    } catch (const std::exception& e) {
      usage(e.what());
    }
  }
  std::filesystem::create_directories(o.findings);
  std::snprintf(g_findings, sizeof g_findings, "%s", std::filesystem::absolute(o.findings).c_str());

  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  for (const auto& input : corpus) run_one(input, o.timeout);  // the seeds themselves must pass
  fp::fuzz::Mutator mutator(o.seed, corpus, dictionary, o.max_len);
  std::uint64_t runs = 0;
  bool out_of_time = false;
  for (; runs < o.iterations; ++runs) {
    if (o.seconds > 0 && (runs & 15) == 0 && elapsed() > o.seconds) {
      out_of_time = true;
      break;
    }
    run_one(mutator.next(), o.timeout);
  }
  std::printf("%s: %zu seeds and %llu mutated inputs (seed %llu) in %.1f s%s, no finding\n", g_target, corpus.size(),
              static_cast<unsigned long long>(runs), static_cast<unsigned long long>(o.seed), elapsed(),
              out_of_time ? " (stopped by --seconds before --iterations)" : "");
  return 0;
}
