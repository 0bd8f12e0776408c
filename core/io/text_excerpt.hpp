#pragma once
// What a message shows of a value the user gave: its first 80 characters, then how long it was
// (a 240 KB --set value echoed whole buried the message it came with).
#include <algorithm>
#include <cstddef>
#include <string>

namespace fp {

/// The first `limit` characters of s (line breaks and tabs shown as \\n, \\t: a message stays one line).
inline std::string excerpt(const std::string& s, std::size_t limit = 80) {
  std::size_t n = std::min(limit, s.size());
  while (n > 0 && n < s.size() && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;  // not inside a UTF-8 character
  std::string out;
  for (std::size_t i = 0; i < n; ++i) {
    if (s[i] == '\n') out += "\\n";
    else if (s[i] == '\t') out += "\\t";
    else if (s[i] == '\r') out += "\\r";
    else out += s[i];
  }
  return n == s.size() ? out : out + "... (" + std::to_string(s.size()) + " characters)";
}

}  // namespace fp
