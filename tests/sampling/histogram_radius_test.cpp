// HistogramRadius: piecewise-linear CDF through the cumulative weights, counts per bin.
#include "core/sampling/histogram_radius.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sampling_test_util.hpp"

namespace fp {
namespace {

TEST(HistogramRadius, CdfInterpolatesTheCumulativeWeights) {
  const HistogramRadius dist({0.01, 0.012, 0.015, 0.02}, {1, 3, 2});
  EXPECT_EQ(dist.cdf(0.01), 0.0);
  EXPECT_NEAR(dist.cdf(0.012), 1.0 / 6, 1e-15);
  EXPECT_NEAR(dist.cdf(0.011), 0.5 / 6, 1e-15);
  EXPECT_NEAR(dist.cdf(0.015), 4.0 / 6, 1e-15);
  EXPECT_NEAR(dist.cdf(0.0175), 5.0 / 6, 1e-15);
  EXPECT_EQ(dist.cdf(0.02), 1.0);
  EXPECT_NEAR(dist.mean(), (1 * 0.011 + 3 * 0.0135 + 2 * 0.0175) / 6, 1e-16);
}

TEST(HistogramRadius, EmptyBinsAreNeverDrawnAndTrimTheRange) {
  const HistogramRadius dist({1, 2, 3, 4, 5, 6}, {0, 1, 0, 2, 0});
  EXPECT_EQ(dist.r_min(), 2.0);
  EXPECT_EQ(dist.r_max(), 5.0);
  const std::size_t n = 60000;
  double in_first = 0.0;
  for (double r : test::draw(dist, n, 4)) {
    ASSERT_FALSE(r > 3.0 && r < 4.0) << r;
    in_first += r <= 3.0;
  }
  const double p = 1.0 / 3, sd = std::sqrt(n * p * (1 - p));
  EXPECT_NEAR(in_first, n * p, 5 * sd);
  EXPECT_DOUBLE_EQ(dist.cdf(3.5), 1.0 / 3);
}

}  // namespace
}  // namespace fp
