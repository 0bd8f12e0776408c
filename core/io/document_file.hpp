#pragma once
// Reads a small text document frontpack is given (a scene, a study), with the checks every input
// file gets (input_file.hpp) and a size cap. Problems are SceneErrors naming the file.
#include <cstddef>
#include <string>

namespace fp {

/// The text of `path`, a `kind` file ("scene", "study"; `example` is shown when a folder is given),
/// at most `cap` bytes. Throws SceneError(path, 0, 0, "", why).
std::string read_document_file(const std::string& path, const std::string& kind, const std::string& example, std::size_t cap);

}  // namespace fp
