#pragma once
// The independent check of a packing: every pair (through its own cell list, not the packer's
// grid), every ball against the container (through its own distances, containment_check.hpp,
// not the container's code), every radius against the requested distribution.
// `frontpack pack` and `frontpack validate` give this one verdict: the figure the packer reports
// must be the figure validate finds. Packings of shapes get the same verdict and report from the
// same code (validate_particles.hpp) with their own geometry (contact/shape_validation.hpp).
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/metrics/contact_network.hpp"
#include "core/metrics/orientation_fit.hpp"
#include "core/metrics/radii_fit.hpp"
#include "core/sampling/chi_square_test.hpp"
#include "core/sampling/radius_distribution.hpp"

namespace fp {

/// Default level of the radii test, the same for `pack` and `validate` (one verdict).
inline constexpr double kRadiiAlpha = 1e-3;

struct ValidationIssue {
  /// "overlap": pair (i, j), i < j, value overlap depth / smaller unit (spheres: (ri + rj - d) / min(ri, rj));
  /// "outside": particle i (j = -1), value protrusion / unit (spheres: (signed_distance(c) + r) / r,
  ///   ContainmentCheck's distance);
  /// "radius_out_of_range" (spheres) / "size_out_of_range" (shapes): particle i, value
  ///   radius_excess(law, size) (radii_fit.hpp: relative distance to the sizes the law can
  ///   produce; 1 for a size <= 0 without a law);
  /// "non_finite": particle i with a NaN/inf position or size, value +inf.
  std::string kind;
  std::int64_t i = -1, j = -1;
  double value_rel = 0.0;
};

/// What a packing was asked for, per template id: the size law (the radius law of spheres), the
/// share by number and (shapes) the orientation law.
struct RequestedTemplate {
  const RadiusDistribution* size = nullptr;
  double fraction = 1.0;
  const OrientationSpec* orientation = nullptr;  ///< null: orientations not tested (spheres)
};

/// The one report of every packing's check (validate_particles.hpp), spheres and shapes. Lengths
/// are relative to a particle's length unit: a sphere's radius, a shape's circumscribed radius
/// (a pair: the smaller of the two).
struct ValidationReport {
  /// At least one particle, no issue of any kind and every size test passed.
  bool ok = true;
  double tolerance = 0.0;          ///< overlap allowance and contact tolerance used
  std::string unit_name = "radius";  ///< the length unit: "radius", or "circumscribed radius" for shapes
  double radii_alpha = kRadiiAlpha;  ///< level shared by the size tests (Bonferroni)
  std::uint64_t particles = 0;
  std::uint64_t pairs_checked = 0; ///< candidate pairs whose exact distance was computed
  double max_overlap_rel = 0.0;    ///< max over pairs of overlap depth / smaller unit, <= 0 if none overlap
  double max_outside_rel = 0.0;    ///< max over particles of protrusion / unit, <= 0 if all inside
  std::uint64_t overlap_count = 0, outside_count = 0, radius_count = 0, non_finite_count = 0;
  std::vector<ValidationIssue> worst;  ///< up to 20 issues, largest value_rel first

  // Contacts: pairs with |gap| <= tolerance x the smaller unit; particles that close to the walls.
  std::uint64_t contacts = 0;
  std::uint64_t wall_contacts = 0;
  double max_contact_gap_rel = 0.0;  ///< largest |gap| / smaller unit among the contacts (how exactly they touch)

  /// The test of each template's sizes against its law (radii_fit.hpp; spheres: one, the radii);
  /// a template without a law or without particles is not computed.
  std::vector<RadiiFit> sizes;
  /// Two templates or more: chi-square of the counts per template against the requested shares.
  std::optional<ChiSquareResult> mix;

  /// Shapes: the test of each template's orientations against its law (orientation_fit.hpp); a
  /// template without a law or without particles is not computed. Their tests share their own
  /// level, orientation_alpha (Bonferroni), beside the size tests'.
  std::vector<OrientationFit> orientations;
  double orientation_alpha = kOrientationAlpha;

  bool empty() const { return particles == 0; }
  /// Orientation tests computed (a template's polar, azimuth and spin count three).
  int orientation_tests() const;
  double orientation_level() const { return orientation_tests() > 0 ? orientation_alpha / orientation_tests() : orientation_alpha; }
  bool orientations_ok() const;
  double mean_coordination() const { return particles ? 2.0 * static_cast<double>(contacts) / static_cast<double>(particles) : 0.0; }
  /// The radii of a packing of spheres (the one size law); not computed otherwise.
  const RadiiFit& radii() const;
  /// Size tests computed (each template's, and the mix).
  int tests() const;
  /// Each test at radii_alpha / tests().
  double test_level() const { return tests() > 0 ? radii_alpha / tests() : radii_alpha; }
  bool sizes_ok() const;
  /// A few lines: verdict, counts, maxima, the worst issues, the size tests.
  std::string summary() const;
  /// One line for a summary: "ok (...)" or "FAILED (...)" with what was checked and found.
  std::string one_line() const;
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
/// container kind without an independent check. With `network`, the contacts it found are listed
/// there (the analysis' contact network: contacts are found once). `threads` share the work; the
/// report is the same for every count.
template <int D>
ValidationReport validate_packing(const Packing<D>& packing, const Container<D>& container,
                                  const RadiusDistribution* dist_or_null, double overlap_tol_rel = 1e-9,
                                  double radii_alpha = kRadiiAlpha, ContactNetwork<D>* network = nullptr,
                                  int threads = 1);

}  // namespace fp
