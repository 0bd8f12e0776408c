#include "core/sampling/constant_radius.hpp"

#include "core/sampling/parameter_checks.hpp"

namespace fp {

using sampling_detail::num;

ConstantRadius::ConstantRadius(double radius) : radius_(radius) {
  sampling_detail::require_positive("ConstantRadius", "radius", radius);
}

double ConstantRadius::sample(Rng&) const { return radius_; }
double ConstantRadius::cdf(double r) const { return r < radius_ ? 0.0 : 1.0; }
std::string ConstantRadius::describe() const { return "constant " + num(radius_); }

}  // namespace fp
