#pragma once
// Every exception ends in one "frontpack: error: ..." line that says what failed, never a
// class name: our own errors carry their message (file, line, key); out of memory and
// file-system errors, which do not know what the command was doing, are told by Activity.
//   { const Activity doing("packing scene 's.yaml'"); ... }
//   catch (...) { return report_failure(1); }   // "out of memory while packing scene 's.yaml'"
#include <string>

namespace fp {

/// Names what the command is doing for its lifetime (innermost wins). Ended by an exception,
/// it is still named by the catch block that reports that exception.
class Activity {
 public:
  explicit Activity(std::string what);
  ~Activity();
  Activity(const Activity&) = delete;
  Activity& operator=(const Activity&) = delete;

 private:
  int unwinding_at_start_;
};

/// The message for the exception being handled: call inside a catch block.
std::string failure_message();

/// Prints "frontpack: error: <failure_message()>" on stderr and returns `exit_code`.
int report_failure(int exit_code);

}  // namespace fp
