#include "core/sampling/radius_moment.hpp"

#include <cmath>
#include <stdexcept>

namespace fp {

double radius_moment(const RadiusDistribution& d, int k) {
  if (k < 1) throw std::invalid_argument("radius_moment: k must be >= 1");
  if (const auto atoms = d.atoms(); !atoms.empty()) {
    double m = 0;
    for (const auto& [r, p] : atoms) m += p * std::pow(r, k);
    return m;
  }
  const double lo = d.r_min(), hi = d.r_max();
  double m = std::pow(lo, k);
  if (!(hi > lo)) return m;
  // Substituting r = lo e^t: dr = r dt, so the integrand is k r^k (1 - F(r)) dt; Simpson's rule.
  constexpr int kSteps = 4096;  // even
  const double dt = std::log(hi / lo) / kSteps;
  const auto f = [&](int i) {
    const double r = i == kSteps ? hi : lo * std::exp(i * dt);
    return k * std::pow(r, k) * (1.0 - d.cdf(r));
  };
  double s = f(0) + f(kSteps);
  for (int i = 1; i < kSteps; ++i) s += (i % 2 ? 4.0 : 2.0) * f(i);
  return m + s * dt / 3.0;
}

}  // namespace fp
