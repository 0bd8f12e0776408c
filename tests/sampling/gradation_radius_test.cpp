// GradationRadius: the sieve curve is reproduced by the samples in its own basis (mass with d^3
// in 3D, d^2 in 2D, or count), the count CDF matches closed forms and quadrature.
#include "core/sampling/gradation_radius.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sampling_test_util.hpp"

namespace fp {
namespace {

using Basis = GradationRadius::Basis;
using Curve = std::vector<std::pair<double, double>>;

const Curve kModerate = {{1.0, 0}, {1.5, 20}, {2.0, 50}, {3.0, 80}, {4.0, 100}};

/// Fraction of sum(d^k) carried by particles with diameter <= sieve (k = 0: by count).
double passing_of_samples(const std::vector<double>& radii, double sieve, double k) {
  double below = 0.0, total = 0.0;
  for (double r : radii) {
    const double w = std::pow(2.0 * r, k);
    total += w;
    if (2.0 * r <= sieve) below += w;
  }
  return below / total;
}

/// Sieves and the geometric midpoints between them (tests the log-linear interpolation).
std::vector<double> check_sizes(const Curve& c) {
  std::vector<double> sizes;
  for (std::size_t j = 0; j + 1 < c.size(); ++j) {
    sizes.push_back(c[j].first);
    sizes.push_back(std::sqrt(c[j].first * c[j + 1].first));
  }
  return sizes;
}

TEST(GradationRadius, SingleBinClosedForms) {
  // One bin [1, 2] in d. Count density in d: ~ 1/d (count), d^-3 (mass 2D), d^-4 (mass 3D).
  const Curve one = {{1.0, 0}, {2.0, 100}};
  const GradationRadius count(one, Basis::Count, 3), mass2(one, Basis::Mass, 2), mass3(one, Basis::Mass, 3);
  const double d = 1.5;
  EXPECT_NEAR(count.cdf(d / 2), std::log(d) / std::log(2.0), 1e-15);
  EXPECT_NEAR(mass2.cdf(d / 2), (1 - std::pow(d, -2)) / 0.75, 1e-15);
  EXPECT_NEAR(mass3.cdf(d / 2), (1 - std::pow(d, -3)) / 0.875, 1e-15);
  EXPECT_NEAR(count.mean(), 0.5 / std::log(2.0), 1e-15);
  EXPECT_NEAR(mass2.mean(), 0.5 * (2 * 0.5) / 0.75, 1e-15);
  EXPECT_NEAR(mass3.mean(), 0.5 * (1.5 * 0.75) / 0.875, 1e-15);
  EXPECT_EQ(mass3.r_min(), 0.5);
  EXPECT_EQ(mass3.r_max(), 1.0);
}

TEST(GradationRadius, CountBasisCdfPassesThroughTheSieves) {
  const GradationRadius dist(kModerate, Basis::Count, 3);
  for (const auto& [d, p] : kModerate) EXPECT_NEAR(dist.cdf(d / 2), p / 100, 1e-14) << "sieve " << d;
  for (double d : check_sizes(kModerate)) EXPECT_NEAR(dist.cdf(d / 2), dist.passing_fraction(d), 1e-14);
  const std::size_t n = 50000;
  const auto radii = test::draw(dist, n, 3);
  for (double d : check_sizes(kModerate)) {
    const double p = dist.passing_fraction(d), sd = std::sqrt(p * (1 - p) / n);
    EXPECT_NEAR(passing_of_samples(radii, d, 0.0), p, 5 * sd + 1e-12) << "d = " << d;
  }
}

class MassBasis : public ::testing::TestWithParam<int> {};

TEST_P(MassBasis, MassWeightedPassingOfSamplesReproducesTheCurve) {
  const int dim = GetParam();
  const GradationRadius dist(kModerate, Basis::Mass, dim);
  const auto radii = test::draw(dist, 200000, 21);
  for (double d : check_sizes(kModerate))
    EXPECT_NEAR(passing_of_samples(radii, d, dim), dist.passing_fraction(d), 0.01) << "d = " << d;
  // Weighting with the other dimension's mass misses the curve: 2D and 3D are different models.
  double worst = 0.0;
  for (double d : check_sizes(kModerate))
    worst = std::max(worst, std::fabs(passing_of_samples(radii, d, 5 - dim) - dist.passing_fraction(d)));
  EXPECT_GT(worst, 0.03);
}

INSTANTIATE_TEST_SUITE_P(Dimensions, MassBasis, ::testing::Values(2, 3));

TEST(GradationRadius, TwoDimensionalMassGivesFewerSmallParticlesThanThreeDimensional) {
  const GradationRadius mass2(kModerate, Basis::Mass, 2), mass3(kModerate, Basis::Mass, 3),
      count(kModerate, Basis::Count, 3);
  for (double d : {1.2, 1.5, 2.0, 2.5, 3.5}) {
    // Dividing mass by d^k favours small particles more for larger k.
    EXPECT_GT(mass3.cdf(d / 2), mass2.cdf(d / 2) + 1e-3) << d;
    EXPECT_GT(mass2.cdf(d / 2), count.cdf(d / 2) + 1e-3) << d;
  }
  EXPECT_LT(mass3.mean(), mass2.mean());
  EXPECT_LT(mass2.mean(), count.mean());
}

TEST(GradationRadius, CountCdfAndMeanMatchQuadratureOfTheCountDensity) {
  // A sand grading by mass: count density in d is (w_i / L_i) d^(-k-1) in bin i.
  const Curve sand = {{0.075, 0}, {0.15, 5}, {0.3, 20}, {0.6, 45}, {1.18, 70}, {2.36, 90}, {4.75, 100}};
  for (int dim : {2, 3}) {
    const GradationRadius dist(sand, Basis::Mass, dim);
    std::vector<double> bin_count, bin_moment;
    double total = 0.0, moment = 0.0;
    for (std::size_t i = 0; i + 1 < sand.size(); ++i) {
      const double c = (sand[i + 1].second - sand[i].second) / std::log(sand[i + 1].first / sand[i].first);
      auto f = [&](double d) { return c * std::pow(d, -dim - 1.0); };
      bin_count.push_back(test::simpson(f, sand[i].first, sand[i + 1].first));
      total += bin_count.back();
      moment += test::simpson([&](double d) { return d * f(d); }, sand[i].first, sand[i + 1].first);
    }
    double cumulative = 0.0;
    for (std::size_t i = 0; i + 1 < sand.size(); ++i) {
      cumulative += bin_count[i];
      EXPECT_NEAR(dist.cdf(sand[i + 1].first / 2), cumulative / total, 1e-10) << "dim " << dim << " sieve " << i + 1;
    }
    EXPECT_NEAR(dist.mean(), 0.5 * moment / total, 1e-10 * dist.mean());
  }
}

TEST(GradationRadius, FlatSegmentsHoldNoParticles) {
  const Curve gap = {{0.5, 0}, {1.0, 0}, {2.0, 50}, {3.0, 50}, {4.0, 100}, {8.0, 100}};
  const GradationRadius dist(gap, Basis::Mass, 3);
  EXPECT_EQ(dist.r_min(), 0.5);
  EXPECT_EQ(dist.r_max(), 2.0);
  for (double r : test::draw(dist, 20000, 2)) ASSERT_FALSE(2 * r > 2.0 && 2 * r < 3.0) << r;
  EXPECT_EQ(dist.cdf(0.5), 0.0);
  EXPECT_EQ(dist.cdf(1.0), dist.cdf(1.4));  // flat over d in [2, 3]
  EXPECT_GT(dist.cdf(1.0), 0.5);             // by count, the fine half of the mass is most particles
  EXPECT_EQ(dist.passing_fraction(2.5), 0.5);
  EXPECT_EQ(dist.describe(), "gradation by mass (3D), 6 sieves, d in [0.5, 8]");
}

}  // namespace
}  // namespace fp
