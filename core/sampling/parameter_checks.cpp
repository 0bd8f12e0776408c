#include "core/sampling/parameter_checks.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace fp::sampling_detail {

std::string num(double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

void fail(const char* who, const std::string& what) {
  throw std::invalid_argument(std::string(who) + ": " + what);
}

void require_positive(const char* who, const std::string& name, double v) {
  if (!std::isfinite(v) || !(v > 0.0)) fail(who, name + " (" + num(v) + ") must be positive and finite");
}

void require_finite(const char* who, const std::string& name, double v) {
  if (!std::isfinite(v)) fail(who, name + " (" + num(v) + ") must be finite");
}

void require_bounds(const char* who, double lo, double hi, const char* lo_name, const char* hi_name) {
  require_positive(who, lo_name, lo);
  require_positive(who, hi_name, hi);
  if (!(lo < hi))
    fail(who, std::string(lo_name) + " (" + num(lo) + ") must be < " + hi_name + " (" + num(hi) + ")");
}

}  // namespace fp::sampling_detail
