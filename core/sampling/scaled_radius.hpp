#pragma once
// A radius law scaled by a factor s: R' = s R, the law's shape kept (`stop: {particles: N,
// scale_sizes: true}` solves for s so that N particles fill the container).
#include <string>
#include <utility>
#include <vector>

#include "core/sampling/radius_distribution.hpp"

namespace fp {

class ScaledRadius final : public RadiusDistribution {
 public:
  /// Needs a finite s > 0 (std::invalid_argument otherwise).
  ScaledRadius(RadiusDistributionPtr law, double scale);

  /// The law's own draw, times s (the same stream of draws for every s).
  double sample(Rng& rng) const override { return scale_ * law_->sample(rng); }
  double cdf(double r) const override { return law_->cdf(r / scale_); }
  double r_min() const override { return scale_ * law_->r_min(); }
  double r_max() const override { return scale_ * law_->r_max(); }
  double mean() const override { return scale_ * law_->mean(); }
  /// "<the law's>, scaled by s".
  std::string describe() const override;
  std::vector<std::pair<double, double>> atoms() const override;
  double scale() const { return scale_; }
  const RadiusDistribution& unscaled() const { return *law_; }

 private:
  RadiusDistributionPtr law_;
  double scale_;
};

}  // namespace fp
