#include "core/sampling/histogram_radius.hpp"

#include <algorithm>
#include <cmath>

#include "core/sampling/parameter_checks.hpp"

namespace fp {

using sampling_detail::num;

namespace {
constexpr const char* kWho = "HistogramRadius";
}

HistogramRadius::HistogramRadius(std::vector<double> edges, std::vector<double> weights)
    : edges_(std::move(edges)) {
  if (edges_.size() < 2) sampling_detail::fail(kWho, "edges needs at least 2 values (got " + std::to_string(edges_.size()) + ")");
  if (weights.size() != edges_.size() - 1)
    sampling_detail::fail(kWho, "weights needs one value per bin: " + std::to_string(edges_.size() - 1) +
                                    " (got " + std::to_string(weights.size()) + ")");
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    const std::string name = "edges[" + std::to_string(i) + "]";
    sampling_detail::require_positive(kWho, name, edges_[i]);
    if (i > 0 && !(edges_[i] > edges_[i - 1]))
      sampling_detail::fail(kWho, name + " (" + num(edges_[i]) + ") must be > edges[" + std::to_string(i - 1) +
                                      "] (" + num(edges_[i - 1]) + ")");
  }
  double total = 0.0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (!std::isfinite(weights[i]) || weights[i] < 0.0)
      sampling_detail::fail(kWho, "weights[" + std::to_string(i) + "] (" + num(weights[i]) + ") must be >= 0 and finite");
    total += weights[i];
  }
  if (!(total > 0.0) || !std::isfinite(total))
    sampling_detail::fail(kWho, "the weights must have a positive finite sum (got " + num(total) + ")");

  double cumulative = 0.0, weighted_sum = 0.0;
  std::size_t first = weights.size(), last = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    probabilities_.push_back(weights[i] / total);
    cumulative += weights[i];
    cumulative_.push_back(cumulative / total);
    weighted_sum += weights[i] * 0.5 * (edges_[i] + edges_[i + 1]);
    if (weights[i] > 0.0) {
      first = std::min(first, i);
      last = i;
    }
  }
  // Exactly 1 from the last drawable bin on, so that rounding can never hand u to a trailing empty bin.
  std::fill(cumulative_.begin() + static_cast<std::ptrdiff_t>(last), cumulative_.end(), 1.0);
  r_min_ = edges_[first];
  r_max_ = edges_[last + 1];
  mean_ = std::clamp(weighted_sum / total, r_min_, r_max_);
}

double HistogramRadius::sample(Rng& rng) const {
  const double u = rng.uniform01();
  // First bin whose cumulative weight exceeds u: never a bin of weight 0.
  const auto bin = static_cast<std::size_t>(std::upper_bound(cumulative_.begin(), cumulative_.end(), u) -
                                            cumulative_.begin());
  const double lo = edges_[bin], hi = edges_[bin + 1];
  return std::min(hi, lo + (hi - lo) * rng.uniform01());
}

double HistogramRadius::cdf(double r) const {
  if (!(r > edges_.front())) return 0.0;
  if (!(r < edges_.back())) return 1.0;
  // Bin containing r: edges_[bin] <= r < edges_[bin + 1].
  const auto bin = static_cast<std::size_t>(std::upper_bound(edges_.begin(), edges_.end(), r) - edges_.begin()) - 1;
  const double below = bin == 0 ? 0.0 : cumulative_[bin - 1];
  const double f = below + probabilities_[bin] * (r - edges_[bin]) / (edges_[bin + 1] - edges_[bin]);
  return std::clamp(f, 0.0, 1.0);
}

std::string HistogramRadius::describe() const {
  return "histogram (" + std::to_string(probabilities_.size()) + " bins) on [" + num(r_min_) + ", " +
         num(r_max_) + "]";
}

}  // namespace fp
