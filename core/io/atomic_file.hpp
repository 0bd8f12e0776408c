#pragma once
// Atomic file replacement: write everything to "<path>.tmp-<pid>" in the target's folder,
// then rename over the target. Readers (and a crash) see either the old file or the
// complete new one, never a half-written file.
//
// Missing folders are NOT created: a typo in an output path should be an error, not a
// surprise directory tree. The constructor throws std::runtime_error naming the path.
#include <fstream>
#include <functional>
#include <ostream>
#include <string>

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
  /// an existing target is left untouched).
  void commit();

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_path_; }

 private:
  void discard() noexcept;

  std::string path_;
  std::string temp_path_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Runs `body` on the stream of an AtomicFile for `path` and commits. If `body` throws, the
/// temporary is removed and the exception propagates; the target is untouched.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& body);

/// Same, for a ready string.
void write_text_file_atomically(const std::string& path, const std::string& text);

}  // namespace fp
