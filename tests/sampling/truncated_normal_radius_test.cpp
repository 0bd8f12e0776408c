// TruncatedNormalRadius against quadrature of the normal density on [min, max].
#include "core/sampling/truncated_normal_radius.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sampling_test_util.hpp"

namespace fp {
namespace {

struct Params {
  double mean, stddev, min, max;
};

class TruncatedNormalQuadrature : public ::testing::TestWithParam<Params> {};

TEST_P(TruncatedNormalQuadrature, CdfAndMeanMatchTheIntegratedDensity) {
  const auto [mu, sd, lo, hi] = GetParam();
  const TruncatedNormalRadius dist(mu, sd, lo, hi);
  // Unnormalised density, scaled at the end nearest the mode so that tails do not underflow.
  const double c = std::clamp(mu, lo, hi);
  auto density = [&](double r) {
    const double z = (r - mu) / sd, zc = (c - mu) / sd;
    return std::exp(-0.5 * (z - zc) * (z + zc));
  };
  const double total = test::simpson(density, lo, hi, 40000);
  for (double t : {0.05, 0.2, 0.5, 0.8, 0.95}) {
    const double r = lo + t * (hi - lo);
    EXPECT_NEAR(dist.cdf(r), test::simpson(density, lo, r, 40000) / total, 1e-9) << "r = " << r;
  }
  const double mean = test::simpson([&](double r) { return r * density(r); }, lo, hi, 40000) / total;
  EXPECT_NEAR(dist.mean(), mean, 1e-10 * hi);
}

INSTANTIATE_TEST_SUITE_P(Cases, TruncatedNormalQuadrature,
                         ::testing::Values(Params{0.015, 0.003, 0.01, 0.02}, Params{0.011, 0.004, 0.01, 0.02},
                                           Params{0.0, 1.0, 6.0, 6.5}, Params{10.0, 1.0, 1.0, 2.0},
                                           Params{0.0, 1.0, 30.0, 31.0}, Params{1.0, 0.01, 0.5, 0.63},
                                           Params{1e6, 2e5, 5e5, 2e6}, Params{2e-6, 5e-7, 1e-6, 3e-6}));

TEST(TruncatedNormalRadius, SymmetricTruncationKeepsTheMeanAndHalvesAtIt) {
  const TruncatedNormalRadius dist(0.015, 0.003, 0.01, 0.02);
  EXPECT_NEAR(dist.mean(), 0.015, 1e-15);
  EXPECT_NEAR(dist.cdf(0.015), 0.5, 1e-15);
  EXPECT_EQ(dist.parent_mean(), 0.015);
  EXPECT_EQ(dist.parent_stddev(), 0.003);
}

TEST(TruncatedNormalRadius, FarRightTailIsNearlyExponential) {
  // Beyond a = 30 standard deviations, Q(a + t) / Q(a) = exp(-a t - t^2/2) R(a + t) / R(a), with
  // the Mills ratio R(x) = (1/x)(1 - 1/x^2 + 3/x^4 - 15/x^6 + ...) (error ~1e-12 at x = 30).
  // The upper bound of 31 removes Q(31)/Q(30), about 1e-13 of the mass.
  const TruncatedNormalRadius dist(0.0, 1.0, 30.0, 31.0);
  auto mills = [](double x) { const double y = 1 / (x * x); return (1 - y + 3 * y * y - 15 * y * y * y) / x; };
  for (double t : {0.01, 0.03, 0.1})
    EXPECT_NEAR(dist.cdf(30.0 + t), 1.0 - std::exp(-30.0 * t - 0.5 * t * t) * mills(30 + t) / mills(30), 1e-10);
  EXPECT_NEAR(dist.mean(), 30.0 + 1.0 / 30.0, 1e-3);
}

TEST(TruncatedNormalRadius, WideTruncationRecoversTheParentMoments) {
  const TruncatedNormalRadius dist(1.0, 0.1, 0.2, 1.8);  // +-8 sd
  EXPECT_NEAR(dist.mean(), 1.0, 1e-14);
  EXPECT_NEAR(dist.cdf(1.1), 0.841344746068542949, 1e-14);  // Phi(1)
  const auto [mean, sd] = test::moments(test::draw(dist, 40000, 11));
  EXPECT_NEAR(sd, 0.1, 0.003);
}

}  // namespace
}  // namespace fp
