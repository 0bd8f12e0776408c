#pragma once
// Radius ~ N(mean, stddev^2) conditioned on min <= r <= max. `mean` and `stddev` are the
// parameters of the parent (untruncated) normal; mean() returns the mean of the truncated one.
// Sampled exactly by inverse CDF (one uniform_open01() draw per radius), with probabilities
// taken on the small side of the interval, so truncation far in a tail stays accurate.
#include "core/sampling/radius_distribution.hpp"
#include "core/sampling/standard_normal.hpp"

namespace fp {

class TruncatedNormalRadius final : public RadiusDistribution {
 public:
  /// Needs finite mean, stddev > 0, 0 < min < max, and a parent probability of [min, max]
  /// of at least 1e-300 (about 37 standard deviations into a tail).
  TruncatedNormalRadius(double mean, double stddev, double min, double max);

  double sample(Rng& rng) const override;
  double cdf(double r) const override;
  double r_min() const override { return min_; }
  double r_max() const override { return max_; }
  double mean() const override { return mean_truncated_; }
  std::string describe() const override;

  double parent_mean() const { return mu_; }
  double parent_stddev() const { return sigma_; }

 private:
  double mu_, sigma_, min_, max_;
  TruncatedStandardNormal z_;
  double mean_truncated_;
};

}  // namespace fp
