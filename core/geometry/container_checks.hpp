#pragma once
// Shared by the container constructors: parameter checks that name the offending parameter,
// and the short number formatting used by describe(). Internal to core/geometry.
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/geometry/vec.hpp"

namespace fp::detail {

/// Shortest text that reads back to the same double ("0.9", not "0.900000").
inline std::string format_number(double v) {
  char buf[32];
  auto res = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, res.ptr);
}

/// Six significant digits, for human-facing summaries ("volume 5.60494").
inline std::string format_short(double v) {
  char buf[32];
  auto res = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::general, 6);
  return std::string(buf, res.ptr);
}

template <int D>
std::string format_vec(const Vec<D>& v) {
  std::string s = "[";
  for (int a = 0; a < D; ++a) {
    if (a) s += ",";
    s += format_number(v[a]);
  }
  return s + "]";
}

inline void require_finite(double v, const char* who, const char* param) {
  if (!std::isfinite(v))
    throw std::invalid_argument(std::string(who) + ": " + param + " must be finite, got " + format_number(v));
}

template <int D>
void require_finite(const Vec<D>& v, const char* who, const char* param) {
  if (!v.allFinite())
    throw std::invalid_argument(std::string(who) + ": " + param + " must be finite, got " + format_vec<D>(v));
}

inline void require_positive(double v, const char* who, const char* param) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::invalid_argument(std::string(who) + ": " + param + " must be positive and finite, got " +
                                format_number(v));
}

}  // namespace fp::detail
