#pragma once
// Randomised quasi-Monte-Carlo integration over boxes: a Halton point set (bases 2, 3, 5)
// with Cranley-Patterson random shifts (Owen, "Monte Carlo theory, methods and examples",
// ch. 17). Every replicate shifts the same points by one uniform vector modulo 1, so each
// replicate is an unbiased estimate, and the spread of the replicates gives the standard error
// that a bare low-discrepancy sequence cannot. Shifts come from our Rng: the same seed gives the
// same estimate on every platform. Used for the VF of paper 000 Eq. 16 in regions without a
// closed form (container_volume_fraction.hpp) and for region measures (radial_distribution.hpp).
// Integrals that are sums of many small ones (one per ball) give each term its own shifts
// (qmc_shift with its own stream): on a lattice the terms repeat, and shared shifts would make
// their errors add up instead of averaging out.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

/// Sample sizes of the estimators that use QMC (container and core volume fractions, g(r)).
struct QmcOptions {
  std::size_t points_per_ball = 32;    ///< per replicate, for a ball straddling a region's boundary
  /// Cap on points_per_ball * replicates * straddling balls: beyond it fewer points per ball
  /// (at least 4), since the errors of many balls average out. Keeps a mesh container's core,
  /// where every ball near the surface straddles, at a few seconds for 10^6 balls.
  std::size_t max_ball_points = std::size_t{1} << 21;
  std::size_t region_points = 4096;    ///< per replicate, for the measure of a region
  int replicates = 16;                 ///< independent random shifts (>= 2 for a standard error)
  std::uint64_t seed = 0x5eed;         ///< of the shifts
};

/// A value with its standard error (0 when the value is exact up to rounding).
struct Estimate {
  double value = 0.0;
  double std_error = 0.0;
};

/// Van der Corput radical inverse of i in base b: the digits of i mirrored behind the point.
double radical_inverse(std::uint64_t i, unsigned base);

/// Points 1..n of the D-dimensional Halton sequence (bases 2, 3, 5), in [0, 1)^D.
template <int D>
std::vector<Vec<D>> halton_points(std::size_t n);

/// A shift uniform in [0, 1)^D, the same for the same (seed, stream).
template <int D>
Vec<D> qmc_shift(std::uint64_t seed, std::uint64_t stream);

/// One shift per replicate: qmc_shift(options.seed, k), k = 0 .. replicates - 1.
template <int D>
std::vector<Vec<D>> qmc_shifts(const QmcOptions& options);

/// frac(u + shift), componentwise: the shifted point in [0, 1)^D.
template <int D>
Vec<D> shifted(const Vec<D>& u, const Vec<D>& shift) {
  Vec<D> x = u + shift;
  for (int a = 0; a < D; ++a) x[a] -= x[a] >= 1.0 ? 1.0 : 0.0;
  return x;
}

/// Mean of the replicate estimates and the standard error of that mean (0 for one replicate).
Estimate mean_and_error(const std::vector<double>& replicates);

}  // namespace fp
