#pragma once
// Temporary files that must not outlive an interrupted run. AtomicFile registers each of its
// temporaries here; after install_temp_file_cleanup(), SIGINT, SIGTERM, SIGHUP and SIGQUIT
// first remove every registered path, then kill the process as the signal would have.
//
// The handler may interrupt anything, malloc included, so the table is a fixed array of
// fixed-size paths and the handler calls only unlink(), rmdir(), sigaction() and raise()
// (all async-signal-safe).
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
