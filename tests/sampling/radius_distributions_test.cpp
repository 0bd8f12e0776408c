// Properties every radius distribution must have, checked on each kind at ordinary and extreme
// scales (radii ~1e-6 and ~1e6, r_max / r_min up to 1000): samples in [r_min, r_max], a
// K-S p-value against its own cdf() above 1e-3, the sample mean within 5 standard errors of
// mean(), a monotone cdf from 0 to 1, and the same radii for the same seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "core/sampling/constant_radius.hpp"
#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/gradation_radius.hpp"
#include "core/sampling/histogram_radius.hpp"
#include "core/sampling/ks_test.hpp"
#include "core/sampling/lognormal_radius.hpp"
#include "core/sampling/truncated_normal_radius.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "sampling_test_util.hpp"

namespace fp {
namespace {

using Basis = GradationRadius::Basis;

struct Case {
  std::string name;
  std::function<RadiusDistributionPtr()> make;
  bool continuous = true;
};

std::ostream& operator<<(std::ostream& os, const Case& c) { return os << c.name; }

template <class T, class... A>
std::function<RadiusDistributionPtr()> make(A... args) {
  return [=] { return std::make_shared<const T>(args...); };
}

std::vector<Case> cases() {
  const std::vector<std::pair<double, double>> sand = {{0.075, 0}, {0.15, 5}, {0.3, 20}, {0.6, 45},
                                                       {1.18, 70}, {2.36, 90}, {4.75, 100}};
  const std::vector<std::pair<double, double>> fine = {{1e-6, 0}, {1e-5, 10}, {1e-4, 60}, {1e-3, 100}};
  return {
      {"uniform_paper", make<UniformRadius>(0.01, 0.02)},
      {"uniform_ratio_1000_micro", make<UniformRadius>(1e-6, 1e-3)},
      {"uniform_mega", make<UniformRadius>(1e6, 2e6)},
      {"truncnormal_centred", make<TruncatedNormalRadius>(0.015, 0.003, 0.01, 0.02)},
      {"truncnormal_skewed", make<TruncatedNormalRadius>(0.011, 0.004, 0.01, 0.02)},
      {"truncnormal_right_tail", make<TruncatedNormalRadius>(0.0, 1.0, 6.0, 6.5)},
      {"truncnormal_left_tail", make<TruncatedNormalRadius>(10.0, 1.0, 1.0, 2.0)},
      {"truncnormal_far_tail", make<TruncatedNormalRadius>(0.0, 1.0, 30.0, 31.0)},
      {"truncnormal_nearly_uniform_mega", make<TruncatedNormalRadius>(1e6, 1e9, 1e6, 1.001e6)},
      {"truncnormal_micro", make<TruncatedNormalRadius>(2e-6, 5e-7, 1e-6, 3e-6)},
      {"lognormal", [] { return std::make_shared<const LognormalRadius>(LognormalRadius::from_median(0.01, 0.5, 0.002, 0.05)); }},
      {"lognormal_ratio_1000", [] { return std::make_shared<const LognormalRadius>(LognormalRadius::from_median(1.0, 1.0, 0.03, 30.0)); }},
      {"lognormal_micro", make<LognormalRadius>(std::log(5e-6), 0.3, 1e-6, 2e-5)},
      {"lognormal_mega_tail", make<LognormalRadius>(std::log(1e6), 0.1, 2e6, 3e6)},
      {"histogram", make<HistogramRadius>(std::vector<double>{0.01, 0.012, 0.015, 0.02}, std::vector<double>{1, 3, 2})},
      {"histogram_empty_bins", make<HistogramRadius>(std::vector<double>{1, 2, 3, 4, 5, 6}, std::vector<double>{0, 1, 0, 2, 0})},
      {"histogram_ratio_1000", make<HistogramRadius>(std::vector<double>{1e3, 1e4, 1e5, 1e6}, std::vector<double>{5, 1, 0.1})},
      {"gradation_sand_mass_3d", make<GradationRadius>(sand, Basis::Mass, 3)},
      {"gradation_sand_mass_2d", make<GradationRadius>(sand, Basis::Mass, 2)},
      {"gradation_sand_count", make<GradationRadius>(sand, Basis::Count, 3)},
      {"gradation_ratio_1000_mass_3d", make<GradationRadius>(fine, Basis::Mass, 3)},
      {"gradation_ratio_1000_count", make<GradationRadius>(fine, Basis::Count, 2)},
      {"constant", make<ConstantRadius>(0.015), false},
      {"constant_micro", make<ConstantRadius>(1e-6), false},
      {"discrete_bidisperse", make<DiscreteRadius>(std::vector<std::pair<double, double>>{{0.01, 1}, {0.02, 1}}), false},
      {"discrete_mega", make<DiscreteRadius>(std::vector<std::pair<double, double>>{{3e6, 0.2}, {1e6, 0.5}, {2e6, 0.3}}), false},
  };
}

class EveryDistribution : public ::testing::TestWithParam<Case> {};

TEST_P(EveryDistribution, SamplesAreInRangeMatchTheCdfAndTheMean) {
  const auto dist = GetParam().make();
  const std::size_t n = 20000;
  const auto radii = test::draw(*dist, n, 42);
  ASSERT_GT(dist->r_min(), 0.0);
  ASSERT_LE(dist->r_min(), dist->r_max());
  for (double r : radii) {
    ASSERT_GE(r, dist->r_min());
    ASSERT_LE(r, dist->r_max());
  }
  const auto [mean, sd] = test::moments(radii);
  EXPECT_GE(dist->mean(), dist->r_min());
  EXPECT_LE(dist->mean(), dist->r_max());
  EXPECT_LE(std::fabs(mean - dist->mean()), 5.0 * sd / std::sqrt(static_cast<double>(n)) + 1e-12 * dist->mean())
      << "sample mean " << mean << " vs mean() " << dist->mean();
  if (GetParam().continuous) {
    const double d = ks_statistic(radii, [&](double r) { return dist->cdf(r); });
    EXPECT_GT(ks_pvalue(d, n), 1e-3) << "D_n = " << d;
  }
}

TEST_P(EveryDistribution, CdfIsMonotoneFromZeroToOne) {
  const auto dist = GetParam().make();
  const double lo = dist->r_min(), hi = dist->r_max();
  EXPECT_EQ(dist->cdf(0.5 * lo), 0.0);
  EXPECT_EQ(dist->cdf(hi), 1.0);
  EXPECT_EQ(dist->cdf(2.0 * hi), 1.0);
  if (GetParam().continuous) {
    EXPECT_EQ(dist->cdf(lo), 0.0);
  }
  double previous = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    const double f = dist->cdf(lo + (hi - lo) * i / 1000.0);
    ASSERT_GE(f, previous);
    ASSERT_LE(f, 1.0);
    previous = f;
  }
}

TEST_P(EveryDistribution, SameSeedSameRadii) {
  const auto dist = GetParam().make();
  const auto a = test::draw(*dist, 1000, 7), b = test::draw(*dist, 1000, 7), c = test::draw(*dist, 1000, 8);
  EXPECT_EQ(a, b);
  if (dist->r_min() < dist->r_max()) {
    EXPECT_NE(a, c);
  }
  EXPECT_FALSE(dist->describe().empty());
}

INSTANTIATE_TEST_SUITE_P(Kinds, EveryDistribution, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

TEST(ConstantRadius, IsConstantAndLeavesTheStreamUntouched) {
  const ConstantRadius c(0.015);
  Rng rng(3), reference(3);
  EXPECT_EQ(c.sample(rng), 0.015);
  EXPECT_EQ(rng.next_u64(), reference.next_u64());
  EXPECT_EQ(c.cdf(std::nextafter(0.015, 0.0)), 0.0);
  EXPECT_EQ(c.cdf(0.015), 1.0);
  EXPECT_EQ(c.describe(), "constant 0.015");
}

TEST(UniformRadius, CdfAndMomentsInClosedForm) {
  const UniformRadius u(0.01, 0.02);
  EXPECT_DOUBLE_EQ(u.cdf(0.0125), 0.25);
  EXPECT_DOUBLE_EQ(u.mean(), 0.015);
  EXPECT_EQ(u.describe(), "uniform [0.01, 0.02]");
  // Sample variance of U[a,b] is (b-a)^2/12.
  const auto [mean, sd] = test::moments(test::draw(u, 50000, 1));
  EXPECT_NEAR(sd, 0.01 / std::sqrt(12.0), 0.01 * 0.01 / std::sqrt(12.0));
}

}  // namespace
}  // namespace fp
