#include "cli/failure_report.hpp"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <vector>

namespace fp {
namespace {

// The activities of the live Activity objects, innermost last. One that ends by stack unwinding
// stays on top (above t_live) so that the catch block, reached after the unwinding, still
// sees what was being done when the exception was thrown.
thread_local std::vector<std::string> t_stack;
thread_local std::size_t t_live = 0;

std::string current_activity() { return t_stack.empty() ? "running" : t_stack.back(); }

}  // namespace

Activity::Activity(std::string what) : unwinding_at_start_(std::uncaught_exceptions()) {
  t_stack.resize(t_live);
  t_stack.push_back(std::move(what));
  ++t_live;
}

Activity::~Activity() {
  --t_live;
  if (std::uncaught_exceptions() <= unwinding_at_start_) t_stack.resize(t_live);
}

std::string failure_message() {
  try {
    throw;
  } catch (const std::bad_alloc&) {
    return "out of memory while " + current_activity();
  } catch (const std::length_error&) {  // the standard library's, named after its internals
    return "out of memory while " + current_activity() + " (a size beyond what can be allocated)";
  } catch (const std::out_of_range&) {  // ours are never out_of_range: a bug
    return "internal error while " + current_activity() + " (an index out of range); please report it with the scene";
  } catch (const std::filesystem::filesystem_error& e) {
    std::string s = "cannot access";
    if (!e.path1().empty()) s += " '" + e.path1().string() + "'";
    if (!e.path2().empty()) s += " or '" + e.path2().string() + "'";
    return s + ": " + e.code().message() + " (while " + current_activity() + ")";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    return what.empty() ? "failure while " + current_activity() : what;  // our messages name file, line and key
  } catch (...) {
    return "unexpected failure while " + current_activity();
  }
}

int report_failure(int exit_code) {
  const std::string message = failure_message();
  t_stack.resize(t_live);  // reported: forget the activities that ended with the exception
  std::fprintf(stderr, "frontpack: error: %s\n", message.c_str());
  return exit_code;
}

}  // namespace fp
