#include "core/io/atomic_file.hpp"

#include <unistd.h>  // getpid

#include <cerrno>
#include <cstdio>  // rename, renameat2 (glibc >= 2.28)
#include <cstring>
#include <fcntl.h>  // AT_FDCWD
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "core/io/temp_file_registry.hpp"

namespace fp {
namespace {

thread_local AtomicFileGroup* t_open_group = nullptr;

std::string folder_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error("cannot write '" + path + "': " + why);
}

}  // namespace

// A symbolic link is written through (like `>` in a shell): its target is replaced.
std::string atomic_write_target(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_symlink(path, ec)) return path;
  const std::filesystem::path resolved = std::filesystem::canonical(path, ec);
  return ec ? path : resolved.string();  // a dangling link is replaced by the file
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_.empty()) fail(path_, "empty file name");
  if (path_.find('\0') != std::string::npos) fail(path_, "the file name contains a NUL byte");
  target_ = atomic_write_target(path_);
  const std::string folder = folder_of(target_);
  std::error_code ec;
  const auto status = std::filesystem::status(folder, ec);
  if (!std::filesystem::exists(status))
    fail(path_, "folder '" + folder + "' does not exist (frontpack does not create folders)");
  if (!std::filesystem::is_directory(status)) fail(path_, "'" + folder + "' is not a folder");
  if (std::filesystem::is_directory(target_, ec)) fail(path_, "it is a folder");

  temp_path_ = target_ + ".tmp-" + std::to_string(static_cast<long long>(::getpid()));
  slot_ = register_temp_path(temp_path_);  // before the file exists: a signal never misses it
  out_.open(temp_path_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    const int err = errno;
    unregister_temp_path(slot_);
    slot_ = -1;
    fail(path_, "cannot create temporary file '" + temp_path_ + "': " + std::strerror(err));
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) discard();
}

void AtomicFile::discard() noexcept {
  if (out_.is_open()) out_.close();
  if (!temp_path_.empty()) std::remove(temp_path_.c_str());
  unregister_temp_path(slot_);
  slot_ = -1;
}

void AtomicFile::commit() {
  if (committed_) return;
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();  // sets failbit if the final write-back fails (e.g. disk full)
  if (!written || !out_) {
    discard();
    fail(path_, "write error (disk full, file size limit or I/O error)");
  }
  if (t_open_group) {  // the group renames it with the others
    t_open_group->adopt({path_, target_, temp_path_, slot_});
    slot_ = -1;
    committed_ = true;
    return;
  }
  if (std::rename(temp_path_.c_str(), target_.c_str()) != 0) {
    const int err = errno;
    discard();
    fail(path_, std::string("cannot rename the temporary file over it: ") + std::strerror(err));
  }
  unregister_temp_path(slot_);
  slot_ = -1;
  committed_ = true;
}

AtomicFileGroup::AtomicFileGroup() {
  if (t_open_group) throw std::logic_error("AtomicFileGroup: groups do not nest");
  t_open_group = this;
}

AtomicFileGroup::~AtomicFileGroup() {
  if (t_open_group == this) t_open_group = nullptr;
  if (!done_) discard_all();
}

void AtomicFileGroup::discard_all() noexcept {
  for (const Entry& e : entries_) {
    std::remove(e.temp.c_str());
    unregister_temp_path(e.slot);
  }
  entries_.clear();
}

void AtomicFileGroup::commit() {
  if (t_open_group == this) t_open_group = nullptr;
  if (done_) return;
  enum class Done { Exchanged, Created, Replaced };  // Replaced: no way back (no RENAME_EXCHANGE here)
  std::vector<Done> done;
  done.reserve(entries_.size());
  const CleanupSignalsBlocked hold;  // the renames are one step for Ctrl-C too
  for (const Entry& e : entries_) {
    if (::renameat2(AT_FDCWD, e.temp.c_str(), AT_FDCWD, e.target.c_str(), RENAME_EXCHANGE) == 0) {
      done.push_back(Done::Exchanged);  // the temporary now holds the old file
      continue;
    }
    int err = errno;
    if (err == ENOENT || err == EINVAL || err == ENOSYS || err == ENOTSUP) {  // no target yet, or no exchange here
      if (std::rename(e.temp.c_str(), e.target.c_str()) == 0) {
        done.push_back(err == ENOENT ? Done::Created : Done::Replaced);
        continue;
      }
      err = errno;
    }
    // Undo, newest first: swap the old files back, remove the files this group created.
    bool undone = true;
    for (std::size_t j = done.size(); j-- > 0;) {
      const Entry& d = entries_[j];
      if (done[j] == Done::Exchanged)
        undone = ::renameat2(AT_FDCWD, d.temp.c_str(), AT_FDCWD, d.target.c_str(), RENAME_EXCHANGE) == 0 && undone;
      else if (done[j] == Done::Created)
        undone = std::rename(d.target.c_str(), d.temp.c_str()) == 0 && undone;
      else
        undone = false;
    }
    const std::string failed = e.path;  // e dies with the entries
    discard_all();
    done_ = true;
    fail(failed, std::string("cannot rename the temporary file over it: ") + std::strerror(err) +
                     (undone ? " (no file was replaced)" : " (some files of the set were already replaced)"));
  }
  discard_all();  // the old contents of exchanged targets
  done_ = true;
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
