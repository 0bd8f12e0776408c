#include "cli_test_util.hpp"

#include <charconv>

namespace fptest {

bool parse_numbers(const std::string& line, char separator, std::vector<double>& out) {
  out.clear();
  std::size_t i = 0;
  const auto is_sep = [&](char c) { return separator == ' ' ? (c == ' ' || c == '\t' || c == '\r') : c == separator; };
  while (i < line.size()) {
    if (separator == ' ')
      while (i < line.size() && is_sep(line[i])) ++i;
    if (i >= line.size()) break;
    std::size_t j = i;
    while (j < line.size() && !is_sep(line[j])) ++j;
    double v = 0;
    const auto res = std::from_chars(line.data() + i, line.data() + j, v);
    if (res.ec != std::errc() || res.ptr != line.data() + j) return false;
    out.push_back(v);
    i = j + (separator == ' ' ? 0 : 1);
  }
  return true;
}

}  // namespace fptest
