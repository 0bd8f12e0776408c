// E[R^k] of every size law against closed forms (and k = 1 against each law's own mean()).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "core/sampling/constant_radius.hpp"
#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/gradation_radius.hpp"
#include "core/sampling/histogram_radius.hpp"
#include "core/sampling/lognormal_radius.hpp"
#include "core/sampling/radius_moment.hpp"
#include "core/sampling/truncated_normal_radius.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "sampling_test_util.hpp"

namespace fp {
namespace {

double phi(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

TEST(RadiusMoment, UniformMatchesClosedForm) {
  for (const auto& [a, b] : std::vector<std::pair<double, double>>{{0.01, 0.02}, {1e-3, 1.0}, {1e-9, 1e-3}, {5.0, 5.0 + 1e-9}})
    for (int k = 1; k <= 3; ++k) {
      const UniformRadius d(a, b);
      const double exact = (std::pow(b, k + 1) - std::pow(a, k + 1)) / ((k + 1) * (b - a));
      EXPECT_NEAR(radius_moment(d, k), exact, 1e-7 * exact) << "U[" << a << ", " << b << "], k = " << k;
    }
}

TEST(RadiusMoment, DiscreteAndConstantAreExact) {
  EXPECT_DOUBLE_EQ(radius_moment(ConstantRadius(0.25), 3), 0.25 * 0.25 * 0.25);
  const DiscreteRadius d({{1.0, 3.0}, {2.0, 1.0}});  // weights by count: 3/4 at 1, 1/4 at 2
  EXPECT_DOUBLE_EQ(radius_moment(d, 3), 0.75 * 1 + 0.25 * 8);
  EXPECT_DOUBLE_EQ(radius_moment(d, 2), 0.75 * 1 + 0.25 * 4);
}

TEST(RadiusMoment, HistogramMatchesPiecewiseUniform) {
  const std::vector<double> edges = {0.001, 0.01, 0.1, 1.0};
  const std::vector<double> weights = {5, 3, 1};
  const HistogramRadius d(edges, weights);
  for (int k = 1; k <= 3; ++k) {
    double exact = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
      const double a = edges[i], b = edges[i + 1];
      exact += weights[i] / 9.0 * (std::pow(b, k + 1) - std::pow(a, k + 1)) / ((k + 1) * (b - a));
    }
    EXPECT_NEAR(radius_moment(d, k), exact, 1e-5 * exact) << "k = " << k;
  }
}

TEST(RadiusMoment, TruncatedLognormalMatchesClosedForm) {
  const double mu = std::log(0.01), s = 0.6, a = 0.002, b = 0.05;
  const LognormalRadius d(mu, s, a, b);
  const double z = phi((std::log(b) - mu) / s) - phi((std::log(a) - mu) / s);
  for (int k = 1; k <= 3; ++k) {
    const double exact = std::exp(k * mu + 0.5 * k * k * s * s) *
                         (phi((std::log(b) - mu - k * s * s) / s) - phi((std::log(a) - mu - k * s * s) / s)) / z;
    EXPECT_NEAR(radius_moment(d, k), exact, 1e-5 * exact) << "k = " << k;
  }
}

TEST(RadiusMoment, TruncatedNormalMatchesQuadratureOfItsDensity) {
  const double m = 1.0, s = 0.3, a = 0.5, b = 2.0;
  const TruncatedNormalRadius d(m, s, a, b);
  const double z = phi((b - m) / s) - phi((a - m) / s);
  for (int k = 1; k <= 3; ++k) {
    const double exact = test::simpson(
        [&](double r) { return std::pow(r, k) * std::exp(-0.5 * (r - m) * (r - m) / (s * s)) / (s * std::sqrt(2 * M_PI) * z); }, a, b);
    EXPECT_NEAR(radius_moment(d, k), exact, 1e-6 * exact) << "k = " << k;
  }
}

TEST(RadiusMoment, FirstMomentIsEachLawsMean) {
  const std::vector<std::shared_ptr<const RadiusDistribution>> laws = {
      std::make_shared<UniformRadius>(0.01, 0.02),
      std::make_shared<TruncatedNormalRadius>(0.015, 0.003, 0.01, 0.02),
      std::make_shared<LognormalRadius>(std::log(0.01), 1.0, 1e-4, 0.1),
      std::make_shared<HistogramRadius>(std::vector<double>{1, 2, 4}, std::vector<double>{1, 1}),
      std::make_shared<GradationRadius>(std::vector<std::pair<double, double>>{{0.1, 0}, {1, 40}, {10, 100}},
                                        GradationRadius::Basis::Mass, 3),
      std::make_shared<DiscreteRadius>(std::vector<std::pair<double, double>>{{1, 1}, {1000, 1}})};
  for (const auto& d : laws) EXPECT_NEAR(radius_moment(*d, 1), d->mean(), 1e-5 * d->mean()) << d->describe();
}

TEST(RadiusMoment, WideGradationByMassMatchesClosedForm) {
  // A ratio of 1000 by mass: the curve is log-linear in diameter between sieves, so the mass is
  // uniform in ln r on each segment, and by count E[R^3] = 1 / E_mass[R^-3] (count density =
  // mass density / r^3, normalised) = 1 / sum over segments of dp (r0^-3 - r1^-3) / (3 ln(r1 / r0)).
  const GradationRadius d({{0.002, 0}, {0.02, 30}, {0.2, 60}, {2, 100}}, GradationRadius::Basis::Mass, 3);
  const std::vector<std::pair<double, double>> segments = {{0.001, 0.01}, {0.01, 0.1}, {0.1, 1.0}};
  const std::vector<double> dp = {0.3, 0.3, 0.4};
  double inv = 0;
  for (std::size_t s = 0; s < dp.size(); ++s) {
    const auto [r0, r1] = segments[s];
    inv += dp[s] * (std::pow(r0, -3) - std::pow(r1, -3)) / (3 * std::log(r1 / r0));
  }
  EXPECT_NEAR(radius_moment(d, 3), 1 / inv, 1e-6 / inv);
}

TEST(RadiusMoment, RefusesKBelowOne) { EXPECT_THROW(radius_moment(UniformRadius(1, 2), 0), std::invalid_argument); }

}  // namespace
}  // namespace fp
