#include "core/metrics/radius_scale_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/metrics/radii_fit.hpp"

namespace fp {
namespace {

/// The distinct radii (equal within kRadiusSlack) with their counts, largest count first.
std::vector<std::pair<double, std::uint64_t>> distinct(std::span<const double> radii) {
  std::vector<double> sorted(radii.begin(), radii.end());
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::pair<double, std::uint64_t>> out;
  for (const double r : sorted) {
    if (!out.empty() && r - out.back().first <= kRadiusSlack * out.back().first) ++out.back().second;
    else out.emplace_back(r, 1);
  }
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  return out;
}

/// How many radii fall on the values of `atoms` scaled by s.
std::uint64_t on_values(const std::vector<std::pair<double, std::uint64_t>>& values,
                        const std::vector<std::pair<double, double>>& atoms, double s) {
  std::uint64_t n = 0;
  for (const auto& [r, count] : values) {
    const double x = r / s;
    const auto it = std::lower_bound(atoms.begin(), atoms.end(), x, [](const auto& a, double v) { return a.first < v; });
    double excess = INFINITY;
    if (it != atoms.end()) excess = std::min(excess, (it->first - x) / it->first);
    if (it != atoms.begin()) excess = std::min(excess, (x - std::prev(it)->first) / std::prev(it)->first);
    if (excess <= kRadiusSlack) n += count;
  }
  return n;
}

}  // namespace

double fit_radius_scale(std::span<const double> radii, const RadiusDistribution& law) {
  if (radii.empty()) return 1.0;
  double sum = 0, lo = INFINITY, hi = 0;
  for (const double r : radii) sum += r, lo = std::min(lo, r), hi = std::max(hi, r);
  const double by_mean = sum / static_cast<double>(radii.size()) / law.mean();
  const std::vector<std::pair<double, double>> atoms = law.atoms();
  if (atoms.empty()) {
    const double smallest = hi / law.r_max(), largest = lo / law.r_min();  // the scales keeping every radius in range
    return smallest <= largest ? std::clamp(by_mean, smallest, largest) : by_mean;
  }
  const auto values = distinct(radii);
  const double common = values.front().first;
  double best = by_mean;
  std::uint64_t best_on = 0;
  for (const auto& [a, p] : atoms) {
    const double s = common / a;
    const std::uint64_t on = on_values(values, atoms, s);
    if (on > best_on || (on == best_on && std::abs(std::log(s / by_mean)) < std::abs(std::log(best / by_mean))))
      best = s, best_on = on;
  }
  return best;
}

}  // namespace fp
