#pragma once
// Token lists of the fuzz targets (tests/fuzz/dict/<target>.dict), in libFuzzer's -dict format so
// that both drivers read the same file: one token per line, `"text"` or `name="text"`, with the
// escapes \\, \" and \xHH; blank lines and lines starting with '#' are skipped.
#include <string>
#include <vector>

namespace fp::fuzz {

/// The tokens of `path`. Throws std::runtime_error naming the file and line on a malformed line.
std::vector<std::string> read_dictionary(const std::string& path);

}  // namespace fp::fuzz
