#include "core/io/temp_file_registry.hpp"

#include <limits.h>  // PATH_MAX
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace fp {
namespace {

enum SlotState : int { kFree = 0, kFilling = 1, kFile = 2, kFolder = 3 };

// Lock-free atomics are safe to read from a signal handler; a slot becomes visible to the
// handler only once its path is complete (kFilling -> kFile/kFolder, release).
static_assert(std::atomic<int>::is_always_lock_free);
std::atomic<int> g_state[kMaxTempPaths];
char g_path[kMaxTempPaths][PATH_MAX];

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

// Child processes (a study's runs), 0 = free: the signal is passed on to each.
static_assert(std::atomic<pid_t>::is_always_lock_free);
std::atomic<pid_t> g_child[kMaxChildProcesses];

void signal_children(int sig) noexcept {
  for (auto& c : g_child)
    if (const pid_t pid = c.load(std::memory_order_acquire); pid > 0) ::kill(pid, sig);
}

void remove_all_now() noexcept {
  // Files first, then folders (which are empty once their files are gone), newest first.
  for (const int kind : {kFile, kFolder})
    for (int i = kMaxTempPaths - 1; i >= 0; --i)
      if (g_state[i].load(std::memory_order_acquire) == kind) {
        if (kind == kFile) ::unlink(g_path[i]);
        else ::rmdir(g_path[i]);
        g_state[i].store(kFree, std::memory_order_release);
      }
}

extern "C" void on_cleanup_signal(int sig) {
  const int saved_errno = errno;
  signal_children(sig);  // they clean up after themselves the same way
  remove_all_now();
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  errno = saved_errno;
  // Still blocked inside the handler: delivered with the default action as the handler returns.
  ::raise(sig);
}

sigset_t cleanup_signal_set() {
  sigset_t set;
  sigemptyset(&set);
  for (int s : kSignals) sigaddset(&set, s);
  return set;
}

}  // namespace

int register_temp_path(const std::string& path, bool folder) {
  if (path.size() >= PATH_MAX) throw std::runtime_error("path longer than PATH_MAX: '" + path + "'");
  for (int i = 0; i < kMaxTempPaths; ++i) {
    int expected = kFree;
    if (!g_state[i].compare_exchange_strong(expected, kFilling, std::memory_order_acq_rel)) continue;
    std::memcpy(g_path[i], path.c_str(), path.size() + 1);
    g_state[i].store(folder ? kFolder : kFile, std::memory_order_release);
    return i;
  }
  throw std::runtime_error("more than " + std::to_string(kMaxTempPaths) + " temporary files at once (for '" + path + "')");
}

void unregister_temp_path(int slot) noexcept {
  if (slot >= 0 && slot < kMaxTempPaths) g_state[slot].store(kFree, std::memory_order_release);
}

void remove_registered_temp_paths() noexcept { remove_all_now(); }

int register_child_process(pid_t pid) {
  for (int i = 0; i < kMaxChildProcesses; ++i) {
    pid_t expected = 0;
    if (g_child[i].compare_exchange_strong(expected, pid, std::memory_order_acq_rel)) return i;
  }
  throw std::runtime_error("more than " + std::to_string(kMaxChildProcesses) + " child processes at once");
}

void unregister_child_process(int slot) noexcept {
  if (slot >= 0 && slot < kMaxChildProcesses) g_child[slot].store(0, std::memory_order_release);
}

void install_temp_file_cleanup() {
  static std::atomic<bool> installed{false};
  if (installed.exchange(true)) return;
  struct sigaction sa {};
  sa.sa_handler = on_cleanup_signal;
  sa.sa_mask = cleanup_signal_set();  // one cleanup at a time
  for (int s : kSignals) {
    struct sigaction old {};
    if (::sigaction(s, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(s, &sa, nullptr);
  }
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  ::sigaction(SIGXFSZ, &ignore, nullptr);
}

CleanupSignalsBlocked::CleanupSignalsBlocked() {
  const sigset_t set = cleanup_signal_set();
  pthread_sigmask(SIG_BLOCK, &set, &previous_);
}

CleanupSignalsBlocked::~CleanupSignalsBlocked() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }

}  // namespace fp
