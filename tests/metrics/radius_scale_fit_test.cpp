// The scale fitted from a packing's radii (core/metrics/radius_scale_fit.hpp): a sample of a law
// scaled by s gives s back (exactly, to rounding, for a discrete law; within sampling and inside
// the scales that keep every radius in range for a continuous one), and the radii then pass the
// size test against the law at that scale. A scale cannot hide a wrong shape: radii whose spread
// is wider than the law's stay out of range at every scale.
#include "core/metrics/radius_scale_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "core/metrics/radii_fit.hpp"
#include "core/sampling/constant_radius.hpp"
#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/rng.hpp"
#include "core/sampling/scaled_radius.hpp"
#include "core/sampling/uniform_radius.hpp"

namespace fp {
namespace {

std::vector<double> draws(const RadiusDistribution& law, int n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> r;
  for (int k = 0; k < n; ++k) r.push_back(law.sample(rng));
  return r;
}

TEST(RadiusScaleFit, AContinuousLawScaledGivesItsScaleBack) {
  const auto law = std::make_shared<const UniformRadius>(1.0, 3.0);
  for (const double s : {1.7, 0x1p-40, 0x1p40}) {
    const std::vector<double> r = draws(ScaledRadius(law, s), 5000, 4);
    const double fit = fit_radius_scale(r, *law);
    EXPECT_NEAR(fit / s, 1.0, 0.01) << s;
    const ScaledRadius at(law, fit);
    for (const double x : r) ASSERT_LE(radius_excess(at, x), kRadiusSlack) << s << ": " << x;
    EXPECT_TRUE(radii_fit(r, at).passes(1e-3)) << s;
  }
}

TEST(RadiusScaleFit, ADiscreteLawScaledGivesItsScaleBackExactly) {
  for (const auto& weights : {std::vector<std::pair<double, double>>{{1.0, 3.0}, {4.0, 1.0}},
                              std::vector<std::pair<double, double>>{{1.0, 1.0}, {4.0, 3.0}},
                              std::vector<std::pair<double, double>>{{1.0, 1.0}, {2.0, 1.0}, {4.0, 1.0}}}) {
    const auto law = std::make_shared<const DiscreteRadius>(weights);
    const double s = 0.37;
    const std::vector<double> r = draws(ScaledRadius(law, s), 2000, 5);
    const double fit = fit_radius_scale(r, *law);
    EXPECT_NEAR(fit / s, 1.0, 1e-14);
    const RadiiFit f = radii_fit(r, ScaledRadius(law, fit));
    EXPECT_EQ(f.off_support, 0u);
    EXPECT_TRUE(f.passes(1e-3)) << f.describe();
  }
}

TEST(RadiusScaleFit, AConstantLawAndAnEmptySample) {
  const auto law = std::make_shared<const ConstantRadius>(2.0);
  EXPECT_EQ(fit_radius_scale(std::vector<double>(10, 3.0), *law), 1.5);
  EXPECT_EQ(fit_radius_scale(std::vector<double>{}, *law), 1.0);
}

TEST(RadiusScaleFit, NoScaleHidesASpreadWiderThanTheLaw) {
  const auto law = std::make_shared<const UniformRadius>(1.0, 3.0);
  const std::vector<double> r = draws(UniformRadius(1.0, 5.0), 2000, 6);  // r_max / r_min 5, the law's 3
  const ScaledRadius at(law, fit_radius_scale(r, *law));
  const auto out = std::count_if(r.begin(), r.end(), [&](double x) { return radius_excess(at, x) > kRadiusSlack; });
  EXPECT_GT(out, 0);
}

}  // namespace
}  // namespace fp
