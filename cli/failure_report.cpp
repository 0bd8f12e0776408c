#include "cli/failure_report.hpp"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <stdexcept>

namespace fp {
namespace {

thread_local std::string t_activity = "running";

}  // namespace

Activity::Activity(std::string what) : previous_(std::move(t_activity)) { t_activity = std::move(what); }

Activity::~Activity() { t_activity = std::move(previous_); }

std::string failure_message() {
  try {
    throw;
  } catch (const std::bad_alloc&) {
    return "out of memory while " + t_activity;
  } catch (const std::length_error&) {  // the standard library's, named after its internals
    return "out of memory while " + t_activity + " (a size beyond what can be allocated)";
  } catch (const std::out_of_range&) {  // ours are never out_of_range: a bug
    return "internal error while " + t_activity + " (an index out of range); please report it with the scene";
  } catch (const std::filesystem::filesystem_error& e) {
    std::string s = "cannot access";
    if (!e.path1().empty()) s += " '" + e.path1().string() + "'";
    if (!e.path2().empty()) s += " or '" + e.path2().string() + "'";
    return s + ": " + e.code().message() + " (while " + t_activity + ")";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    return what.empty() ? "failure while " + t_activity : what;  // our messages name file, line and key
  } catch (...) {
    return "unexpected failure while " + t_activity;
  }
}

int report_failure(int exit_code) {
  const std::string message = failure_message();
  std::fprintf(stderr, "frontpack: error: %s\n", message.c_str());
  return exit_code;
}

}  // namespace fp
