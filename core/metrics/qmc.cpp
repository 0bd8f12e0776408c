#include "core/metrics/qmc.hpp"

#include <cmath>
#include <stdexcept>

#include "core/sampling/rng.hpp"

namespace fp {

double radical_inverse(std::uint64_t i, unsigned base) {
  const double inv = 1.0 / base;
  double f = inv, x = 0.0;
  for (; i > 0; i /= base, f *= inv) x += f * static_cast<double>(i % base);
  return x;
}

template <int D>
std::vector<Vec<D>> halton_points(std::size_t n) {
  constexpr unsigned kBases[3] = {2, 3, 5};
  std::vector<Vec<D>> pts(n);
  for (std::size_t k = 0; k < n; ++k)
    for (int a = 0; a < D; ++a) pts[k][a] = radical_inverse(k + 1, kBases[a]);
  return pts;
}

template <int D>
Vec<D> qmc_shift(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t mixed = stream;
  Rng rng(seed ^ Rng::splitmix64(mixed));
  Vec<D> s;
  for (int a = 0; a < D; ++a) s[a] = rng.uniform01();
  return s;
}

template <int D>
std::vector<Vec<D>> qmc_shifts(const QmcOptions& options) {
  if (options.replicates < 1) throw std::invalid_argument("QmcOptions: replicates must be >= 1");
  std::vector<Vec<D>> shifts;
  for (int k = 0; k < options.replicates; ++k)
    shifts.push_back(qmc_shift<D>(options.seed, static_cast<std::uint64_t>(k)));
  return shifts;
}

Estimate mean_and_error(const std::vector<double>& replicates) {
  Estimate e;
  if (replicates.empty()) return e;
  const double k = static_cast<double>(replicates.size());
  for (const double v : replicates) e.value += v;
  e.value /= k;
  if (replicates.size() < 2) return e;
  double ss = 0.0;
  for (const double v : replicates) ss += (v - e.value) * (v - e.value);
  e.std_error = std::sqrt(ss / (k * (k - 1.0)));
  return e;
}

template std::vector<Vec<2>> halton_points<2>(std::size_t);
template std::vector<Vec<3>> halton_points<3>(std::size_t);
template Vec<2> qmc_shift<2>(std::uint64_t, std::uint64_t);
template Vec<3> qmc_shift<3>(std::uint64_t, std::uint64_t);
template std::vector<Vec<2>> qmc_shifts<2>(const QmcOptions&);
template std::vector<Vec<3>> qmc_shifts<3>(const QmcOptions&);

}  // namespace fp
