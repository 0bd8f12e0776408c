#pragma once
// The goodness-of-fit test of a packing's radii against the requested size distribution, chosen
// by the kind of law (RadiusDistribution::atoms()):
//   constant   every radius equals the value within kRadiusSlack (p = 1, else 0);
//   discrete   Pearson's chi-square on the counts per value, and the exact binomial test of each
//              value expected fewer than 5 times (core/sampling/chi_square_test.hpp);
//              a radius matching no value (within kRadiusSlack) has probability 0: p = 0;
//   continuous one-sample Kolmogorov-Smirnov (core/sampling/ks_test.hpp).
// One definition for `pack`, `validate` and `analyze`. The front leaves its last `radius_pool`
// draws unplaced (mostly large ones), so the placed radii are a slightly biased sample: the test
// is meant to see that bias when the pool is large against N, and it does.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/sampling/radius_distribution.hpp"

namespace fp {

/// Relative slack between a radius and the law's values or bounds: files round-trip doubles
/// exactly, so this only absorbs the rounding of a scale applied to a whole packing.
inline constexpr double kRadiusSlack = 1e-12;

struct RadiiFit {
  std::string test;           ///< "constant", "chi-square" or "K-S"; "" when not computed
  std::uint64_t n = 0;        ///< radii tested (0: not computed)
  /// constant: max |r - value| / value; chi-square: Pearson's X^2 (+inf with off_support);
  /// K-S: D_n = sup |F_n - F|.
  double statistic = std::numeric_limits<double>::quiet_NaN();
  int dof = 0;                ///< chi-square: pooled classes - 1 (0: one class)
  std::size_t rare = 0;       ///< chi-square: values expected fewer than 5 times, tested exactly too
  double rare_p = 1.0;        ///< chi-square: the smallest exact p-value of those
  double p = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t off_support = 0;  ///< constant/discrete: radii matching none of the values

  bool computed() const { return n > 0; }
  /// Not computed, or p >= alpha.
  bool passes(double alpha) const { return !computed() || !(p < alpha); }
  /// E.g. "chi-square X2 = 0.475 (1 dof), p = 0.491".
  std::string describe() const;
};

/// How far r lies from the radii the law can produce, relative to the nearest of them: for a
/// discrete law |r - v| / v for the nearest value v; for a continuous one (r - r_max) / r_max
/// above, (r_min - r) / r_min below, 0 in between. A radius is out of range when this exceeds
/// kRadiusSlack.
double radius_excess(const RadiusDistribution& dist, double r);

/// The test of `radii` (finite; any order) against `dist`. An empty sample gives the default
/// (not computed) result.
RadiiFit radii_fit(std::vector<double> radii, const RadiusDistribution& dist);

}  // namespace fp
