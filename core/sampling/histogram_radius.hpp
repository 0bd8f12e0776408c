#pragma once
// Piecewise-uniform radius: bin i = [edges[i], edges[i+1]] holds the fraction
// weights[i] / sum(weights) of the particles (by count), uniformly in radius within the bin.
// Sampled exactly: one uniform01() draw picks the bin by its cumulative weight, a second places
// the radius uniformly inside it (two draws keep full resolution in light bins).
#include <vector>

#include "core/sampling/radius_distribution.hpp"

namespace fp {

class HistogramRadius final : public RadiusDistribution {
 public:
  /// edges: positive, finite, strictly increasing, at least 2; weights: one per bin, finite,
  /// >= 0, positive sum. r_min/r_max span the bins of positive weight only.
  HistogramRadius(std::vector<double> edges, std::vector<double> weights);

  double sample(Rng& rng) const override;
  double cdf(double r) const override;
  double r_min() const override { return r_min_; }
  double r_max() const override { return r_max_; }
  double mean() const override { return mean_; }
  std::string describe() const override;

  const std::vector<double>& edges() const { return edges_; }
  /// Bin probabilities (summing to 1).
  const std::vector<double>& probabilities() const { return probabilities_; }

 private:
  std::vector<double> edges_, probabilities_;
  std::vector<double> cumulative_;  // cumulative_[i] = P(R <= edges_[i + 1]); back() == 1 exactly
  double r_min_ = 0.0, r_max_ = 0.0, mean_ = 0.0;
};

}  // namespace fp
