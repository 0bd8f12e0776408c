#pragma once
// Shared helpers of the sampling tests: seeded draws, sample moments, Simpson quadrature and a
// check that a constructor throws std::invalid_argument naming the bad parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/sampling/radius_distribution.hpp"

namespace fp::test {

inline std::vector<double> draw(const RadiusDistribution& dist, std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> out(n);
  for (auto& r : out) r = dist.sample(rng);
  return out;
}

struct Moments {
  double mean = 0.0, sd = 0.0;
};

inline Moments moments(const std::vector<double>& x) {
  double m = 0.0;
  for (double v : x) m += v;
  m /= static_cast<double>(x.size());
  double s2 = 0.0;
  for (double v : x) s2 += (v - m) * (v - m);
  return {m, std::sqrt(s2 / static_cast<double>(x.size() - 1))};
}

/// Composite Simpson rule with n (even) intervals.
inline double simpson(const std::function<double(double)>& f, double a, double b, int n = 4000) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return s * h / 3.0;
}

/// make() must throw std::invalid_argument whose message contains every one of `words`.
inline void expect_invalid(const std::function<void()>& make, const std::vector<std::string>& words) {
  try {
    make();
    ADD_FAILURE() << "no exception; expected one mentioning '" << words.front() << "'";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    for (const auto& w : words) EXPECT_NE(msg.find(w), std::string::npos) << "message: " << msg << "\nlacks: " << w;
  }
}

}  // namespace fp::test
