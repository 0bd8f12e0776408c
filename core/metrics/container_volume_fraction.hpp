#pragma once
// Volume fraction (area fraction in 2D) of a region of the container: the whole container, or
// its core, the points at least `shrink` inside the boundary ({x : signed_distance(x) <= -shrink};
// the core of the analysis uses shrink = 2 r_max). Paper 002 Sect. 1 defines VF as the solid
// measure over the container measure; paper 000 Eq. 16 computes it in a probe as sum chi_i V_i / V_p,
// chi_i the fraction of particle i inside: that is what is summed here, with the region as probe.
//
// Method, ball by ball (balls assumed not to overlap one another, as validate checks):
//  * wholly inside the region (for a general container: signed_distance(c) <= -shrink - r, which
//    suffices because the signed distance is 1-Lipschitz): its full measure, exact;
//  * wholly outside: nothing;
//  * straddling the boundary: in closed form where there is one — a box region cut by a single
//    face plane (sphere cap / disk segment), a ball region (lens, paper 002 Eq. 2) — otherwise by
//    randomised QMC (qmc.hpp) inside the ball's bounding cube.
// The region's measure is exact for boxes, balls, cylinders (a shrunk cylinder is a cylinder) and
// for any container when shrink = 0; otherwise QMC over the shrunk bounding box. The reported
// standard error is that of the replicates of solid / measure; it is 0 when nothing was sampled.
// A valid packing (every ball inside) has no straddling ball in the whole container, so its VF
// there is exact for every container and equals vf_container(packing, container.measure()).
#include <cstdint>
#include <functional>
#include <string>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/metrics/qmc.hpp"

namespace fp {

struct RegionVolumeFraction {
  double shrink = 0.0;               ///< the region: signed_distance <= -shrink
  Estimate measure;                  ///< |region| (0: empty region, vf NaN)
  Estimate vf;                       ///< sum over balls of |ball and region| / |region|
  std::uint64_t balls_inside = 0;    ///< counted whole
  std::uint64_t balls_cut_exact = 0; ///< straddling, measured in closed form
  std::uint64_t balls_sampled = 0;   ///< straddling, estimated by QMC
  bool exact = true;                 ///< nothing estimated (std errors are 0)
  std::string method;                ///< e.g. "exact", "exact + QMC (12 balls)", "QMC measure"
};

/// |{x : signed_distance(x) <= -shrink}|: exact where stated above, else QMC. shrink >= 0.
template <int D>
Estimate region_measure(const Container<D>& container, double shrink, const QmcOptions& qmc = {});

/// VF in the region of points at least `shrink` (>= 0) inside the container. O(N) plus the QMC
/// work for straddling balls (replicates * points_per_ball each). Balls with a non-finite centre
/// or radius are skipped. Throws std::invalid_argument for a negative or non-finite shrink.
template <int D>
RegionVolumeFraction vf_region(const Packing<D>& packing, const Container<D>& container, double shrink,
                               const QmcOptions& qmc = {});

/// Particles of any shape for vf_region: each one's bounding ball (centre, radius), its exact
/// measure and whether it holds a point. A particle whose bounding ball is inside the region
/// counts whole (its exact measure), one whose ball is outside counts nothing, and one whose
/// ball straddles the boundary is sampled by QMC in the ball's bounding cube against
/// contains(i, x) and the region ("balls" in the result's counts are these particles).
template <int D>
struct RegionBodies {
  std::vector<Vec<D>> centres;
  std::vector<double> bounding_radii;
  std::vector<double> measures;
  std::function<bool(std::size_t, const Vec<D>&)> contains;
};

template <int D>
RegionVolumeFraction vf_region(const RegionBodies<D>& bodies, const Container<D>& container, double shrink,
                               const QmcOptions& qmc = {});

}  // namespace fp
