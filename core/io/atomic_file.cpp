#include "core/io/atomic_file.hpp"

#include <unistd.h>  // getpid

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace fp {
namespace {

std::string folder_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error("cannot write '" + path + "': " + why);
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_.empty()) fail(path_, "empty file name");
  const std::string folder = folder_of(path_);
  std::error_code ec;
  const auto status = std::filesystem::status(folder, ec);
  if (!std::filesystem::exists(status))
    fail(path_, "folder '" + folder + "' does not exist (frontpack does not create folders)");
  if (!std::filesystem::is_directory(status)) fail(path_, "'" + folder + "' is not a folder");
  if (std::filesystem::is_directory(path_, ec)) fail(path_, "it is a folder");

  temp_path_ = path_ + ".tmp-" + std::to_string(static_cast<long long>(::getpid()));
  out_.open(temp_path_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    const int err = errno;
    fail(path_, "cannot create temporary file '" + temp_path_ + "': " + std::strerror(err));
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) discard();
}

void AtomicFile::discard() noexcept {
  if (out_.is_open()) out_.close();
  if (!temp_path_.empty()) std::remove(temp_path_.c_str());
}

void AtomicFile::commit() {
  if (committed_) return;
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();  // sets failbit if the final write-back fails (e.g. disk full)
  if (!written || !out_) {
    discard();
    fail(path_, "write error (disk full or I/O error?)");
  }
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    discard();
    fail(path_, std::string("cannot rename the temporary file over it: ") + std::strerror(err));
  }
  committed_ = true;
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& body) {
  AtomicFile file(path);
  body(file.stream());
  file.commit();
}

void write_text_file_atomically(const std::string& path, const std::string& text) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

}  // namespace fp
