#pragma once
// Constructor checks shared by the size distributions: each failure throws std::invalid_argument
// whose message names the class, the parameter and its value, e.g.
// "UniformRadius: min (0.03) must be < max (0.02)".
#include <string>

namespace fp::sampling_detail {

/// Shortest text that reads back as the same double ("0.03", "1e-06").
std::string num(double v);

[[noreturn]] void fail(const char* who, const std::string& what);

/// v must be finite and > 0.
void require_positive(const char* who, const std::string& name, double v);
/// v must be finite.
void require_finite(const char* who, const std::string& name, double v);
/// 0 < lo < hi, both finite (the bounds every bounded radius distribution needs).
void require_bounds(const char* who, double lo, double hi, const char* lo_name = "min",
                    const char* hi_name = "max");

}  // namespace fp::sampling_detail
