#include "core/sampling/gradation_radius.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/sampling/parameter_checks.hpp"

namespace fp {

using sampling_detail::num;

namespace {
constexpr const char* kWho = "GradationRadius";

/// Integral of exp(a x) over [0, L], without cancellation for small a L.
double integral_exp(double a, double L) { return a == 0.0 ? L : std::expm1(a * L) / a; }
}  // namespace

GradationRadius::GradationRadius(std::vector<std::pair<double, double>> diameter_percent_passing, Basis basis,
                                 int dimension)
    : points_(std::move(diameter_percent_passing)), basis_(basis), dimension_(dimension) {
  if (dimension != 2 && dimension != 3)
    sampling_detail::fail(kWho, "dimension (" + std::to_string(dimension) + ") must be 2 or 3");
  if (basis != Basis::Mass && basis != Basis::Count) sampling_detail::fail(kWho, "basis must be Mass or Count");
  if (points_.size() < 2)
    sampling_detail::fail(kWho, "diameter_percent_passing needs at least 2 points (got " +
                                    std::to_string(points_.size()) + ")");
  for (std::size_t j = 0; j < points_.size(); ++j) {
    const std::string at = "diameter_percent_passing[" + std::to_string(j) + "]: ";
    const auto [d, p] = points_[j];
    sampling_detail::require_positive(kWho, at + "diameter", d);
    if (!std::isfinite(p) || p < 0.0 || p > 100.0)
      sampling_detail::fail(kWho, at + "percent passing (" + num(p) + ") must be in [0, 100]");
    if (j == 0) continue;
    const auto [d_prev, p_prev] = points_[j - 1];
    if (!(d > d_prev))
      sampling_detail::fail(kWho, at + "diameter (" + num(d) + ") must be > the previous diameter (" +
                                      num(d_prev) + ")");
    if (p < p_prev)
      sampling_detail::fail(kWho, at + "percent passing (" + num(p) + ") must be >= the previous one (" +
                                      num(p_prev) + ")");
  }
  if (points_.front().second != 0.0)
    sampling_detail::fail(kWho, "diameter_percent_passing[0]: percent passing (" + num(points_.front().second) +
                                    ") must be 0 at the smallest sieve (no particle below it)");
  if (points_.back().second != 100.0)
    sampling_detail::fail(kWho, "diameter_percent_passing[" + std::to_string(points_.size() - 1) +
                                    "]: percent passing (" + num(points_.back().second) +
                                    ") must be 100 at the largest sieve (no particle above it)");

  k_ = basis == Basis::Count ? 0.0 : static_cast<double>(dimension);
  const std::size_t bins = points_.size() - 1;
  const double d0 = points_.front().first;
  // Count weight of bin i: (w_i / L_i) (d_i / d0)^-k integral_exp(-k, L_i), in logs (the factors
  // span many decades for wide gradings), normalised by the largest before exponentiating.
  std::vector<double> log_weight(bins, -std::numeric_limits<double>::infinity());
  double log_max = -std::numeric_limits<double>::infinity();
  std::size_t first = bins, last = 0;
  for (std::size_t i = 0; i < bins; ++i) {
    const double d = points_[i].first, w = (points_[i + 1].second - points_[i].second) / 100.0;
    const double L = std::log(points_[i + 1].first / d);
    log_width_.push_back(L);
    if (!(w > 0.0)) continue;
    first = std::min(first, i);
    last = i;
    log_weight[i] = std::log(w / L) - k_ * std::log(d / d0) + std::log(integral_exp(-k_, L));
    log_max = std::max(log_max, log_weight[i]);
  }
  double total = 0.0;
  for (std::size_t i = 0; i < bins; ++i) {
    count_prob_.push_back(std::exp(log_weight[i] - log_max));
    total += count_prob_.back();
  }
  double cumulative = 0.0, mean_d = 0.0;
  for (std::size_t i = 0; i < bins; ++i) {
    count_prob_[i] /= total;
    cumulative += count_prob_[i];
    count_cumulative_.push_back(cumulative);
    // E[d | bin i] = d_i * integral_exp(1 - k, L) / integral_exp(-k, L).
    const double L = log_width_[i];
    mean_d += count_prob_[i] * points_[i].first * integral_exp(1.0 - k_, L) / integral_exp(-k_, L);
  }
  std::fill(count_cumulative_.begin() + static_cast<std::ptrdiff_t>(last), count_cumulative_.end(), 1.0);
  r_min_ = 0.5 * points_[first].first;
  r_max_ = 0.5 * points_[last + 1].first;
  // A sieve of 4.9e-324 (the smallest double) has a radius of 0: no radius 0 may be drawn.
  sampling_detail::require_positive(kWho, "half the smallest sieve with particles (the smallest radius)", r_min_);
  mean_ = std::clamp(0.5 * mean_d, r_min_, r_max_);
}

double GradationRadius::sample(Rng& rng) const {
  const double u = rng.uniform01();
  const auto bin = static_cast<std::size_t>(
      std::upper_bound(count_cumulative_.begin(), count_cumulative_.end(), u) - count_cumulative_.begin());
  const double v = rng.uniform01(), L = log_width_[bin];
  // Inverse of the in-bin count CDF integral_exp(-k, x) / integral_exp(-k, L).
  const double x = k_ == 0.0 ? v * L : -std::log1p(v * std::expm1(-k_ * L)) / k_;
  const double d = points_[bin].first * std::exp(std::clamp(x, 0.0, L));
  return std::clamp(0.5 * d, 0.5 * points_[bin].first, 0.5 * points_[bin + 1].first);
}

double GradationRadius::bin_count_cdf(std::size_t i, double d) const {
  const double L = log_width_[i];
  const double x = std::clamp(std::log(d / points_[i].first), 0.0, L);
  return integral_exp(-k_, x) / integral_exp(-k_, L);
}

double GradationRadius::cdf(double r) const {
  const double d = 2.0 * r;
  if (!(d > points_.front().first)) return 0.0;
  if (!(d < points_.back().first)) return 1.0;
  const auto upper = std::upper_bound(points_.begin(), points_.end(), d,
                                      [](double v, const std::pair<double, double>& p) { return v < p.first; });
  const auto bin = static_cast<std::size_t>(upper - points_.begin()) - 1;
  const double below = bin == 0 ? 0.0 : count_cumulative_[bin - 1];
  return std::clamp(below + count_prob_[bin] * bin_count_cdf(bin, d), 0.0, 1.0);
}

double GradationRadius::passing_fraction(double diameter) const {
  if (!(diameter > points_.front().first)) return 0.0;
  if (!(diameter < points_.back().first)) return 1.0;
  const auto upper = std::upper_bound(points_.begin(), points_.end(), diameter,
                                      [](double v, const std::pair<double, double>& p) { return v < p.first; });
  const auto i = static_cast<std::size_t>(upper - points_.begin()) - 1;
  const double t = std::log(diameter / points_[i].first) / log_width_[i];
  return (points_[i].second + (points_[i + 1].second - points_[i].second) * t) / 100.0;
}

std::string GradationRadius::describe() const {
  const std::string by = basis_ == Basis::Mass ? "mass (" + std::to_string(dimension_) + "D)" : "count";
  return "gradation by " + by + ", " + std::to_string(points_.size()) + " sieves, d in [" +
         num(points_.front().first) + ", " + num(points_.back().first) + "]";
}

}  // namespace fp
