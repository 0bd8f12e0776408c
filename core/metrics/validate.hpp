#pragma once
// The independent check of a packing: every pair (through its own cell list, not the packer's
// grid), every ball against the container, every radius against the requested distribution.
// The figure the packer reports must be the figure validate finds.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/sampling/radius_distribution.hpp"

namespace fp {

struct ValidationIssue {
  /// "overlap": pair (i, j), i < j, value (ri + rj - d) / r_min;
  /// "outside": ball i (j = -1), value (signed_distance(c) + r) / r;
  /// "radius_out_of_range": ball i, value the relative distance to the allowed range
  ///   ((r - r_max) / r_max above, (r_min - r) / r_min below; 1 for r <= 0 without a distribution);
  /// "non_finite": ball i with a NaN/inf centre or radius, value +inf.
  std::string kind;
  std::int64_t i = -1, j = -1;
  double value_rel = 0.0;
};

struct ValidationReport {
  bool ok = true;                  ///< no issue of any kind (the K-S figures do not count)
  double tolerance = 0.0;          ///< overlap_tol_rel used
  std::uint64_t particles = 0;
  std::uint64_t pairs_checked = 0; ///< candidate pairs whose exact distance was computed
  double max_overlap_rel = 0.0;    ///< max over pairs of (ri + rj - d) / r_min, 0 if none overlap
  double max_outside_rel = 0.0;    ///< max over balls of (signed_distance(c) + r) / r, 0 if all inside
  std::uint64_t overlap_count = 0, outside_count = 0, radius_count = 0, non_finite_count = 0;
  std::vector<ValidationIssue> worst;  ///< up to 20 issues, largest value_rel first
  /// One-sample K-S of the radii against the distribution; NaN when none was given.
  double radii_ks_statistic = std::numeric_limits<double>::quiet_NaN();
  double radii_ks_pvalue = std::numeric_limits<double>::quiet_NaN();

  /// A few lines: verdict, counts, maxima, the worst issues, the radii K-S.
  std::string summary() const;
};

/// Checks a packing. r_min is the smallest positive radius of the packing. An overlap is an
/// issue when (ri + rj - d) / r_min > overlap_tol_rel; a ball is outside when signed_distance(c)
/// + r > overlap_tol_rel * r; with a distribution, radii outside [dist.r_min, dist.r_max] (1e-12
/// relative slack) are issues; without one, only r <= 0 is. Throws std::invalid_argument unless
/// overlap_tol_rel >= 0.
/// One line: "overlap 12-40: 3.1e-08" (kind, ids, value relative to r_min or r).
std::string describe(const ValidationIssue& issue);

template <int D>
ValidationReport validate_packing(const Packing<D>& packing, const Container<D>& container,
                                  const RadiusDistribution* dist_or_null, double overlap_tol_rel = 1e-9);

}  // namespace fp
