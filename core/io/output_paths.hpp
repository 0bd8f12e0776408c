#pragma once
// The files a command is about to write, checked before any work, so that a bad path costs
// nothing and no file is lost. Refused (OutputPathError, exit code 2):
// * a path that cannot be a file name: empty, with a NUL byte, longer than PATH_MAX, or with a
//   name longer than NAME_MAX (the temporary "<name>.tmp-<pid>" must fit too);
// * a folder that does not exist, is not a folder or is not writable (access W_OK);
// * a target that is a folder, or exists and is not a regular file (/dev/null, a pipe: the
//   atomic replacement would rename a file over it);
// * more than 128 files at once (they are all temporaries before the renames);
// * two outputs that are the same file, and an output that is one of the command's inputs.
//   "Same" after normalisation: ./ and .., symbolic links and hard links (device and inode for
//   files that exist, the weakly canonical absolute path for those that do not).
#include <stdexcept>
#include <string>
#include <vector>

namespace fp {

/// A file a command writes or reads, and how the user named it (for messages).
struct NamedPath {
  std::string path;
  std::string where;  ///< message prefix: "scene.yaml:7:5: key 'output[1].path'", "option -o"
  std::string what;   ///< "output", "run record", "surfaces file of output 'a.vtu'", "scene file", ...
};

/// A path that must not be written. what() = "<where>: <what> '<path>' <problem>".
class OutputPathError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws OutputPathError for the first problem found (see above).
void check_output_paths(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

/// The last check alone: no output is an input or another output. For files in folders not made
/// yet (a study's runs), as many as there are: no limit on their number.
void check_distinct_files(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

}  // namespace fp
