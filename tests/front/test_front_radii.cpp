// The packed radii follow the requested distribution: a one-sample Kolmogorov–Smirnov test of
// every packing's radii against the distribution's CDF, for each distribution family, with the
// default packer options and with a radius pool (radii that wait must not bias the sample).
#include <gtest/gtest.h>

#include <string>

#include "core/sampling/ks_test.hpp"
#include "front_checks.hpp"

namespace fptest {
namespace {

struct DistributionCase {
  std::string name;
  std::string radius_yaml;  ///< the particles.radius mapping
  double box_side;          ///< sized for ~2,000-4,000 particles
};

std::ostream& operator<<(std::ostream& os, const DistributionCase& c) { return os << c.name; }

const DistributionCase kCases[] = {
    {"uniform", "{distribution: uniform, min: 0.01, max: 0.02}", 0.42},
    {"normal", "{distribution: normal, mean: 0.015, std: 0.003, min: 0.008, max: 0.024}", 0.4},
    {"lognormal", "{distribution: lognormal, median: 0.014, sigma: 0.35, min: 0.006, max: 0.03}", 0.4},
    {"histogram", "{distribution: histogram, edges: [0.01, 0.015, 0.02, 0.03], weights: [5, 3, 1]}", 0.42},
    {"gradation", "{distribution: gradation, curve: [[0.02, 0], [0.03, 40], [0.06, 100]]}", 0.5},
    {"gradation_count", "{distribution: gradation, curve: [[0.02, 0], [0.03, 40], [0.06, 100]], basis: count}",
     0.55},
};

class FrontRadii : public ::testing::TestWithParam<std::tuple<DistributionCase, int, int>> {};

TEST_P(FrontRadii, PackedRadiiFollowTheDistribution) {
  const auto& [c, dimension, pool] = GetParam();
  const double L = dimension == 3 ? c.box_side : 4 * c.box_side;
  std::string yaml = "dimension: " + std::to_string(dimension) + "\nseed: 21\ncontainer: {type: " +
                     (dimension == 3 ? "box, min: [0, 0, 0], max: [" + std::to_string(L) + ", " + std::to_string(L) +
                                           ", " + std::to_string(L) + "]}"
                                     : "rectangle, min: [0, 0], max: [" + std::to_string(L) + ", " + std::to_string(L) +
                                           "]}") +
                     "\nparticles: {radius: " + c.radius_yaml + "}\nstop: {particles: 5000}\n";
  if (pool > 0) yaml += "packer: {radius_pool: " + std::to_string(pool) + "}\n";
  const fp::Scene scene = scene_from_yaml(yaml);
  const auto check = [&](const auto& P) {
    SCOPED_TRACE(c.name + " " + std::to_string(dimension) + "D pool " + std::to_string(pool) + ": " +
                 std::to_string(P.size()) + " particles");
    EXPECT_GE(P.size(), 1500u);
    for (double r : P.radii) {
      ASSERT_GE(r, scene.radii->r_min());
      ASSERT_LE(r, scene.radii->r_max());
    }
    const double d = fp::ks_statistic(P.radii, [&](double r) { return scene.radii->cdf(r); });
    const double p = fp::ks_pvalue(d, P.size());
    EXPECT_GT(p, 1e-3) << "D_n = " << d;
    // Radii are not silently shrunk or swapped for others: the sample mean matches too
    // (5 standard errors; the spread is at most (r_max - r_min) / 2).
    double mean = 0;
    for (double r : P.radii) mean += r;
    mean /= static_cast<double>(P.size());
    EXPECT_NEAR(mean, scene.radii->mean(),
                5 * 0.5 * (scene.radii->r_max() - scene.radii->r_min()) / std::sqrt(static_cast<double>(P.size())));
  };
  if (dimension == 3) check(fp::pack<3>(scene).packing);
  else check(fp::pack<2>(scene).packing);
}

INSTANTIATE_TEST_SUITE_P(AllDistributions, FrontRadii,
                         ::testing::Combine(::testing::ValuesIn(kCases), ::testing::Values(3, 2),
                                            ::testing::Values(0, 1, 16)),  // 0: the default pool; 1: the paper
                         [](const auto& info) {
                           return std::get<0>(info.param).name + "_" + std::to_string(std::get<1>(info.param)) +
                                  "D_pool" + (std::get<2>(info.param) ? std::to_string(std::get<2>(info.param)) : "Default");
                         });

}  // namespace
}  // namespace fptest
