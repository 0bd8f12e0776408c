// A law split at r_s (core/sampling/split_radius.hpp): each side's draws stay on it and follow the
// law conditioned on it (K-S), its CDF and mean are the conditioned law's, discrete atoms are
// renormalised, and both sides mixed in the proportions F(r_s) : 1 - F(r_s) are the whole law.
#include "core/sampling/split_radius.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/ks_test.hpp"
#include "core/sampling/rng.hpp"
#include "core/sampling/uniform_radius.hpp"

namespace fp {
namespace {

TEST(SplitRadius, EachSideIsTheLawConditionedOnIt) {
  const auto law = std::make_shared<const UniformRadius>(1.0, 7.0);
  const SplitRadius below(law, 2.5, SplitRadius::Side::Below), above(law, 2.5, SplitRadius::Side::Above);
  EXPECT_DOUBLE_EQ(below.share_below(), 0.25);
  EXPECT_EQ(below.r_min(), 1.0);
  EXPECT_EQ(below.r_max(), 2.5);
  EXPECT_EQ(above.r_min(), 2.5);
  EXPECT_EQ(above.r_max(), 7.0);
  EXPECT_NEAR(below.mean(), 1.75, 1e-9);
  EXPECT_NEAR(above.mean(), 4.75, 1e-9);
  EXPECT_DOUBLE_EQ(below.cdf(2.0), 1.0 / 1.5);
  EXPECT_DOUBLE_EQ(above.cdf(4.0), 1.5 / 4.5);
  Rng rng(3);
  std::vector<double> b, a, mixed;
  for (int k = 0; k < 20000; ++k) {
    b.push_back(below.sample(rng));
    a.push_back(above.sample(rng));
    ASSERT_LE(b.back(), 2.5);
    ASSERT_GT(a.back(), 2.5);
  }
  EXPECT_GT(ks_pvalue(ks_statistic(b, [&](double r) { return below.cdf(r); }), b.size()), 1e-3);
  EXPECT_GT(ks_pvalue(ks_statistic(a, [&](double r) { return above.cdf(r); }), a.size()), 1e-3);
  // A quarter below, three quarters above: the whole law.
  mixed.insert(mixed.end(), b.begin(), b.begin() + 5000);
  mixed.insert(mixed.end(), a.begin(), a.begin() + 15000);
  EXPECT_GT(ks_pvalue(ks_statistic(mixed, [&](double r) { return law->cdf(r); }), mixed.size()), 1e-3);
}

TEST(SplitRadius, DiscreteAtomsAreRenormalisedAndEmptySidesRefused) {
  const auto law = std::make_shared<const DiscreteRadius>(std::vector<std::pair<double, double>>{{1, 0.5}, {2, 0.3}, {3, 0.2}});
  const SplitRadius above(law, 1.5, SplitRadius::Side::Above);
  const auto atoms = above.atoms();
  ASSERT_EQ(atoms.size(), 2u);
  EXPECT_DOUBLE_EQ(atoms[0].second, 0.6);
  EXPECT_DOUBLE_EQ(atoms[1].second, 0.4);
  EXPECT_THROW(SplitRadius(law, 0.5, SplitRadius::Side::Below), std::invalid_argument);
  EXPECT_THROW(SplitRadius(law, 3.0, SplitRadius::Side::Above), std::invalid_argument);
}

}  // namespace
}  // namespace fp
