// A law scaled by s (core/sampling/scaled_radius.hpp): the same stream of draws times s, its CDF,
// range, mean and values moved by s, its description naming s; a scale that is not a finite
// positive number is refused.
#include "core/sampling/scaled_radius.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/rng.hpp"
#include "core/sampling/uniform_radius.hpp"

namespace fp {
namespace {

TEST(ScaledRadius, IsTheLawTimesTheScale) {
  const auto law = std::make_shared<const UniformRadius>(1.0, 3.0);
  const ScaledRadius scaled(law, 2.5);
  EXPECT_EQ(scaled.r_min(), 2.5);
  EXPECT_EQ(scaled.r_max(), 7.5);
  EXPECT_DOUBLE_EQ(scaled.mean(), 5.0);
  EXPECT_DOUBLE_EQ(scaled.cdf(5.0), 0.5);
  EXPECT_EQ(scaled.cdf(2.4), 0.0);
  EXPECT_EQ(scaled.cdf(7.6), 1.0);
  EXPECT_EQ(scaled.describe(), law->describe() + ", scaled by 2.5");
  EXPECT_TRUE(scaled.atoms().empty());
  Rng a(9), b(9);
  for (int k = 0; k < 1000; ++k) ASSERT_EQ(scaled.sample(a), 2.5 * law->sample(b));
}

TEST(ScaledRadius, MovesTheValuesOfADiscreteLaw) {
  const auto law = std::make_shared<const DiscreteRadius>(std::vector<std::pair<double, double>>{{1.0, 3.0}, {4.0, 1.0}});
  const ScaledRadius scaled(law, 0.5);
  ASSERT_EQ(scaled.atoms().size(), 2u);
  EXPECT_EQ(scaled.atoms()[0].first, 0.5);
  EXPECT_EQ(scaled.atoms()[1].first, 2.0);
  EXPECT_DOUBLE_EQ(scaled.atoms()[0].second, 0.75);
  EXPECT_DOUBLE_EQ(scaled.cdf(0.5), 0.75);
}

TEST(ScaledRadius, RefusesAScaleThatIsNotAFinitePositiveNumber) {
  const auto law = std::make_shared<const UniformRadius>(1.0, 3.0);
  for (const double s : {0.0, -1.0, double(INFINITY), double(NAN)}) EXPECT_THROW(ScaledRadius(law, s), std::invalid_argument) << s;
}

}  // namespace
}  // namespace fp
