#pragma once
// The independent check of a packing: every pair (through its own cell list, not the packer's
// grid), every ball against the container (through its own distances, containment_check.hpp,
// not the container's code), every radius against the requested distribution.
// `frontpack pack` and `frontpack validate` give this one verdict: the figure the packer reports
// must be the figure validate finds.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/metrics/radii_fit.hpp"
#include "core/sampling/radius_distribution.hpp"

namespace fp {

/// Default level of the radii test, the same for `pack` and `validate` (one verdict).
inline constexpr double kRadiiAlpha = 1e-3;

struct ValidationIssue {
  /// "overlap": pair (i, j), i < j, value (ri + rj - d) / min(ri, rj);
  /// "outside": ball i (j = -1), value (signed_distance(c) + r) / r (ContainmentCheck's distance);
  /// "radius_out_of_range": ball i, value radius_excess(dist, r) (radii_fit.hpp: relative
  ///   distance to the radii the law can produce; 1 for r <= 0 without a distribution);
  /// "non_finite": ball i with a NaN/inf centre or radius, value +inf.
  std::string kind;
  std::int64_t i = -1, j = -1;
  double value_rel = 0.0;
};

struct ValidationReport {
  /// At least one particle, no issue of any kind and the radii test passed at radii_alpha.
  bool ok = true;
  double tolerance = 0.0;          ///< overlap_tol_rel used
  double radii_alpha = kRadiiAlpha;
  std::uint64_t particles = 0;
  std::uint64_t pairs_checked = 0; ///< candidate pairs whose exact distance was computed
  double max_overlap_rel = 0.0;    ///< max over pairs of (ri + rj - d) / min(ri, rj), 0 if none overlap
  double max_outside_rel = 0.0;    ///< max over balls of (signed_distance(c) + r) / r, 0 if all inside
  std::uint64_t overlap_count = 0, outside_count = 0, radius_count = 0, non_finite_count = 0;
  std::vector<ValidationIssue> worst;  ///< up to 20 issues, largest value_rel first
  /// The goodness-of-fit test of the finite radii (radii_fit.hpp); not computed without a
  /// distribution.
  RadiiFit radii;

  bool empty() const { return particles == 0; }
  bool radii_ok() const { return radii.passes(radii_alpha); }
  /// A few lines: verdict, counts, maxima, the worst issues, the radii test.
  std::string summary() const;
};

/// One line: "overlap 12-40: 3.1e-08" (kind, ids, value relative to min(ri, rj) or r).
std::string describe(const ValidationIssue& issue);

/// Checks a packing with the packer's own rules, on code of its own (a cell list, not the packer's
/// grid; containment_check.hpp, not the container's distance code). A pair overlaps when
/// (ri + rj - d) > overlap_tol_rel * min(ri, rj) (the packer's allowance); a ball is outside
/// when its centre is outside or its distance to the boundary is below r - overlap_tol_rel * r;
/// with a distribution, a radius is out of range when radius_excess > kRadiusSlack and the radii
/// fail when the radii_fit p-value is below radii_alpha; without one, only r <= 0 is an issue.
/// An empty packing fails. Throws std::invalid_argument unless overlap_tol_rel >= 0, and for a
/// container kind without an independent check.
template <int D>
ValidationReport validate_packing(const Packing<D>& packing, const Container<D>& container,
                                  const RadiusDistribution* dist_or_null, double overlap_tol_rel = 1e-9,
                                  double radii_alpha = kRadiiAlpha);

}  // namespace fp
