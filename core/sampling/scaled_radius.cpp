#include "core/sampling/scaled_radius.hpp"

#include <cmath>
#include <stdexcept>

#include "core/sampling/parameter_checks.hpp"

namespace fp {

using sampling_detail::num;

ScaledRadius::ScaledRadius(RadiusDistributionPtr law, double scale) : law_(std::move(law)), scale_(scale) {
  if (!(scale > 0) || !std::isfinite(scale))
    throw std::invalid_argument("ScaledRadius: the scale must be a finite positive number (got " + num(scale) + ")");
}

std::string ScaledRadius::describe() const { return law_->describe() + ", scaled by " + num(scale_); }

std::vector<std::pair<double, double>> ScaledRadius::atoms() const {
  std::vector<std::pair<double, double>> out = law_->atoms();
  for (auto& atom : out) atom.first *= scale_;
  return out;
}

}  // namespace fp
