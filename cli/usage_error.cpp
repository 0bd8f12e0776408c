#include "cli/usage_error.hpp"

#include <cctype>
#include <regex>

#include "core/io/text_excerpt.hpp"

namespace fp {

std::string usage_error_text(const CLI::ParseError& e, const std::string& command) {
  const std::string what = e.what();
  const std::string help = " (frontpack " + (command.empty() ? std::string() : command + " ") + "--help lists them)";
  std::smatch m;
  // CLI11's own texts, read by their form: they name the option first.
  if (std::regex_match(what, m, std::regex(R"((\S+): \1 (.*))")))  // our validators name the option themselves
    return m[1].str() + " " + excerpt(m[2].str(), 240);
  if (std::regex_match(what, m, std::regex(R"((\S+): At Most 1 required but received (\d+))")))
    return m[1].str() + " is given " + m[2].str() + " times; it takes one";
  if (std::regex_match(what, m, std::regex(R"(The following arguments? (?:was|were) not expected: (.*))")))
    return "unexpected argument" + std::string(m[1].str().find(' ') != std::string::npos ? "s " : " ") + excerpt(m[1].str()) +
           help;
  if (std::regex_match(what, m, std::regex(R"((--?\S+) is required)")))
    return "missing the option " + m[1].str() + help;
  if (std::regex_match(what, m, std::regex(R"((\S+) is required)"))) {
    std::string name = m[1].str();
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return "missing the argument " + name + " (frontpack " + command + " " + name + " ...)";
  }
  if (std::regex_match(what, m, std::regex(R"((\S+): Value (.*) not in range (\S+) to (\S+))")))
    return m[1].str() + " must be from " + m[3].str() + " to " + m[4].str() + " (got " + excerpt(m[2].str()) + ")";
  if (std::regex_match(what, m, std::regex(R"((\S+) requires (.*))")))
    return m[1].str() + " requires " + excerpt(m[2].str());
  return excerpt(what, 240) + help;
}

}  // namespace fp
