// The radii test chosen by the kind of law: constant (exact match), discrete (chi-square on the
// counts), continuous (K-S, unchanged). Samples of every kind pass against their own law and fail
// against a neighbouring one; radius_excess measures the distance to what the law can produce.
#include "core/metrics/radii_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/sampling/constant_radius.hpp"
#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/gradation_radius.hpp"
#include "core/sampling/histogram_radius.hpp"
#include "core/sampling/ks_test.hpp"
#include "core/sampling/lognormal_radius.hpp"
#include "core/sampling/rng.hpp"
#include "core/sampling/truncated_normal_radius.hpp"
#include "core/sampling/uniform_radius.hpp"

namespace fp {
namespace {

std::vector<double> draw(const RadiusDistribution& d, int n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> r(static_cast<std::size_t>(n));
  for (double& x : r) x = d.sample(rng);
  return r;
}

TEST(RadiiFit, EveryKindPassesAgainstItsOwnLawWithItsOwnTest) {
  using Basis = GradationRadius::Basis;
  const std::vector<std::pair<std::shared_ptr<const RadiusDistribution>, std::string>> laws = {
      {std::make_shared<ConstantRadius>(0.015), "constant"},
      {std::make_shared<DiscreteRadius>(std::vector<std::pair<double, double>>{{0.01, 1}, {0.015, 1}}), "chi-square"},
      {std::make_shared<UniformRadius>(0.01, 0.02), "K-S"},
      {std::make_shared<TruncatedNormalRadius>(0.015, 0.003, 0.01, 0.02), "K-S"},
      {std::make_shared<LognormalRadius>(LognormalRadius::from_median(0.01, 0.5, 0.002, 0.05)), "K-S"},
      {std::make_shared<HistogramRadius>(std::vector<double>{0.01, 0.012, 0.02}, std::vector<double>{1, 3}), "K-S"},
      {std::make_shared<GradationRadius>(std::vector<std::pair<double, double>>{{0.02, 0}, {0.03, 40}, {0.04, 100}},
                                         Basis::Mass, 3),
       "K-S"},
  };
  for (const auto& [law, test] : laws) {
    const RadiiFit f = radii_fit(draw(*law, 3000, 11), *law);
    EXPECT_EQ(f.test, test) << law->describe();
    EXPECT_EQ(f.n, 3000u);
    EXPECT_GT(f.p, 1e-3) << law->describe() << ": " << f.describe();
    EXPECT_TRUE(f.passes(1e-3));
    EXPECT_EQ(f.off_support, 0u);
  }
}

TEST(RadiiFit, ContinuousLawsKeepTheirKsTest) {
  const UniformRadius law(0.01, 0.02);
  const auto r = draw(law, 1000, 3);
  const RadiiFit f = radii_fit(r, law);
  const double d = ks_statistic(r, [&](double x) { return law.cdf(x); });
  EXPECT_EQ(f.statistic, d);
  EXPECT_EQ(f.p, ks_pvalue(d, r.size()));
  // Against a slightly wider law the same sample fails.
  const UniformRadius wider(0.01, 0.022);
  EXPECT_FALSE(radii_fit(r, wider).passes(1e-3));
}

TEST(RadiiFit, DiscreteCountsAndStrayRadii) {
  const DiscreteRadius law({{0.01, 1}, {0.015, 1}});
  // The counts: 332 small, 350 large (K-S with ties said D = 0.513, p = 6e-158).
  std::vector<double> r(332, 0.01);
  r.insert(r.end(), 350, 0.015);
  const RadiiFit even = radii_fit(r, law);
  EXPECT_EQ(even.test, "chi-square");
  EXPECT_NEAR(even.statistic, 162.0 / 341.0, 1e-13);
  EXPECT_EQ(even.dof, 1);
  EXPECT_GT(even.p, 0.4);
  // A 2:1 mix drawn from another law fails.
  const DiscreteRadius other({{0.01, 2}, {0.015, 1}});
  EXPECT_LT(radii_fit(draw(other, 600, 5), law).p, 1e-6);
  // A radius between the values has probability 0.
  r.push_back(0.0125);
  const RadiiFit stray = radii_fit(r, law);
  EXPECT_EQ(stray.off_support, 1u);
  EXPECT_EQ(stray.p, 0.0);
  EXPECT_TRUE(std::isinf(stray.statistic));
  EXPECT_FALSE(stray.passes(1e-3));
}

TEST(RadiiFit, ConstantIsAnExactMatch) {
  const ConstantRadius law(0.02);
  std::vector<double> r(50, 0.02);
  r[7] = 0.02 * (1 + 5e-13);  // within the slack
  const RadiiFit ok = radii_fit(r, law);
  EXPECT_EQ(ok.test, "constant");
  EXPECT_EQ(ok.p, 1.0);
  EXPECT_NEAR(ok.statistic, 5e-13, 1e-15);  // r rounds to 2e-18
  r[8] = 0.0201;
  const RadiiFit bad = radii_fit(r, law);
  EXPECT_EQ(bad.p, 0.0);
  EXPECT_EQ(bad.off_support, 1u);
  EXPECT_NEAR(bad.statistic, 0.005, 1e-12);
  EXPECT_FALSE(radii_fit({}, law).computed());
  EXPECT_TRUE(radii_fit({}, law).passes(0.5));  // nothing to test: not evidence against the law
}

TEST(RadiusExcess, DistanceToWhatTheLawCanProduce) {
  const UniformRadius u(1.0, 2.0);
  EXPECT_EQ(radius_excess(u, 1.5), 0.0);
  EXPECT_NEAR(radius_excess(u, 2.2), 0.1, 1e-15);
  EXPECT_NEAR(radius_excess(u, 0.9), 0.1, 1e-15);
  const DiscreteRadius d({{1.0, 1}, {2.0, 1}});
  EXPECT_EQ(radius_excess(d, 2.0), 0.0);
  EXPECT_NEAR(radius_excess(d, 1.2), 0.2, 1e-15);   // nearest value 1
  EXPECT_NEAR(radius_excess(d, 1.8), 0.1, 1e-15);   // nearest value 2
  EXPECT_NEAR(radius_excess(ConstantRadius(4.0), 3.0), 0.25, 1e-15);
}

}  // namespace
}  // namespace fp
