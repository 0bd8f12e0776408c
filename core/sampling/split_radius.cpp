#include "core/sampling/split_radius.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/sampling/parameter_checks.hpp"

namespace fp {

using sampling_detail::num;

SplitRadius::SplitRadius(RadiusDistributionPtr law, double r_s, Side side)
    : law_(std::move(law)), r_s_(r_s), side_(side), f_(law_->cdf(r_s)) {
  if (!(f_ >= 1e-4 && f_ <= 1 - 1e-4))
    throw std::invalid_argument("SplitRadius: the split " + num(r_s) + " leaves less than a part in 10^4 of " +
                                law_->describe() + " on one side (F = " + num(f_) + ")");
  lo_ = side == Side::Below ? law_->r_min() : r_s;
  hi_ = side == Side::Below ? r_s : law_->r_max();
  // The mean by count: lo + the integral of 1 - F over [lo, hi] (trapezoids on 4,096 steps).
  const int steps = 4096;
  double tail = 0;
  for (int k = 0; k < steps; ++k) {
    const double a = lo_ + (hi_ - lo_) * k / steps, b = lo_ + (hi_ - lo_) * (k + 1) / steps;
    tail += (2 - cdf(a) - cdf(b)) / 2 * (b - a);
  }
  mean_ = lo_ + tail;
}

double SplitRadius::sample(Rng& rng) const {
  for (int tries = 0; tries < 1000000; ++tries) {
    const double r = law_->sample(rng);
    if ((r <= r_s_) == (side_ == Side::Below)) return r;
  }
  throw std::runtime_error("SplitRadius: no draw of " + law_->describe() + " fell on its side of " + num(r_s_));
}

double SplitRadius::cdf(double r) const {
  const double F = law_->cdf(r);
  return side_ == Side::Below ? std::clamp(F / f_, 0.0, 1.0) : std::clamp((F - f_) / (1 - f_), 0.0, 1.0);
}

std::string SplitRadius::describe() const {
  return law_->describe() + (side_ == Side::Below ? ", r <= " : ", r > ") + num(r_s_);
}

std::vector<std::pair<double, double>> SplitRadius::atoms() const {
  std::vector<std::pair<double, double>> out;
  for (const auto& [r, p] : law_->atoms())
    if ((r <= r_s_) == (side_ == Side::Below)) out.emplace_back(r, p / (side_ == Side::Below ? f_ : 1 - f_));
  return out;
}

}  // namespace fp
