#pragma once
// Radial distribution function g(r) of the centres (paper 000 Sect. 3.3, Fig. 7b), with r in
// mean diameters <d> (by count): g = 0 below the closest approach, a first peak near 1, and g -> 1
// where there is no long-range order. Standard ideal-gas normalisation:
//   g(r_k) = H_k / (N_ref rho |shell_k|),
// H_k the number of (reference, other) centre pairs at a distance in bin k, |shell_k| the measure
// of the bin's spherical (2D: annular) shell, rho the number of centres in the reference region
// over its measure.
// Boundary handling: no correction formula; the reference centres are restricted to the region at
// least r_cut + r_max inside the container (signed_distance <= -(r_cut + r_max)), so every shell
// around them lies where centres are not depleted by the wall; all centres count as neighbours.
// The measure of that region is exact for boxes, balls and cylinders, else QMC (qmc.hpp).
// Large packings: at most max_reference of those centres are used (every k-th by index, k the
// smallest step that keeps them under the cap); rho still counts them all. 10^5 references with
// hundreds of neighbours each put far more pairs in every bin than its shape needs.
// Search: the metrics cell list enumerates pairs at contact reach; g(r) needs, per reference
// centre, every centre within r_cut (~10 radii), so it buckets the centres in a uniform grid of
// cells of side r_cut / 3 and visits only the cells the ball of radius r_cut reaches.
#include <cstdint>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/metrics/qmc.hpp"

namespace fp {

struct RdfOptions {
  double range = 5.0;  ///< r_cut, in mean diameters
  int bins = 100;      ///< equal bins on [0, range]
  std::uint64_t max_reference = 100000;  ///< cap on the reference centres used
  QmcOptions qmc;      ///< for the measure of the reference region of other containers
};

struct RadialDistribution {
  double mean_diameter = 0.0;
  double range = 0.0;                      ///< r_cut / <d>
  std::vector<double> r;                   ///< bin centres / <d>
  std::vector<double> g;                   ///< all 0 when there is no reference centre
  double reference_margin = 0.0;           ///< r_cut + r_max, in length units
  std::uint64_t eligible_particles = 0;    ///< centres at least reference_margin inside
  std::uint64_t reference_particles = 0;   ///< N_ref: those used (<= max_reference)
  Estimate reference_measure;              ///< of the region of the reference centres
  double density = 0.0;                    ///< rho = eligible_particles / reference_measure
};

/// O(N + N_ref (r_cut / <d>)^D). Throws std::invalid_argument unless range > 0, bins >= 1 and
/// max_reference >= 1. Balls with a non-finite or non-positive radius or centre are left out.
/// `threads` share the reference particles; the result is the same for every count.
template <int D>
RadialDistribution radial_distribution(const Packing<D>& packing, const Container<D>& container,
                                       const RdfOptions& options = {}, int threads = 1);

}  // namespace fp
