#pragma once
// What frontpack reads (scene, mesh, packing) must be a regular file: a device such as
// /dev/zero, a pipe or a folder would be read for ever or fail deep inside a parser, so it is
// refused at once, by a stat() of the path.
#include <string>

namespace fp {

/// Why `path` cannot be read as an input file, or "" when it can: what exists there must be a
/// regular file (symbolic links followed): "is not a regular file (a device, pipe or socket)",
/// "is a folder". A path that does not exist gives "": the caller's open() reports why.
std::string input_file_problem(const std::string& path);

}  // namespace fp
