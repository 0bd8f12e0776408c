#pragma once
// The arithmetic a study may write where a parameter's value goes into the scene: `${2 * r}`,
// `${sqrt(a) / 2}` (core/io/study_yaml.hpp, a parameter's `set`). Numbers, the parameter's own
// name, + - * / ^ (power, right-associative), unary signs, parentheses, pi, and the functions
// sqrt, cbrt, exp, log, sin, cos, tan, abs. Nothing else: a study stays a list of values, not a
// program.
#include <stdexcept>
#include <string>
#include <string_view>

namespace fp {

/// A problem with an expression: the message says what and at which character.
struct ExpressionError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// The value of `text` where `name` stands for `value`. Throws ExpressionError for a syntax error,
/// an unknown name or function, and a result that is not a finite number (1 / 0, sqrt(-1)).
double evaluate_expression(std::string_view text, const std::string& name, double value);

/// `x` as the shortest text that reads back as exactly `x` ("0.1", "1e-300", "2").
std::string shortest_number_text(double x);

}  // namespace fp
