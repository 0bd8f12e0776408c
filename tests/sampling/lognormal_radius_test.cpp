// LognormalRadius: median, mean against closed forms and quadrature in log r.
#include "core/sampling/lognormal_radius.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sampling_test_util.hpp"

namespace fp {
namespace {

TEST(LognormalRadius, MedianOfSymmetricTruncationIsTheParentMedian) {
  const double median = 0.01, s = 0.5;
  const auto dist = LognormalRadius::from_median(median, s, median * std::exp(-3 * s), median * std::exp(3 * s));
  EXPECT_NEAR(dist.cdf(median), 0.5, 1e-14);
  EXPECT_NEAR(dist.mu_log(), std::log(median), 1e-15);
  auto radii = test::draw(dist, 20001, 9);
  std::nth_element(radii.begin(), radii.begin() + 10000, radii.end());
  // Sample median: sd ~ 1 / (2 f(m) sqrt(n)); f(m) of ln r ~ 1/(0.997 s sqrt(2 pi)).
  EXPECT_NEAR(std::log(radii[10000] / median), 0.0, 5.0 * s * 1.25 / std::sqrt(20001.0));
}

TEST(LognormalRadius, OneSidedTruncationMovesTheMedian) {
  // from_median names the parent median: cutting the upper tail only lowers the median.
  const auto dist = LognormalRadius::from_median(1.0, 1.0, 0.01, 2.0);
  EXPECT_GT(dist.cdf(1.0), 0.55);
}

TEST(LognormalRadius, WideTruncationRecoversTheParentMean) {
  const double mu = std::log(0.02), s = 0.4;
  const LognormalRadius dist(mu, s, std::exp(mu - 9 * s), std::exp(mu + 9 * s));
  EXPECT_NEAR(dist.mean() / std::exp(mu + 0.5 * s * s), 1.0, 1e-12);
}

struct Params {
  double mu_log, sigma_log, min, max;
};

class LognormalQuadrature : public ::testing::TestWithParam<Params> {};

TEST_P(LognormalQuadrature, CdfAndMeanMatchTheIntegratedDensity) {
  const auto [mu, s, lo, hi] = GetParam();
  const LognormalRadius dist(mu, s, lo, hi);
  // In y = ln r the density is normal; scaled at the end nearest the mode.
  const double ylo = std::log(lo), yhi = std::log(hi), c = std::clamp(mu, ylo, yhi);
  auto g = [&](double y) { return std::exp(-0.5 * ((y - mu) * (y - mu) - (c - mu) * (c - mu)) / (s * s)); };
  const double total = test::simpson(g, ylo, yhi, 20000);
  for (double t : {0.1, 0.4, 0.6, 0.9}) {
    const double y = ylo + t * (yhi - ylo);
    EXPECT_NEAR(dist.cdf(std::exp(y)), test::simpson(g, ylo, y, 20000) / total, 1e-9);
  }
  const double mean = test::simpson([&](double y) { return std::exp(y) * g(y); }, ylo, yhi, 20000) / total;
  EXPECT_NEAR(dist.mean() / mean, 1.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Cases, LognormalQuadrature,
                         ::testing::Values(Params{std::log(0.01), 0.5, 0.002, 0.05},
                                           Params{0.0, 1.0, 0.03, 30.0},
                                           Params{std::log(1e6), 0.1, 2e6, 3e6},  // far upper tail
                                           Params{std::log(1e-6), 0.2, 1e-8, 2e-7},  // far lower tail
                                           // sigma_log = 50: exp(sigma^2/2) overflows and the shifted
                                           // mass underflows; only their ratio is finite.
                                           Params{0.0, 50.0, 1e-3, 1e3}));

}  // namespace
}  // namespace fp
