#pragma once
// What every fuzz harness (fuzz_<target>.cpp) needs: the checks of the property it asserts and a
// private folder for the files it hands to readers that only take paths.
//
// The property: every input either succeeds or fails with the documented error, whose message
// names no C++ internal (no "std::", "YAML::", "basic_string", "[json.exception...", ...). Any
// other outcome (another exception type, a crash, a sanitizer report, a hang) is a finding.
// A violation prints what was wrong and aborts, so that libFuzzer and mutation_driver.cpp both
// see a crash and keep the input.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace fp::fuzz {

/// Inputs longer than this are cut: the property is about content, and a bounded input keeps
/// every run short (a hang is then a finding, not a large file).
inline constexpr std::size_t kMaxInputBytes = 64 * 1024;

/// Prints "fuzz property violated: <what>" and aborts.
[[noreturn]] void violation(const std::string& what);

/// Checks `condition`; on failure a violation saying `what`.
inline void require(bool condition, const std::string& what) {
  if (!condition) violation(what);
}

/// A documented error's message: not empty, and no name of a C++ internal unless the input
/// itself holds that text (messages may quote the input). `context` says which call failed.
void check_error_message(std::string_view message, std::string_view input, const std::string& context);

/// Called from `catch (...)`: the type of the exception in flight, demangled ("std::out_of_range").
std::string current_exception_type();

/// A violation for an exception that is not the documented one; call from a catch block.
[[noreturn]] void unexpected_exception(const std::string& context);

/// The process's own scratch folder (created on first use under $TMPDIR or /tmp, removed at
/// exit), holding copies of the meshes of tests/fuzz/meshes so that scenes can name them.
const std::string& scratch_folder();

/// Writes `data` to <scratch folder>/<name> (replacing it) and returns the path.
std::string write_scratch_file(const std::string& name, const std::uint8_t* data, std::size_t size);

}  // namespace fp::fuzz
