#include "core/io/output_paths.hpp"

#include <limits.h>  // NAME_MAX, PATH_MAX
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <system_error>
#include <tuple>

#include "core/io/atomic_file.hpp"
#include "core/io/temp_file_registry.hpp"

namespace fp {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const NamedPath& p, const std::string& problem) {
  throw OutputPathError(p.where + ": " + p.what + " '" + p.path + "' " + problem);
}

/// Which file a path names: device and inode when it exists (hard and symbolic links, ./ and
/// .. all agree), else the absolute path with the existing part resolved.
struct Identity {
  bool exists = false;
  dev_t dev = 0;
  ino_t ino = 0;
  std::string canonical;
  bool operator<(const Identity& o) const {
    return std::tie(exists, dev, ino, canonical) < std::tie(o.exists, o.dev, o.ino, o.canonical);
  }
};

Identity identity_of(const std::string& path) {
  Identity id;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    id.exists = true;
    id.dev = st.st_dev;
    id.ino = st.st_ino;
    return id;
  }
  std::error_code ec;
  const fs::path abs = fs::absolute(path, ec).lexically_normal();
  const fs::path resolved = fs::weakly_canonical(abs, ec);
  id.canonical = (ec ? abs : resolved).string();
  return id;
}

void check_name(const NamedPath& p) {
  if (p.path.empty()) refuse(p, "is an empty file name");
  if (p.path.find('\0') != std::string::npos) refuse(p, "contains a NUL byte");
  if (p.path.size() + kAtomicTempSuffixMax >= PATH_MAX)
    refuse(p, "is " + std::to_string(p.path.size()) + " bytes long; paths are limited to " +
                  std::to_string(PATH_MAX - 1 - kAtomicTempSuffixMax) + " (PATH_MAX, less the suffix of the temporary file)");
  std::size_t start = 0;
  while (start <= p.path.size()) {
    std::size_t end = p.path.find('/', start);
    if (end == std::string::npos) end = p.path.size();
    const std::size_t length = end - start;
    const bool last = end == p.path.size();
    const std::size_t limit = last ? NAME_MAX - kAtomicTempSuffixMax : NAME_MAX;
    if (length > limit)
      refuse(p, std::string("has a ") + (last ? "file name" : "folder name") + " of " + std::to_string(length) +
                    " bytes; names are limited to " + std::to_string(limit) +
                    (last ? " (NAME_MAX, less the suffix '.tmp-<pid>' of the temporary file)" : " (NAME_MAX)"));
    start = end + 1;
  }
}

void check_writable(const NamedPath& p) {
  const std::string target = atomic_write_target(p.path);
  struct stat st {};
  if (::stat(target.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) refuse(p, "is a folder");
    if (!S_ISREG(st.st_mode))
      refuse(p, "exists and is not a regular file (a device, pipe or socket): frontpack replaces files by renaming a "
                "new one over them");
  }
  const fs::path parent = fs::path(target).parent_path();
  const std::string folder = parent.empty() ? "." : parent.string();
  if (::stat(folder.c_str(), &st) != 0) {
    const int err = errno;
    if (err == ENOENT) refuse(p, "cannot be written: folder '" + folder + "' does not exist (frontpack does not create folders)");
    refuse(p, "cannot be written: folder '" + folder + "': " + std::strerror(err));
  }
  if (!S_ISDIR(st.st_mode)) refuse(p, "cannot be written: '" + folder + "' is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    const int err = errno;
    refuse(p, "cannot be written: folder '" + folder + "' is not writable (" + std::strerror(err) + ")");
  }
}

}  // namespace

void check_output_paths(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  // All of them are temporaries at once before the renames (temp_file_registry's table).
  if (outputs.size() > kMaxTempPaths / 2)
    refuse(outputs[kMaxTempPaths / 2], "is one file too many: at most " + std::to_string(kMaxTempPaths / 2) +
                                           " files are written by one run");
  for (const NamedPath& o : outputs) {
    check_name(o);
    check_writable(o);
  }
  check_distinct_files(outputs, inputs);
}

void check_distinct_files(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  // By identity, first named first: a study's hundred thousand runs are not compared pairwise.
  std::map<Identity, std::size_t> read, written;
  for (std::size_t i = 0; i < inputs.size(); ++i) read.emplace(identity_of(inputs[i].path), i);
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const Identity id = identity_of(outputs[k].path);
    if (const auto it = read.find(id); it != read.end()) {
      const NamedPath& in = inputs[it->second];
      refuse(outputs[k], "is the " + in.what + " '" + in.path + "' (" + in.where + "): frontpack never writes over what it reads");
    }
    if (const auto [it, fresh] = written.emplace(id, k); !fresh) {
      const NamedPath& other = outputs[it->second];
      refuse(outputs[k], "is the same file as " + other.what + " '" + other.path + "' (" + other.where +
                             "): one would replace the other; give each its own file");
    }
  }
}

}  // namespace fp
