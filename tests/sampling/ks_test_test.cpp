// The one-sample Kolmogorov–Smirnov statistic and p-value.
#include "core/sampling/ks_test.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sampling/rng.hpp"
#include "core/sampling/truncated_normal_radius.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "sampling_test_util.hpp"

namespace fp {
namespace {

double uniform_cdf(double x) { return std::clamp(x, 0.0, 1.0); }

TEST(KsStatistic, HandComputedSmallSamples) {
  // {0.1, 0.4, 0.7} against U[0,1]: gaps after each step 1/3-0.1, 2/3-0.4, 1-0.7 -> D = 0.3.
  EXPECT_NEAR(ks_statistic({0.1, 0.4, 0.7}, uniform_cdf), 0.3, 1e-15);
  EXPECT_NEAR(ks_statistic({0.7, 0.1, 0.4}, uniform_cdf), 0.3, 1e-15);  // order does not matter
  // Below the first step: {0.9, 0.95} -> F(0.9) - 0 = 0.9.
  EXPECT_NEAR(ks_statistic({0.9, 0.95}, uniform_cdf), 0.9, 1e-15);
  EXPECT_NEAR(ks_statistic({0.25}, uniform_cdf), 0.75, 1e-15);
  // Ties: F_n jumps 0 -> 1 at 0.5, so D = 0.5 on both sides of the jump.
  EXPECT_NEAR(ks_statistic({0.5, 0.5}, uniform_cdf), 0.5, 1e-15);
  // A perfect stratified sample (i + 1/2) / n has D = 1 / (2n).
  std::vector<double> strata;
  for (int i = 0; i < 100; ++i) strata.push_back((i + 0.5) / 100.0);
  EXPECT_NEAR(ks_statistic(strata, uniform_cdf), 0.005, 1e-15);
  EXPECT_THROW(ks_statistic({}, uniform_cdf), std::invalid_argument);
}

TEST(KsPvalue, KolmogorovDistributionReferenceValues) {
  // scipy.stats.kstwobign.sf / mpmath series.
  EXPECT_NEAR(kolmogorov_survival(1.0), 0.26999967167735456, 1e-14);
  EXPECT_NEAR(kolmogorov_survival(0.5), 0.96394524366487509, 1e-14);
  EXPECT_NEAR(kolmogorov_survival(0.3), 0.99999069419866543, 1e-14);
  EXPECT_NEAR(kolmogorov_survival(2.0), 0.00067092525577970, 1e-15);
  EXPECT_NEAR(kolmogorov_survival(kKsCritical5Percent), 0.05002679733444698, 1e-13);
  // The two series meet at lambda = 1.
  EXPECT_NEAR(kolmogorov_survival(std::nextafter(1.0, 0.0)), kolmogorov_survival(1.0), 1e-14);
  EXPECT_EQ(kolmogorov_survival(0.0), 1.0);
}

TEST(KsPvalue, MonotoneInStatisticAndSampleSize) {
  double previous = 1.0;
  for (double d = 0.0; d <= 0.5; d += 0.005) {
    const double p = ks_pvalue(d, 100);
    EXPECT_LE(p, previous) << "d = " << d;
    EXPECT_GE(p, 0.0);
    previous = p;
  }
  EXPECT_GT(ks_pvalue(0.05, 100), ks_pvalue(0.05, 1000));
  // Small-sample correction: lambda = (sqrt(n) + 0.12 + 0.11/sqrt(n)) d.
  EXPECT_DOUBLE_EQ(ks_pvalue(0.1, 25), kolmogorov_survival((5.0 + 0.12 + 0.022) * 0.1));
  EXPECT_THROW(ks_pvalue(0.1, 0), std::invalid_argument);
}

TEST(KsPvalue, RejectionRateUnderTheNullIsNominal) {
  // 400 samples of n = 50 from U[0,1]: about 5 % of the p-values fall below 0.05.
  Rng rng(31);
  int rejected = 0;
  const int trials = 400;
  for (int t = 0; t < trials; ++t) {
    std::vector<double> x(50);
    for (auto& v : x) v = rng.uniform01();
    rejected += ks_pvalue(ks_statistic(x, uniform_cdf), x.size()) < 0.05;
  }
  // Binomial(400, 0.05): mean 20, sd 4.4.
  EXPECT_GT(rejected, 5);
  EXPECT_LT(rejected, 38);
}

TEST(KsPvalue, WrongDistributionIsRejected) {
  const UniformRadius sampled(0.01, 0.02);
  const auto radii = test::draw(sampled, 20000, 5);
  EXPECT_GT(ks_pvalue(ks_statistic(radii, [&](double r) { return sampled.cdf(r); }), radii.size()), 1e-3);
  const UniformRadius slightly_wider(0.01, 0.0205);
  EXPECT_LT(ks_pvalue(ks_statistic(radii, [&](double r) { return slightly_wider.cdf(r); }), radii.size()), 1e-6);
  const TruncatedNormalRadius bell(0.015, 0.003, 0.01, 0.02);
  EXPECT_LT(ks_pvalue(ks_statistic(radii, [&](double r) { return bell.cdf(r); }), radii.size()), 1e-12);
}

}  // namespace
}  // namespace fp
