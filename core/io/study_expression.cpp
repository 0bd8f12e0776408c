#include "core/io/study_expression.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <utility>

namespace fp {
namespace {

/// Recursive descent over the grammar
///   sum     := product (('+' | '-') product)*
///   product := unary (('*' | '/') unary)*
///   unary   := ('+' | '-') unary | power
///   power   := atom ('^' unary)?            (right-associative: 2^3^2 = 2^9; -2^2 = -4)
///   atom    := number | name | function '(' sum ')' | '(' sum ')'
class Parser {
 public:
  Parser(std::string_view text, const std::string& name, double value) : text_(text), name_(name), value_(value) {}

  double parse() {
    const double v = sum();
    skip_space();
    if (at_ < text_.size()) fail("unexpected '" + std::string(1, text_[at_]) + "'");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ExpressionError(what + " at character " + std::to_string(at_ + 1) + " of '" + std::string(text_) + "'");
  }
  void skip_space() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  bool take(char c) {
    skip_space();
    if (at_ < text_.size() && text_[at_] == c) {
      ++at_;
      return true;
    }
    return false;
  }

  double sum() {
    double v = product();
    while (true) {
      if (take('+')) v += product();
      else if (take('-')) v -= product();
      else return v;
    }
  }
  double product() {
    double v = unary();
    while (true) {
      if (take('*')) v *= unary();
      else if (take('/')) v /= unary();
      else return v;
    }
  }
  double unary() {
    if (take('-')) return -unary();
    if (take('+')) return unary();
    return power();
  }
  double power() {
    const double base = atom();
    return take('^') ? std::pow(base, unary()) : base;
  }
  double atom() {
    skip_space();
    if (at_ >= text_.size()) fail("a number, a name or '(' expected");
    if (take('(')) {
      const double v = sum();
      if (!take(')')) fail("')' expected");
      return v;
    }
    const char c = text_[at_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      double v = 0;
      const auto r = std::from_chars(text_.data() + at_, text_.data() + text_.size(), v);
      if (r.ec != std::errc()) fail("a number expected");
      at_ = static_cast<std::size_t>(r.ptr - text_.data());
      return v;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = at_;
      while (at_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[at_])) || text_[at_] == '_')) ++at_;
      const std::string word(text_.substr(start, at_ - start));
      if (word == name_) return value_;
      if (word == "pi") return std::numbers::pi;
      static const std::pair<const char*, double (*)(double)> functions[] = {
          {"sqrt", [](double x) { return std::sqrt(x); }}, {"cbrt", [](double x) { return std::cbrt(x); }},
          {"exp", [](double x) { return std::exp(x); }},   {"log", [](double x) { return std::log(x); }},
          {"sin", [](double x) { return std::sin(x); }},   {"cos", [](double x) { return std::cos(x); }},
          {"tan", [](double x) { return std::tan(x); }},   {"abs", [](double x) { return std::fabs(x); }}};
      for (const auto& [fname, f] : functions)
        if (word == fname) {
          if (!take('(')) fail("'(' expected after " + word);
          const double x = sum();
          if (!take(')')) fail("')' expected");
          return f(x);
        }
      at_ = start;
      fail("unknown name '" + word + "' (the parameter is '" + name_ +
           "'; functions: sqrt, cbrt, exp, log, sin, cos, tan, abs; constant: pi)");
    }
    fail("unexpected '" + std::string(1, c) + "'");
  }

  std::string_view text_;
  const std::string& name_;
  double value_;
  std::size_t at_ = 0;
};

}  // namespace

double evaluate_expression(std::string_view text, const std::string& name, double value) {
  const double v = Parser(text, name, value).parse();
  if (!std::isfinite(v))
    throw ExpressionError("'" + std::string(text) + "' is not a finite number where " + name + " = " + shortest_number_text(value));
  return v;
}

std::string shortest_number_text(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace fp
