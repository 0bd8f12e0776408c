#pragma once
// JSON form of a PackingAnalysis (core/metrics/packing_analysis.hpp: the quality figures of
// papers 000 (Eqs. 15-17, z(xi), g(r)) and 002 (Eqs. 1-2, K-S, projections)). Only analysis_json.cpp
// includes nlohmann_json; it reads the analysis' plain fields only, so fp_io needs no link to
// fp_metrics.
//
// Layout (keys always present, in this order; NaN and infinities become null):
//   dimension, particles, radii {name ("r", or "r_eq" for shapes), min, max, mean},
//   templates [{family, count}] (shapes only), container {description, from_particles, measure},
//   contact_tolerance,
//   volume_fraction {reference {center, radius, value}, curve {r_ref: [], vf: []},
//                    container {...}, core {...}}   (region: shrink, value, std_error, exact, method,
//                                                     measure {value, std_error}, balls {inside,
//                                                     cut_exact, sampled})
//   coordination {mean, mean_with_walls, contacts, wall_contacts, rattlers, histogram: [],
//                 partial {xi, radius, particles, contacts, z}}
//   overlap {max_overlap_rel, max_contact_gap_rel, worst_pair: [i, j] or null}
//   fabric {per_contact, per_particle}   (each {tensor: D x D, eigenvalues, count})
//   homogeneity {margin, axes: [{axis, lo, hi, n, d, sqrt_n_d, p, below_critical}]}
//   radii_fit {distribution, test, n, statistic, dof, p, off_support}   (test: constant | chi-square | K-S)
//   relative_projections {reference, bins, contacts, axes: [{axis, histogram, n, d, sqrt_n_d, p}]}
//   rdf {mean_diameter, range, reference_margin, reference_particles, reference_measure {value,
//        std_error}, density, r: [], g: []}
//   orientation {axis, tensor {tensor, eigenvalues, count}, order} (shapes only)
//   validation (null when not run) {ok, tolerance, radii_alpha, particles, pairs_checked,
//        max_overlap_rel (over min(ri, rj)), max_outside_rel, overlap_count, outside_count,
//        radius_count, non_finite_count, contacts, wall_contacts, max_contact_gap_rel,
//        worst: [{kind, i, j, value_rel}], radii {test, n,
//        statistic, dof, p, off_support}}
//   and, with include_timings, timings {name: seconds} (which differ from run to run).
#include <string>

#include "core/metrics/packing_analysis.hpp"

namespace fp {

/// The analysis, pretty-printed, ending with a newline. Identical analyses give identical bytes
/// unless include_timings.
std::string analysis_json(const PackingAnalysis& analysis, bool include_timings = false);

/// The analysis' `validation` member alone (the verdict of `frontpack validate`), pretty-printed.
std::string validation_json_text(const ValidationReport& validation);

}  // namespace fp
