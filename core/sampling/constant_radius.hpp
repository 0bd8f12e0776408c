#pragma once
// Every particle has the same radius (monodisperse packings).
#include "core/sampling/radius_distribution.hpp"

namespace fp {

class ConstantRadius final : public RadiusDistribution {
 public:
  /// Throws std::invalid_argument unless radius is positive and finite.
  explicit ConstantRadius(double radius);

  /// Returns the radius without drawing from rng (the stream is left untouched).
  double sample(Rng& rng) const override;
  double cdf(double r) const override;
  double r_min() const override { return radius_; }
  double r_max() const override { return radius_; }
  double mean() const override { return radius_; }
  std::string describe() const override;
  std::vector<std::pair<double, double>> atoms() const override { return {{radius_, 1.0}}; }

 private:
  double radius_;
};

}  // namespace fp
