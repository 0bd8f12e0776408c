#pragma once
// A finite set of radii with relative weights by count (e.g. a bidisperse mixture): P(R = r_i)
// = w_i / sum w. The CDF is a step function. Sampled by inverse CDF on the cumulative weights
// (one uniform01() draw per radius, binary search).
#include <utility>
#include <vector>

#include "core/sampling/radius_distribution.hpp"

namespace fp {

class DiscreteRadius final : public RadiusDistribution {
 public:
  /// Pairs (radius, weight): radii positive, finite and distinct (any order); weights finite and
  /// >= 0 with a positive sum. Entries of weight 0 are dropped (they can never be drawn and must
  /// not widen [r_min, r_max]).
  explicit DiscreteRadius(std::vector<std::pair<double, double>> radius_weight);

  double sample(Rng& rng) const override;
  double cdf(double r) const override;
  double r_min() const override { return radii_.front(); }
  double r_max() const override { return radii_.back(); }
  double mean() const override { return mean_; }
  std::string describe() const override;
  std::vector<std::pair<double, double>> atoms() const override;

  /// Radii with positive weight, increasing, and their probabilities (summing to 1).
  const std::vector<double>& radii() const { return radii_; }
  const std::vector<double>& probabilities() const { return probabilities_; }

 private:
  std::vector<double> radii_, probabilities_;
  std::vector<double> cumulative_;  // cumulative_[i] = P(R <= radii_[i]); back() == 1 exactly
  double mean_ = 0.0;
};

}  // namespace fp
