#pragma once
// Particle size distributions, stated on the radius. Every distribution is bounded:
// the packer needs r_min and r_max (grid cells, neighbour radius), as paper 002 requires.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/sampling/rng.hpp"

namespace fp {

class RadiusDistribution {
 public:
  virtual ~RadiusDistribution() = default;
  /// One radius, drawn by the distribution's own (specified, portable) algorithm.
  virtual double sample(Rng& rng) const = 0;
  /// P(R <= r): the CDF of the radius by count, used by K-S checks of packings.
  virtual double cdf(double r) const = 0;
  virtual double r_min() const = 0;
  virtual double r_max() const = 0;
  /// Mean radius by count.
  virtual double mean() const = 0;
  /// One-line description, e.g. "uniform [0.01, 0.02]".
  virtual std::string describe() const = 0;
  /// The point masses (radius, probability), radii increasing, probabilities summing to 1, of a
  /// discrete law (constant: one); empty for a law with a density. The goodness-of-fit test of a
  /// packing's radii depends on it: counts per value for a discrete law, K-S for a continuous one.
  virtual std::vector<std::pair<double, double>> atoms() const { return {}; }
};

using RadiusDistributionPtr = std::shared_ptr<const RadiusDistribution>;

}  // namespace fp
