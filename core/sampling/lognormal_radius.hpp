#pragma once
// Lognormal radius: ln r ~ N(mu_log, sigma_log^2) (natural log of the radius), conditioned on
// min <= r <= max. Sampled exactly by inverse CDF on ln r (one uniform_open01() draw per radius).
// from_median() takes the median of the parent (untruncated) lognormal, exp(mu_log); it is also
// the median of the truncated one only when the truncation removes equal mass on both sides.
#include "core/sampling/radius_distribution.hpp"
#include "core/sampling/standard_normal.hpp"

namespace fp {

class LognormalRadius final : public RadiusDistribution {
 public:
  /// Needs finite mu_log, sigma_log > 0, 0 < min < max, and a parent probability of [min, max]
  /// of at least 1e-300.
  LognormalRadius(double mu_log, double sigma_log, double min, double max);
  /// mu_log = ln(median); median must be positive and finite.
  static LognormalRadius from_median(double median, double sigma_log, double min, double max);

  double sample(Rng& rng) const override;
  double cdf(double r) const override;
  double r_min() const override { return min_; }
  double r_max() const override { return max_; }
  double mean() const override { return mean_truncated_; }
  std::string describe() const override;

  double mu_log() const { return mu_; }
  double sigma_log() const { return sigma_; }

 private:
  double mu_, sigma_, min_, max_;
  TruncatedStandardNormal z_;
  double mean_truncated_;
};

}  // namespace fp
