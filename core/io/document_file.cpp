#include "core/io/document_file.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/io/input_file.hpp"
#include "core/io/scene_error.hpp"

namespace fp {

std::string read_document_file(const std::string& path, const std::string& kind, const std::string& example, std::size_t cap) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw SceneError(path, 0, 0, "", "is a folder; give the " + kind + " file (YAML) itself, e.g. " + example);
  const std::string problem = input_file_problem(path);
  if (!problem.empty()) throw SceneError(path, 0, 0, "", "the " + kind + " file " + problem);
  const std::string limit = kind + " files are limited to " + std::to_string(cap >> 20) + " MiB";
  if (const auto size = std::filesystem::file_size(path, ec); !ec && size > cap)
    throw SceneError(path, 0, 0, "", "the " + kind + " file is " + std::to_string(size) + " bytes; " + limit);
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    throw SceneError(path, 0, 0, "", "cannot read the " + kind + " file" + (err ? std::string(": ") + std::strerror(err) : ""));
  }
  // In chunks, no more than the cap even if the file grows meanwhile (a buffer of the cap, zeroed
  // and faulted in, cost 50 ms of every run: a sixth of a small packing's).
  std::string text;
  std::array<char, 1 << 16> chunk;
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > cap) throw SceneError(path, 0, 0, "", "the " + kind + " file grew while it was read; " + limit);
  }
  return text;
}

}  // namespace fp
