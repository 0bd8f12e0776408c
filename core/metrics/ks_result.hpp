#pragma once
// A one-sample Kolmogorov-Smirnov test as the metrics report it (paper 002 Sect. 1 and 4: the
// packing is homogeneous at 95 % when sqrt(n) D_n < 1.358 for each centre coordinate).
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "core/sampling/ks_test.hpp"

namespace fp {

struct KsResult {
  std::uint64_t n = 0;                                        ///< sample size (0: not computed)
  double d = std::numeric_limits<double>::quiet_NaN();        ///< D_n = sup |F_n - F|
  double sqrt_n_d = std::numeric_limits<double>::quiet_NaN(); ///< sqrt(n) D_n, compared with 1.358
  double p = std::numeric_limits<double>::quiet_NaN();        ///< ks_pvalue(D_n, n)
  /// sqrt(n) D_n below the 5 % critical value 1.358 (false when not computed).
  bool below_critical() const { return sqrt_n_d < kKsCritical5Percent; }
};

/// The test of `samples` against `cdf` (ks_statistic, ks_pvalue of core/sampling/ks_test.hpp).
/// An empty sample gives the default (NaN) result. O(n log n).
KsResult ks_one_sample(std::vector<double> samples, const std::function<double(double)>& cdf);

}  // namespace fp
