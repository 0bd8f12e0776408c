#include "core/sampling/lognormal_radius.hpp"

#include <algorithm>
#include <cmath>

#include "core/sampling/parameter_checks.hpp"

namespace fp {

using sampling_detail::num;

namespace {
constexpr const char* kWho = "LognormalRadius";

TruncatedStandardNormal checked_standardised(double mu_log, double sigma_log, double min, double max) {
  sampling_detail::require_finite(kWho, "mu_log", mu_log);
  sampling_detail::require_positive(kWho, "sigma_log", sigma_log);
  sampling_detail::require_bounds(kWho, min, max);
  const double a = (std::log(min) - mu_log) / sigma_log, b = (std::log(max) - mu_log) / sigma_log;
  if (!std::isfinite(a) || !std::isfinite(b))
    sampling_detail::fail(kWho, "sigma_log (" + num(sigma_log) + ") is too small for [min, max] = [" + num(min) +
                                    ", " + num(max) + "]: the standardised bounds overflow");
  TruncatedStandardNormal z(a, b);
  if (!(z.mass() >= 1e-300))
    sampling_detail::fail(kWho, "[min, max] = [" + num(min) + ", " + num(max) +
                                    "] has probability below 1e-300 under the lognormal (mu_log " + num(mu_log) +
                                    ", sigma_log " + num(sigma_log) + ") (too far in a tail, or too narrow)");
  return z;
}
}  // namespace

LognormalRadius::LognormalRadius(double mu_log, double sigma_log, double min, double max)
    : mu_(mu_log), sigma_(sigma_log), min_(min), max_(max), z_(checked_standardised(mu_log, sigma_log, min, max)) {
  // E[r] = exp(mu + sigma^2 / 2) P(a - sigma <= Z <= b - sigma) / P(a <= Z <= b), in logs: the
  // factors can overflow and underflow separately although the mean lies in [min, max].
  const TruncatedStandardNormal shifted(z_.lower() - sigma_, z_.upper() - sigma_);
  const double log_mean = mu_ + 0.5 * sigma_ * sigma_ + shifted.log_mass() - z_.log_mass();
  // A [min, max] so narrow that the shifted log-mass cancels out: there exp(E[ln r]) is the mean.
  const double mean = std::isfinite(log_mean) ? std::exp(log_mean) : std::exp(mu_ + sigma_ * z_.mean());
  mean_truncated_ = std::clamp(mean, min_, max_);
}

LognormalRadius LognormalRadius::from_median(double median, double sigma_log, double min, double max) {
  sampling_detail::require_positive(kWho, "median", median);
  return LognormalRadius(std::log(median), sigma_log, min, max);
}

double LognormalRadius::sample(Rng& rng) const {
  return std::clamp(std::exp(mu_ + sigma_ * z_.quantile(rng.uniform_open01())), min_, max_);
}

double LognormalRadius::cdf(double r) const {
  if (!(r > min_)) return 0.0;
  if (!(r < max_)) return 1.0;
  return z_.cdf((std::log(r) - mu_) / sigma_);
}

std::string LognormalRadius::describe() const {
  return "lognormal (mu_log " + num(mu_) + ", sigma_log " + num(sigma_) + ") on [" + num(min_) + ", " +
         num(max_) + "]";
}

}  // namespace fp
