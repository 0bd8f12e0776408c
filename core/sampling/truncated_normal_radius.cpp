#include "core/sampling/truncated_normal_radius.hpp"

#include <algorithm>
#include <cmath>

#include "core/sampling/parameter_checks.hpp"

namespace fp {

using sampling_detail::num;

namespace {
constexpr const char* kWho = "TruncatedNormalRadius";

TruncatedStandardNormal checked_standardised(double mean, double stddev, double min, double max) {
  sampling_detail::require_finite(kWho, "mean", mean);
  sampling_detail::require_positive(kWho, "stddev", stddev);
  sampling_detail::require_bounds(kWho, min, max);
  const double a = (min - mean) / stddev, b = (max - mean) / stddev;
  if (!std::isfinite(a) || !std::isfinite(b))
    sampling_detail::fail(kWho, "stddev (" + num(stddev) + ") is too small for [min, max] = [" + num(min) + ", " +
                                    num(max) + "]: the standardised bounds overflow");
  TruncatedStandardNormal z(a, b);
  // Below this the tail probabilities approach the subnormal range and lose their precision.
  if (!(z.mass() >= 1e-300))
    sampling_detail::fail(kWho, "[min, max] = [" + num(min) + ", " + num(max) +
                                    "] has probability below 1e-300 under N(mean " + num(mean) + ", stddev " +
                                    num(stddev) + ") (too far in a tail, or too narrow)");
  return z;
}
}  // namespace

TruncatedNormalRadius::TruncatedNormalRadius(double mean, double stddev, double min, double max)
    : mu_(mean), sigma_(stddev), min_(min), max_(max), z_(checked_standardised(mean, stddev, min, max)) {
  mean_truncated_ = std::clamp(mu_ + sigma_ * z_.mean(), min_, max_);
}

double TruncatedNormalRadius::sample(Rng& rng) const {
  return std::clamp(mu_ + sigma_ * z_.quantile(rng.uniform_open01()), min_, max_);
}

double TruncatedNormalRadius::cdf(double r) const {
  if (!(r > min_)) return 0.0;
  if (!(r < max_)) return 1.0;
  return z_.cdf((r - mu_) / sigma_);
}

std::string TruncatedNormalRadius::describe() const {
  return "truncated normal (mean " + num(mu_) + ", stddev " + num(sigma_) + ") on [" + num(min_) + ", " +
         num(max_) + "]";
}

}  // namespace fp
