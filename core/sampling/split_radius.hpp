#pragma once
// One side of a radius law split at r_s (void filling's `split`): the law conditioned on
// r > r_s (the part a packer packs) or on r <= r_s (the part the voids take), so that the two,
// in the law's proportions F(r_s) : 1 - F(r_s) by count, are a sample of the whole law.
#include <string>
#include <utility>
#include <vector>

#include "core/sampling/radius_distribution.hpp"

namespace fp {

class SplitRadius final : public RadiusDistribution {
 public:
  enum class Side { Below, Above };  ///< r <= r_s, or r > r_s
  /// Needs F(r_s) strictly between 0 and 1 (both sides non-empty).
  SplitRadius(RadiusDistributionPtr law, double r_s, Side side);

  /// Draws of the law until one falls on this side (at least a part in 10^4 of them does).
  double sample(Rng& rng) const override;
  double cdf(double r) const override;
  double r_min() const override { return lo_; }
  double r_max() const override { return hi_; }
  double mean() const override { return mean_; }
  std::string describe() const override;
  std::vector<std::pair<double, double>> atoms() const override;
  /// F(r_s) of the whole law: the share of this split below it.
  double share_below() const { return f_; }

 private:
  RadiusDistributionPtr law_;
  double r_s_;
  Side side_;
  double f_;          ///< F(r_s)
  double lo_, hi_;    ///< the side's range
  double mean_ = 0.0;
};

}  // namespace fp
