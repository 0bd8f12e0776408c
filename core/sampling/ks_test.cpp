#include "core/sampling/ks_test.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sampling/sort_doubles.hpp"

namespace fp {

double ks_statistic(std::vector<double> samples, const std::function<double(double)>& cdf) {
  if (samples.empty()) throw std::invalid_argument("ks_statistic: samples is empty");
  sort_doubles(samples);
  const double n = static_cast<double>(samples.size());
  double d = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double f = cdf(samples[i]);
    // F_n jumps from i/n to (i+1)/n at samples[i]; with ties the widest gap is still seen.
    d = std::max({d, (static_cast<double>(i) + 1.0) / n - f, f - static_cast<double>(i) / n});
  }
  return d;
}

double kolmogorov_survival(double lambda) {
  if (!(lambda > 0.0)) return 1.0;
  constexpr double kPi = 3.14159265358979323846;
  if (lambda < 1.0) {
    // 1 - sqrt(2 pi) / lambda * sum_{j>=1} exp(-(2j-1)^2 pi^2 / (8 lambda^2)): fast for small lambda.
    const double t = -kPi * kPi / (8.0 * lambda * lambda);
    double sum = 0.0;
    for (int j = 1; j <= 20; ++j) {
      const double term = std::exp((2.0 * j - 1.0) * (2.0 * j - 1.0) * t);
      sum += term;
      if (term < 1e-18 * sum) break;
    }
    return std::clamp(1.0 - std::sqrt(2.0 * kPi) / lambda * sum, 0.0, 1.0);
  }
  double sum = 0.0, sign = 1.0;
  for (int j = 1; j <= 100; ++j) {
    const double term = std::exp(-2.0 * j * j * lambda * lambda);
    sum += sign * term;
    if (term < 1e-18 * sum) break;
    sign = -sign;
  }
  return std::clamp(2.0 * sum, 0.0, 1.0);
}

double ks_pvalue(double d, std::size_t n) {
  if (n == 0) throw std::invalid_argument("ks_pvalue: n must be > 0");
  const double sn = std::sqrt(static_cast<double>(n));
  return kolmogorov_survival((sn + 0.12 + 0.11 / sn) * d);
}

}  // namespace fp
