#include "core/sampling/discrete_radius.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/sampling/parameter_checks.hpp"

namespace fp {

using sampling_detail::num;

namespace {
constexpr const char* kWho = "DiscreteRadius";
}

DiscreteRadius::DiscreteRadius(std::vector<std::pair<double, double>> radius_weight) {
  if (radius_weight.empty()) sampling_detail::fail(kWho, "radius_weight is empty");
  double total = 0.0;
  for (std::size_t i = 0; i < radius_weight.size(); ++i) {
    const std::string at = "radius_weight[" + std::to_string(i) + "]: ";
    sampling_detail::require_positive(kWho, at + "radius", radius_weight[i].first);
    const double w = radius_weight[i].second;
    if (!std::isfinite(w) || w < 0.0)
      sampling_detail::fail(kWho, at + "weight (" + num(w) + ") must be >= 0 and finite");
    total += w;
  }
  if (!(total > 0.0) || !std::isfinite(total))
    sampling_detail::fail(kWho, "the weights must have a positive finite sum (got " + num(total) + ")");
  std::sort(radius_weight.begin(), radius_weight.end());
  for (std::size_t i = 1; i < radius_weight.size(); ++i)
    if (radius_weight[i].first == radius_weight[i - 1].first)
      sampling_detail::fail(kWho, "radius " + num(radius_weight[i].first) + " is listed twice");

  double cumulative = 0.0, weighted_sum = 0.0;
  for (const auto& [r, w] : radius_weight) {
    if (w == 0.0) continue;
    radii_.push_back(r);
    probabilities_.push_back(w / total);
    cumulative += w;
    cumulative_.push_back(cumulative / total);
    weighted_sum += w * r;
  }
  cumulative_.back() = 1.0;  // so that every u in [0, 1) finds a radius
  mean_ = std::clamp(weighted_sum / total, radii_.front(), radii_.back());
}

double DiscreteRadius::sample(Rng& rng) const {
  const double u = rng.uniform01();
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
  return radii_[static_cast<std::size_t>(it - cumulative_.begin())];
}

double DiscreteRadius::cdf(double r) const {
  const auto it = std::upper_bound(radii_.begin(), radii_.end(), r);
  if (it == radii_.begin()) return 0.0;
  return cumulative_[static_cast<std::size_t>(it - radii_.begin()) - 1];
}

std::vector<std::pair<double, double>> DiscreteRadius::atoms() const {
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i < radii_.size(); ++i) out.emplace_back(radii_[i], probabilities_[i]);
  return out;
}

std::string DiscreteRadius::describe() const {
  std::string s = "discrete {";
  for (std::size_t i = 0; i < radii_.size(); ++i)
    s += (i ? ", " : "") + num(radii_[i]) + ": " + num(probabilities_[i]);
  return s + "}";
}

}  // namespace fp
