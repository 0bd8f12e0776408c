#include "dictionary.hpp"

#include <fstream>
#include <stdexcept>

namespace fp::fuzz {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::vector<std::string> read_dictionary(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open the dictionary " + path);
  std::vector<std::string> tokens;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const auto fail = [&](const std::string& why) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": " + why);
    };
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::size_t open = line.find('"', first);
    const std::size_t close = line.find_last_of('"');
    if (open == std::string::npos || close == open) fail("expected \"token\" or name=\"token\"");
    std::string token;
    for (std::size_t i = open + 1; i < close; ++i) {
      if (line[i] != '\\') {
        token += line[i];
        continue;
      }
      if (i + 1 >= close) fail("a '\\' ends the token");
      const char e = line[++i];
      if (e == '\\' || e == '"') {
        token += e;
      } else if (e == 'x' && i + 2 < close && hex_digit(line[i + 1]) >= 0 && hex_digit(line[i + 2]) >= 0) {
        token += static_cast<char>(hex_digit(line[i + 1]) * 16 + hex_digit(line[i + 2]));
        i += 2;
      } else {
        fail("unknown escape '\\" + std::string(1, e) + "' (known: \\\\, \\\", \\xHH)");
      }
    }
    if (token.empty()) fail("empty token");
    tokens.push_back(std::move(token));
  }
  return tokens;
}

}  // namespace fp::fuzz
