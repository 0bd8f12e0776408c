// DiscreteRadius: step CDF, frequencies against the weights.
#include "core/sampling/discrete_radius.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "sampling_test_util.hpp"

namespace fp {
namespace {

TEST(DiscreteRadius, CdfIsAStepFunctionOfTheSortedWeights) {
  const DiscreteRadius dist({{0.03, 1.0}, {0.01, 2.0}, {0.02, 0.0}, {0.015, 1.0}});
  // Zero weight dropped; radii sorted: 0.01 (1/2), 0.015 (1/4), 0.03 (1/4).
  EXPECT_EQ(dist.radii(), (std::vector<double>{0.01, 0.015, 0.03}));
  EXPECT_EQ(dist.cdf(std::nextafter(0.01, 0.0)), 0.0);
  EXPECT_DOUBLE_EQ(dist.cdf(0.01), 0.5);
  EXPECT_DOUBLE_EQ(dist.cdf(0.0149), 0.5);
  EXPECT_DOUBLE_EQ(dist.cdf(0.015), 0.75);
  EXPECT_DOUBLE_EQ(dist.cdf(0.029), 0.75);
  EXPECT_EQ(dist.cdf(0.03), 1.0);
  EXPECT_DOUBLE_EQ(dist.mean(), 0.5 * 0.01 + 0.25 * 0.015 + 0.25 * 0.03);
  EXPECT_EQ(dist.r_min(), 0.01);
  EXPECT_EQ(dist.r_max(), 0.03);
}

TEST(DiscreteRadius, ZeroWeightExtremesDoNotWidenTheRange) {
  const DiscreteRadius dist({{0.001, 0.0}, {0.01, 1.0}, {0.02, 3.0}, {0.5, 0.0}});
  EXPECT_EQ(dist.r_min(), 0.01);
  EXPECT_EQ(dist.r_max(), 0.02);
}

TEST(DiscreteRadius, FrequenciesMatchTheWeightsWithinFiveBinomialSd) {
  const DiscreteRadius dist({{1e-6, 1.0}, {2e-6, 10.0}, {5e-6, 100.0}, {1e-3, 0.5}});
  const std::size_t n = 100000;
  std::map<double, double> counts;
  for (double r : test::draw(dist, n, 17)) counts[r] += 1.0;
  ASSERT_EQ(counts.size(), 4u);  // only the listed radii, all of them drawn
  for (std::size_t i = 0; i < dist.radii().size(); ++i) {
    const double p = dist.probabilities()[i];
    const double expected = p * n, sd = std::sqrt(n * p * (1 - p));
    EXPECT_NEAR(counts[dist.radii()[i]], expected, 5 * sd) << "radius " << dist.radii()[i];
  }
  // Pearson chi-square, 3 dof: 0.999 quantile 16.27.
  double chi2 = 0.0;
  for (std::size_t i = 0; i < dist.radii().size(); ++i) {
    const double e = dist.probabilities()[i] * n, o = counts[dist.radii()[i]];
    chi2 += (o - e) * (o - e) / e;
  }
  EXPECT_LT(chi2, 16.27);
}

}  // namespace
}  // namespace fp
