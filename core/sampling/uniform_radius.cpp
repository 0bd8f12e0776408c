#include "core/sampling/uniform_radius.hpp"

#include <algorithm>

#include "core/sampling/parameter_checks.hpp"

namespace fp {

using sampling_detail::num;

UniformRadius::UniformRadius(double min, double max) : min_(min), max_(max) {
  sampling_detail::require_bounds("UniformRadius", min, max);
}

double UniformRadius::sample(Rng& rng) const {
  return std::min(max_, min_ + (max_ - min_) * rng.uniform01());
}

double UniformRadius::cdf(double r) const {
  return std::clamp((r - min_) / (max_ - min_), 0.0, 1.0);
}

std::string UniformRadius::describe() const { return "uniform [" + num(min_) + ", " + num(max_) + "]"; }

}  // namespace fp
