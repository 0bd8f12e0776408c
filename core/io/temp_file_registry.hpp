#pragma once
// Temporary files that must not outlive an interrupted run. AtomicFile registers each of its
// temporaries here (and a study its runs' processes); after install_temp_file_cleanup(), SIGINT,
// SIGTERM, SIGHUP and SIGQUIT first pass the signal on to every registered child, remove every
// registered path, then kill the process as the signal would have.
//
// The handler may interrupt anything, malloc included, so the table is a fixed array of
// fixed-size paths and the handler calls only kill(), unlink(), rmdir(), sigaction() and raise()
// (all async-signal-safe).
#include <sys/types.h>

#include <csignal>
#include <string>

namespace fp {

/// Paths registered at once, at most (a run holds one per output file and side file).
inline constexpr int kMaxTempPaths = 256;

/// Registers `path` (a file, or with `folder` an empty folder removed after the files) for
/// removal on those signals. Returns the slot to unregister. Throws std::runtime_error if
/// the table is full or the path is longer than PATH_MAX.
int register_temp_path(const std::string& path, bool folder = false);

/// Forgets a slot (the path was renamed or removed). Ignores -1.
void unregister_temp_path(int slot) noexcept;

/// Child processes registered at once, at most (a study's runs at once).
inline constexpr int kMaxChildProcesses = 1024;

/// Registers a child process: those signals are passed on to it (kill) before this process
/// cleans up and ends, so that `kill STUDY` stops its runs too. Returns the slot to unregister
/// once the child has been waited for. Throws std::runtime_error if the table is full.
int register_child_process(pid_t pid);
void unregister_child_process(int slot) noexcept;

/// Installs the handlers (idempotent). A signal that was ignored when the process started
/// (SIGHUP under nohup, SIGINT in a background job) stays ignored. SIGXFSZ is ignored too,
/// so that a file-size limit (ulimit -f) is a write error (EFBIG) reported as such, not a
/// kill that leaves temporaries behind.
void install_temp_file_cleanup();

/// Removes every registered path now (what the handler does) and empties the table.
void remove_registered_temp_paths() noexcept;

/// Holds the cleanup signals back for its lifetime (delivered when it ends), so that a set of
/// renames is not cut in half by Ctrl-C.
class CleanupSignalsBlocked {
 public:
  CleanupSignalsBlocked();
  ~CleanupSignalsBlocked();
  CleanupSignalsBlocked(const CleanupSignalsBlocked&) = delete;
  CleanupSignalsBlocked& operator=(const CleanupSignalsBlocked&) = delete;

 private:
  sigset_t previous_;
};

}  // namespace fp
