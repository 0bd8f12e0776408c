// Normal CDF / quantile / truncated standard normal against high-precision reference values
// (mpmath, 40 digits) and against direct numerical integration of the density.
#include "core/sampling/standard_normal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "sampling_test_util.hpp"

namespace fp {
namespace {

double rel_err(double got, double want) { return std::fabs(got - want) / std::fabs(want); }

TEST(StandardNormal, ReferenceValues) {
  EXPECT_LT(rel_err(normal_quantile(0.975), 1.959963984540054235), 1e-15);
  EXPECT_LT(rel_err(normal_quantile(1e-10), -6.361340902404056205), 1e-14);
  EXPECT_LT(rel_err(normal_quantile(1e-300), -37.04709629936119924), 1e-14);
  EXPECT_LT(rel_err(normal_cdf(-10.0), 7.619853024160526066e-24), 1e-13);
  EXPECT_LT(rel_err(normal_sf(10.0), 7.619853024160526066e-24), 1e-13);
  EXPECT_LT(rel_err(normal_log_cdf(-30.0), -454.3212439563431971), 1e-14);
  EXPECT_LT(rel_err(normal_log_cdf(-40.0), -804.6084420137537882), 1e-14);
  EXPECT_LT(rel_err(normal_log_cdf(-1000.0), -500007.8266948121843), 1e-14);
  EXPECT_EQ(normal_quantile(0.5), 0.0);
  EXPECT_EQ(normal_quantile(0.0), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(normal_quantile(1.0), std::numeric_limits<double>::infinity());
}

TEST(StandardNormal, QuantileInvertsCdfFromTheFarTailToTheCentre) {
  // Relative round trip in p over p = 1e-300 .. 0.5: any wrong AS 241 coefficient shows here.
  for (double lg = -300.0; lg <= std::log10(0.5); lg += 0.25) {
    const double p = std::pow(10.0, lg);
    const double x = normal_quantile(p);
    EXPECT_LT(rel_err(normal_cdf(x), p), 1e-12) << "p = " << p;
  }
  for (double p : {0.6, 0.9, 0.99, 0.999999}) EXPECT_LT(rel_err(normal_quantile(p), -normal_quantile(1.0 - p)), 1e-12);
}

TEST(StandardNormal, CentredQuantileKeepsPrecisionNearOneHalf) {
  // Phi(x) - 1/2 = h ~ x / sqrt(2 pi) for tiny h; 0.5 + h would round to 0.5.
  for (double h : {1e-20, -3e-12, 1e-9}) {
    EXPECT_LT(rel_err(normal_quantile_centred(h), h * std::sqrt(2.0 * 3.14159265358979323846)), 1e-9);
  }
  for (double h : {-0.49, -0.3, 0.1, 0.42, 0.43, 0.499}) {
    const double x = normal_quantile_centred(h);
    EXPECT_NEAR(0.5 * std::erf(x / std::sqrt(2.0)), h, 1e-15 + 1e-13 * std::fabs(h));
  }
}

TEST(StandardNormal, LogCdfIsContinuousAtTheAsymptoticSwitch) {
  const double left = normal_log_cdf(std::nextafter(-30.0, -31.0));
  const double right = normal_log_cdf(-30.0);
  EXPECT_LT(rel_err(left, right), 1e-13);
  EXPECT_NEAR(normal_log_cdf(5.0), std::log1p(-normal_sf(5.0)), 1e-20);
}

struct Interval {
  double a, b;
};

class TruncatedStandardNormalTest : public ::testing::TestWithParam<Interval> {};

TEST_P(TruncatedStandardNormalTest, CdfMeanAndQuantileMatchQuadratureOfTheDensity) {
  const auto [a, b] = GetParam();
  const TruncatedStandardNormal z(a, b);
  // Density scaled by exp(c^2 / 2), c the end nearest 0, so that far tails do not underflow.
  const double c = a > 0 ? a : (b < 0 ? b : 0.0);
  auto g = [c](double x) { return std::exp(-0.5 * (x - c) * (x + c)); };
  const double total = test::simpson(g, a, b);
  for (double t : {0.1, 0.25, 0.5, 0.75, 0.9}) {
    const double x = a + t * (b - a);
    const double want = test::simpson(g, a, x) / total;
    EXPECT_NEAR(z.cdf(x), want, 1e-9) << "x = " << x;
  }
  for (double u : {1e-6, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1.0 - 1e-6}) {
    const double x = z.quantile(u);
    ASSERT_GE(x, a);
    ASSERT_LE(x, b);
    EXPECT_NEAR(z.cdf(x), u, 1e-12) << "u = " << u;
    EXPECT_NEAR(test::simpson(g, a, x) / total, u, 1e-9) << "u = " << u;
  }
  const double mean = test::simpson([&](double x) { return x * g(x); }, a, b) / total;
  EXPECT_NEAR(z.mean(), mean, 1e-9 * (std::fabs(a) + std::fabs(b)));
  const double scale = std::max({std::fabs(a), std::fabs(b), b - a});
  EXPECT_NEAR(z.quantile(0.0), a, 1e-13 * scale);
  EXPECT_NEAR(z.quantile(1.0), b, 1e-13 * scale);
  EXPECT_EQ(z.cdf(a), 0.0);
  EXPECT_EQ(z.cdf(b), 1.0);
  // log_mass agrees with mass where both are representable.
  EXPECT_NEAR(z.log_mass(), std::log(z.mass()), 1e-12 * std::fabs(std::log(z.mass())));
}

INSTANTIATE_TEST_SUITE_P(Intervals, TruncatedStandardNormalTest,
                         ::testing::Values(Interval{-1.0, 1.0}, Interval{-0.5, 2.0}, Interval{0.3, 0.9},
                                           Interval{-2.0, -0.1}, Interval{6.0, 6.5}, Interval{-9.0, -8.0},
                                           Interval{30.0, 31.0}, Interval{-37.0, -36.5},
                                           Interval{-1e-3, 2e-3}, Interval{1e-4, 2e-4}, Interval{-40.0, 3.0}));

TEST(TruncatedStandardNormal, LogMassWhereTheMassUnderflows) {
  // P(-50.2 <= Z <= -50) ~ 1e-546: mass() is 0, log_mass() is not. Reference: the asymptotic
  // density integrated in logs, log phi(-50) + log(integral of exp(-(x^2 - 50^2)/2)).
  const TruncatedStandardNormal z(-50.2, -50.0);
  EXPECT_EQ(z.mass(), 0.0);
  const double log_phi = -0.5 * 2500.0 - 0.5 * std::log(2.0 * 3.14159265358979323846);
  const double integral = test::simpson([](double x) { return std::exp(-0.5 * (x - 50.0) * (x + 50.0)); }, -50.2, -50.0);
  EXPECT_LT(rel_err(z.log_mass(), log_phi + std::log(integral)), 1e-12);
}

}  // namespace
}  // namespace fp
