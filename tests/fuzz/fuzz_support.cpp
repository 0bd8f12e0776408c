#include "fuzz_support.hpp"

#include <cxxabi.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <typeinfo>

namespace fp::fuzz {
namespace {

// Text that only C++ internals put in a message: exception class names, library namespaces,
// libstdc++'s function names ("basic_string::_M_create"), nlohmann's "[json.exception...]".
constexpr std::string_view kInternalMarks[] = {
    "::",           "__",           "_M_",          "basic_",        "bad_alloc",   "bad_array",
    "bad_cast",     "bad_optional", "bad_variant",  "out_of_range",  "length_error", "invalid_argument",
    "logic_error",  "runtime_error", "range_error", "overflow_error", "domain_error", "json.exception",
    "nlohmann",     "yaml-cpp",     "what()",       "terminate called"};

constexpr const char* kScratchMeshes[] = {
    "tests/data/meshes/cube.stl",          "tests/data/meshes/octahedron_binary.stl",
    "tests/data/meshes/box_quads.obj",     "tests/data/scenes-e2e/l_prism.off",
    "tests/fuzz/meshes/icosphere.off",     "tests/fuzz/meshes/torus.obj"};

// Words of the file formats that messages may name although they look like C++ class names.
constexpr std::string_view kFormatWords[] = {"VTKFile", "UnstructuredGrid", "LittleEndian", "BigEndian", "NumberOfPoints",
                                             "NumberOfCells", "NumberOfComponents", "AppendedData", "DataArray",
                                             "PointData", "FieldData", "MeshFormat", "EndMeshFormat",
                                             "PhysicalNames", "EndPhysicalNames", "EndEntities", "EndNodes",
                                             "EndElements"};

/// The first CamelCase word of `text` with two humps or more ("BoxContainer", "LognormalRadius"):
/// the names of frontpack's own classes, which README promises never to show. Empty if none.
std::string_view class_like_word(std::string_view text) {
  const auto upper = [](char c) { return c >= 'A' && c <= 'Z'; };
  const auto lower = [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'); };
  for (std::size_t i = 0; i < text.size();) {
    if (!upper(text[i]) || (i > 0 && (upper(text[i - 1]) || lower(text[i - 1])))) {
      ++i;
      continue;
    }
    std::size_t j = i, humps = 0;
    while (j < text.size() && upper(text[j]) && j + 1 < text.size() && lower(text[j + 1])) {
      ++humps;
      ++j;
      while (j < text.size() && lower(text[j])) ++j;
    }
    const bool whole = j == text.size() || !(upper(text[j]) || lower(text[j]));
    if (humps >= 2 && whole) return text.substr(i, j - i);
    i = j > i ? j : i + 1;
  }
  return {};
}

}  // namespace

void violation(const std::string& what) {
  std::fprintf(stderr, "\nfuzz property violated: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

void check_error_message(std::string_view message_in, std::string_view input, const std::string& context) {
  require(!message_in.empty(), context + ": failed with an empty message");
  // The scratch folder's random name (frontpack-fuzz-LhQy31) is not a class name.
  std::string without_folder(message_in);
  for (std::size_t at; (at = without_folder.find(scratch_folder())) != std::string::npos;)
    without_folder.replace(at, scratch_folder().size(), "<folder>");
  const std::string_view message = without_folder;
  for (const std::string_view mark : kInternalMarks)
    if (message.find(mark) != std::string_view::npos && input.find(mark) == std::string_view::npos)
      violation(context + ": the message shows a C++ internal ('" + std::string(mark) + "'): " + std::string(message));
  for (std::string_view rest = message; !rest.empty();) {
    const std::string_view word = class_like_word(rest);
    if (word.empty()) break;
    const bool format_word = std::find(std::begin(kFormatWords), std::end(kFormatWords), word) != std::end(kFormatWords);
    if (!format_word && input.find(word) == std::string_view::npos)
      violation(context + ": the message names a C++ class ('" + std::string(word) + "'): " + std::string(message));
    rest = rest.substr(static_cast<std::size_t>(word.data() - rest.data()) + word.size());
  }
}

std::string current_exception_type() {
  const std::type_info* type = abi::__cxa_current_exception_type();
  if (type == nullptr) return "(no exception)";
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> name(abi::__cxa_demangle(type->name(), nullptr, nullptr, &status), std::free);
  return status == 0 && name ? name.get() : type->name();
}

void unexpected_exception(const std::string& context) {
  std::string what;
  try {
    throw;
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
    what = "(not a std::exception)";
  }
  violation(context + ": undocumented exception " + current_exception_type() + ": " + what);
}

const std::string& scratch_folder() {
  static const std::string folder = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/frontpack-fuzz-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) violation("cannot create a scratch folder from " + pattern);
    // The meshes scenes may name (container: {type: mesh, file: cube.stl}); small ones only, so
    // that a scene builds its container in milliseconds.
    const std::filesystem::path source(FRONTPACK_SOURCE_DIR);
    for (const char* mesh : kScratchMeshes) {
      const std::filesystem::path from = source / mesh;
      std::error_code ec;
      std::filesystem::copy_file(from, std::filesystem::path(pattern) / from.filename(), ec);
      if (ec) violation("cannot copy " + from.string() + " to the scratch folder: " + ec.message());
    }
    static const std::string remove_at_exit = pattern;
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(remove_at_exit, ignored);
    });
    return pattern;
  }();
  return folder;
}

std::string write_scratch_file(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::string path = scratch_folder() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) violation("cannot write the scratch file " + path);
  return path;
}

}  // namespace fp::fuzz
