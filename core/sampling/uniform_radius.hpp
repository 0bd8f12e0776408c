#pragma once
// Radius uniform on [min, max] (by count), e.g. the paper's U[0.01, 0.02] benchmark.
#include "core/sampling/radius_distribution.hpp"

namespace fp {

class UniformRadius final : public RadiusDistribution {
 public:
  /// Needs 0 < min < max, both finite (use ConstantRadius for min == max).
  UniformRadius(double min, double max);

  /// min + (max - min) * u with one uniform01() draw.
  double sample(Rng& rng) const override;
  double cdf(double r) const override;
  double r_min() const override { return min_; }
  double r_max() const override { return max_; }
  double mean() const override { return 0.5 * (min_ + max_); }
  std::string describe() const override;

 private:
  double min_, max_;
};

}  // namespace fp
