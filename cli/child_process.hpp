#pragma once
// Runs programs as child processes (posix_spawn, no shell), their stdout and stderr into a log
// file, and waits for them one by one (waitpid on each pid: a host program's own children, e.g.
// Python's, are never reaped here). Each is registered with the signal cleanup
// (core/io/temp_file_registry.hpp): Ctrl-C or kill of this process reaches the children too.
#include <string>
#include <sys/types.h>
#include <vector>

namespace fp {

class ChildProcess {
 public:
  /// Starts argv[0] (a path) with `argv`, stdin from /dev/null, stdout and stderr to `log_path`
  /// (replaced). Throws std::runtime_error when it cannot be started.
  ChildProcess(const std::vector<std::string>& argv, const std::string& log_path);
  ~ChildProcess();  ///< a child still running is killed (SIGTERM) and waited for
  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess& operator=(ChildProcess&&) = delete;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Whether it has ended (without blocking); then exit_code() is known.
  bool finished();
  /// Its exit code, or 128 + the signal that ended it.
  int exit_code() const { return code_; }

 private:
  pid_t pid_ = -1;
  int code_ = -1;
  int slot_ = -1;  ///< in the signal cleanup's table of children (core/io/temp_file_registry.hpp)
};

}  // namespace fp
