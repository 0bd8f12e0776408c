// failure_message: out of memory, file-system and standard-library errors become a sentence that
// says what failed; no class name of the library that threw reaches the user.
#include "cli/failure_report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <new>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace fp {
namespace {

template <typename F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (...) {
    return failure_message();
  }
  return "";
}

TEST(FailureReport, OutOfMemoryNamesTheActivity) {
  const Activity outer("packing scene 's.yaml'");
  {
    const Activity inner("reading mesh 'x.off'");
    EXPECT_EQ(message_of([] { throw std::bad_alloc(); }), "out of memory while reading mesh 'x.off'");
  }
  EXPECT_EQ(message_of([] { throw std::bad_alloc(); }), "out of memory while packing scene 's.yaml'");
}

// The usual shape: the Activity lives inside the try block, so it has ended when the catch
// block runs; its name must still be the one reported.
TEST(FailureReport, TheActivityThatEndedWithTheExceptionIsNamed) {
  const Activity outer("packing scene 's.yaml'");
  std::string message;
  try {
    const Activity writing("writing the outputs");
    throw std::bad_alloc();
  } catch (...) {
    message = failure_message();
  }
  EXPECT_EQ(message, "out of memory while writing the outputs");
  try {
    throw std::bad_alloc();
  } catch (...) {
    testing::internal::CaptureStderr();
    EXPECT_EQ(report_failure(1), 1);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "frontpack: error: out of memory while writing the outputs\n");
  }
  try {
    throw std::bad_alloc();
  } catch (...) {
    message = failure_message();  // reported above: back to the live activity
  }
  EXPECT_EQ(message, "out of memory while packing scene 's.yaml'");
}

TEST(FailureReport, NoLibraryNamesInMessages) {
  const Activity doing("writing 'a.csv'");
  const std::string fs_message = message_of([] {
    throw std::filesystem::filesystem_error("status", "a/b.csv", std::make_error_code(std::errc::filename_too_long));
  });
  EXPECT_NE(fs_message.find("'a/b.csv'"), std::string::npos) << fs_message;
  EXPECT_NE(fs_message.find("writing 'a.csv'"), std::string::npos) << fs_message;
  const std::string too_big = message_of([] { std::vector<double>().reserve(std::size_t(-1)); });
  EXPECT_NE(too_big.find("out of memory while writing 'a.csv'"), std::string::npos) << too_big;
  const std::string index = message_of([] { (void)std::vector<int>().at(3); });
  for (const std::string& m : {fs_message, too_big, index, message_of([] { throw 42; })}) {
    for (const char* internal : {"std::", "filesystem error", "bad_alloc", "_M_", "vector::"})
      EXPECT_EQ(m.find(internal), std::string::npos) << m;
  }
  EXPECT_EQ(message_of([] { throw std::runtime_error("s.yaml:3:1: key 'x': bad"); }), "s.yaml:3:1: key 'x': bad");
}

}  // namespace
}  // namespace fp
