#pragma once
// A command line the parser refused, said in frontpack's words: one line after "frontpack:
// error:", the value cut to its first 80 characters, then where to find the options.
#include <CLI/CLI.hpp>
#include <string>

namespace fp {

/// The message for a parse error of `command` ("" before one is chosen), without the prefix.
std::string usage_error_text(const CLI::ParseError& e, const std::string& command);

}  // namespace fp
