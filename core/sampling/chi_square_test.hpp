#pragma once
// Pearson's chi-square goodness-of-fit test of counts per class: the radii test of a discrete
// size distribution (a constant radius is the one-class case). The counts of a discrete law are
// multinomial, and Pearson's statistic is the standard test of multinomial proportions; the
// K-S p-value is not valid for a step CDF (it is conservative and loses power there).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fp {

/// P(X > x) for X chi-square with dof >= 1 degrees of freedom: the regularised upper incomplete
/// gamma function Q(dof / 2, x / 2), accurate in relative terms down to the smallest doubles.
/// 1 for x <= 0. Throws std::invalid_argument for dof < 1 or a NaN x.
double chi_square_survival(double x, int dof);

/// Two-sided exact binomial p-value of `k` successes in `n` trials of probability `p` (0 < p < 1,
/// k <= n): twice the smaller tail, P(X <= k) or P(X >= k), at most 1.
double binomial_two_sided_p(std::uint64_t k, std::uint64_t n, double p);

struct ChiSquareResult {
  double statistic = 0.0;  ///< sum over the (pooled) classes of (O - E)^2 / E
  int dof = 0;             ///< pooled classes - 1; 0: one class, nothing to test
  /// The test's p-value: chi_square_survival(statistic, dof) (1 when dof == 0), or with rare
  /// classes the smallest of it and their exact p-values times the number of tests (Bonferroni).
  double p = 1.0;
  std::size_t classes = 0; ///< after pooling
  std::size_t rare = 0;    ///< classes expected fewer than 5 times, each also tested exactly
  double rare_p = 1.0;     ///< the smallest exact p-value of a rare class (1 without one)
};

/// Test of `observed` counts (n = their sum > 0) against class `probabilities` (same size, > 0,
/// summing to 1 up to rounding). Adjacent classes are pooled, in the order given, until every
/// expected count n p is at least 5 (Cochran's rule: below that the chi-square law of the
/// statistic is not a good approximation and small classes would fake significance). A pooled
/// class loses its own count, so every class expected fewer than 5 times is tested on its own
/// too, by the exact binomial test of its count: a rare class missing from the sample (a grain of
/// gravel per thousand of sand the packer found no room for) cannot hide in its neighbour.
/// Throws std::invalid_argument on a size mismatch, an empty sample or a non-positive probability.
ChiSquareResult chi_square_counts(const std::vector<std::uint64_t>& observed, const std::vector<double>& probabilities);

}  // namespace fp
