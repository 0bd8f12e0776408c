// Pearson's chi-square test: the survival function against closed forms, the pooling of small
// classes, the rejection rate under the null and the power against a skewed mix.
#include "core/sampling/chi_square_test.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/rng.hpp"

namespace fp {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Closed forms of Q(k/2, x/2) for k = 1..4.
double closed_form(double x, int k) {
  const double h = 0.5 * x;
  switch (k) {
    case 1: return std::erfc(std::sqrt(h));
    case 2: return std::exp(-h);
    case 3: return std::erfc(std::sqrt(h)) + std::sqrt(2.0 * x / kPi) * std::exp(-h);
    default: return std::exp(-h) * (1.0 + h);
  }
}

TEST(ChiSquareSurvival, MatchesClosedFormsToRelativeRounding) {
  for (int k = 1; k <= 4; ++k)
    for (double x = 0.01; x < 600.0; x *= 1.37) {
      const double want = closed_form(x, k);
      EXPECT_NEAR(chi_square_survival(x, k) / want, 1.0, 1e-12) << "k " << k << ", x " << x;
    }
  // Far tail, relative accuracy kept (p ~ 1e-304).
  EXPECT_NEAR(chi_square_survival(1400.0, 2) / std::exp(-700.0), 1.0, 1e-12);
}

TEST(ChiSquareSurvival, TabulatedQuantilesAndEdges) {
  EXPECT_NEAR(chi_square_survival(3.841458820694124, 1), 0.05, 1e-14);
  EXPECT_NEAR(chi_square_survival(6.634896601021214, 1), 0.01, 1e-14);
  EXPECT_NEAR(chi_square_survival(16.918977604620448, 9), 0.05, 1e-13);
  EXPECT_NEAR(chi_square_survival(124.34211340400407, 100), 0.05, 1e-12);
  EXPECT_EQ(chi_square_survival(0.0, 3), 1.0);
  EXPECT_EQ(chi_square_survival(-1.0, 3), 1.0);
  EXPECT_EQ(chi_square_survival(INFINITY, 3), 0.0);
  EXPECT_THROW(chi_square_survival(1.0, 0), std::invalid_argument);
  EXPECT_THROW(chi_square_survival(NAN, 1), std::invalid_argument);
}

TEST(ChiSquareCounts, HandComputedAndPooled) {
  // 332 / 350 against 1/2, 1/2: X2 = 2 * 9^2 / 341, 1 dof.
  const ChiSquareResult a = chi_square_counts({332, 350}, {0.5, 0.5});
  EXPECT_EQ(a.classes, 2u);
  EXPECT_EQ(a.dof, 1);
  EXPECT_NEAR(a.statistic, 162.0 / 341.0, 1e-14);
  EXPECT_NEAR(a.p, std::erfc(std::sqrt(81.0 / 341.0)), 1e-14);
  // n = 40 over {0.5, 0.45, 0.04, 0.01}: the last two expect 1.6 and 0.4, pooled with the second.
  const ChiSquareResult b = chi_square_counts({20, 16, 3, 1}, {0.5, 0.45, 0.04, 0.01});
  EXPECT_EQ(b.classes, 2u);
  EXPECT_EQ(b.dof, 1);
  EXPECT_NEAR(b.statistic, 0.0, 1e-14);  // 20 / 20 observed as expected
  EXPECT_EQ(b.p, 1.0);
  // Everything in one pooled class: nothing to test.
  const ChiSquareResult c = chi_square_counts({2, 1}, {0.5, 0.5});
  EXPECT_EQ(c.dof, 0);
  EXPECT_EQ(c.p, 1.0);
  EXPECT_THROW(chi_square_counts({1, 2}, {1.0}), std::invalid_argument);
  EXPECT_THROW(chi_square_counts({0, 0}, {0.5, 0.5}), std::invalid_argument);
  EXPECT_THROW(chi_square_counts({1, 2}, {1.0, 0.0}), std::invalid_argument);
}

TEST(ChiSquareCounts, RareClassesAreCountedExactly) {
  // Binomial tails by hand: P(X = 0) = 0.996^1000, P(X <= 1) adds 1000 * 0.004 * 0.996^999.
  const double p0 = std::pow(0.996, 1000.0), p1 = 1000 * 0.004 * std::pow(0.996, 999.0);
  EXPECT_NEAR(binomial_two_sided_p(0, 1000, 0.004), 2 * p0, 1e-14);
  EXPECT_NEAR(binomial_two_sided_p(1, 1000, 0.004), 2 * (p0 + p1), 1e-13);
  EXPECT_NEAR(binomial_two_sided_p(3, 3, 0.5), 0.25, 1e-15);  // upper tail: P(X = 3) = 1/8
  EXPECT_EQ(binomial_two_sided_p(4, 1000, 0.004), 1.0);       // at the mean: both tails over one half
  EXPECT_LT(binomial_two_sided_p(40, 1000, 0.004), 1e-15);    // ten times the mean
  EXPECT_EQ(binomial_two_sided_p(5000000, 10000000, 1e-7), 0.0);  // underflows at once: no 5e6 terms
  EXPECT_THROW(binomial_two_sided_p(2, 1, 0.5), std::invalid_argument);
  EXPECT_THROW(binomial_two_sided_p(0, 1, 1.0), std::invalid_argument);
  // A class expected 4 times (pooled for the chi-square) and never seen: before, p = 1 (one
  // pooled class, nothing to test); now its exact p-value, the only test.
  const ChiSquareResult gone = chi_square_counts({5000, 0}, {0.9992, 0.0008});
  EXPECT_EQ(gone.dof, 0);
  EXPECT_EQ(gone.rare, 1u);
  EXPECT_NEAR(gone.p, 2 * std::pow(0.9992, 5000.0), 1e-12);
  // Two classes tested by the chi-square and a third expected 2.95 times, missing: two tests,
  // the smaller p-value times 2.
  const ChiSquareResult three = chi_square_counts({29000, 30000, 0}, {0.49, 0.50995, 0.00005});
  EXPECT_EQ(three.dof, 1);
  EXPECT_EQ(three.rare, 1u);
  EXPECT_NEAR(three.rare_p, 2 * std::pow(0.99995, 59000.0), 1e-12);
  EXPECT_NEAR(three.p, std::min(1.0, 2 * std::min(chi_square_survival(three.statistic, 1), three.rare_p)), 1e-15);
}

// How many of `samples` samples of n radii drawn from `law` (values 1, 2, 3, ...) the test
// rejects at 0.05 against the law itself.
int rejections_under_the_null(const DiscreteRadius& law, int samples, int n, std::uint64_t seed) {
  Rng rng(seed);
  int rejected = 0;
  for (int t = 0; t < samples; ++t) {
    std::vector<std::uint64_t> counts(law.probabilities().size(), 0);
    for (int k = 0; k < n; ++k) ++counts[static_cast<std::size_t>(law.sample(rng)) - 1];
    rejected += chi_square_counts(counts, law.probabilities()).p < 0.05 ? 1 : 0;
  }
  return rejected;
}

TEST(ChiSquareCounts, RareClassesKeepTheLevelUnderTheNull) {
  // 2000 samples of n = 300 from {0.97, 0.02, 0.01} (the last two expected 6 and 3): the
  // combined test rejects at most about its level.
  const DiscreteRadius law({{1.0, 0.97}, {2.0, 0.02}, {3.0, 0.01}});
  EXPECT_LT(rejections_under_the_null(law, 2000, 300, 78), 0.07 * 2000);
}

TEST(ChiSquareCounts, RejectionRateUnderTheNullIsNominalAndASkewIsSeen) {
  // 400 samples of n = 200 from a 3-value law: about 5 % of the p-values fall below 0.05.
  const DiscreteRadius law({{1.0, 0.2}, {2.0, 0.3}, {3.0, 0.5}});
  const int rejected = rejections_under_the_null(law, 400, 200, 77);
  EXPECT_GT(rejected, 5);  // Binomial(400, 0.05): mean 20, sd 4.4
  EXPECT_LT(rejected, 38);
  // 0.25 / 0.3 / 0.45 observed at n = 2000 against 0.2 / 0.3 / 0.5: X2 = 35, p ~ 2.5e-8.
  EXPECT_LT(chi_square_counts({500, 600, 900}, law.probabilities()).p, 1e-7);
}

}  // namespace
}  // namespace fp
