#pragma once
// Atomic file replacement: write everything to "<path>.tmp-<pid>" in the target's folder,
// then rename over the target. Readers (and a crash) see either the old file or the
// complete new one, never a half-written file. Each temporary is registered with
// temp_file_registry.hpp, so SIGINT/SIGTERM remove it too.
//
// A set of files (every output of a run) is replaced all or nothing with AtomicFileGroup:
// each file is completed to its temporary first, then all are renamed at once; if one fails,
// every temporary is removed and every target keeps its old content.
//
// An output that is a symbolic link is written through: the file it points to is replaced,
// the link stays. Missing folders are NOT created: a typo in an output path should be an
// error, not a surprise directory tree. The constructor throws std::runtime_error naming the path.
#include <fstream>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace fp {

class AtomicFile {
 public:
  /// Opens the temporary file (binary mode). Throws std::runtime_error naming `path` if the
  /// folder does not exist, is not a folder, or the temporary cannot be created.
  explicit AtomicFile(std::string path);
  /// Removes the temporary unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  /// Flushes, closes, checks the stream state and renames the temporary over the target.
  /// Throws std::runtime_error naming the path on any failure (the temporary is removed,
  /// an existing target is left untouched). Inside an AtomicFileGroup the rename is left to
  /// the group's commit().
  void commit();

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_path_; }

 private:
  void discard() noexcept;

  std::string path_;    ///< as given (messages)
  std::string target_;  ///< what is replaced: path_, or the file a symbolic link path_ points to
  std::string temp_path_;
  std::ofstream out_;
  int slot_ = -1;       ///< temp_file_registry slot of temp_path_
  bool committed_ = false;
};

/// All-or-nothing replacement of several files. While a group is open, an AtomicFile's
/// commit() on the same thread only completes its temporary (flush, close, check) and hands
/// it to the group; commit() of the group then renames them all. Groups do not nest.
class AtomicFileGroup {
 public:
  AtomicFileGroup();
  /// Not committed (an exception on the way): removes every temporary; targets untouched.
  ~AtomicFileGroup();
  AtomicFileGroup(const AtomicFileGroup&) = delete;
  AtomicFileGroup& operator=(const AtomicFileGroup&) = delete;

  /// Replaces every target. A target replaced before a later rename fails is put back (the
  /// renames swap the old and new files, RENAME_EXCHANGE), so on failure no target has
  /// changed; throws std::runtime_error naming the file that failed.
  void commit();

 private:
  friend class AtomicFile;
  struct Entry {
    std::string path, target, temp;
    int slot;
  };
  void adopt(Entry e) { entries_.push_back(std::move(e)); }
  void discard_all() noexcept;

  std::vector<Entry> entries_;
  bool done_ = false;
};

/// Longest suffix of a temporary's name: ".tmp-" and a pid (at most 10 digits).
inline constexpr std::size_t kAtomicTempSuffixMax = 15;

/// The file AtomicFile(path) replaces: `path`, or the file a symbolic link `path` points to.
std::string atomic_write_target(const std::string& path);

/// Runs `body` on the stream of an AtomicFile for `path` and commits. If `body` throws, the
/// temporary is removed and the exception propagates; the target is untouched.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& body);

/// Same, for a ready string.
void write_text_file_atomically(const std::string& path, const std::string& text);

}  // namespace fp
