#pragma once
// A bed's profile (core/geometry/bed_region.hpp): the solid fraction against the height above
// the floor, in slabs across the whole container, and the surface the top particles make.
//  * Slab k holds the bed's points at height [k w, (k + 1) w); its solid fraction is the solid
//    in it over its measure. The measures are exact (the bed's cut at each height). Spheres are
//    cut in closed form (sphere caps, disk segments); other shapes through vf_region's bodies,
//    whole where their bounding ball lies in a slab, by QMC where it straddles.
//  * The bulk is the slabs between 2 r_max above the floor and 2 r_max below the level, where
//    neither the floor nor the surface orders the particles; the top layer is the last 2 r_max.
//  * The half-bulk height is where the profile, read down from the level, first reaches half
//    the bulk: a bed packed to its level has it within a particle radius of the level.
//  * The surface: the highest particle top over columns of 4 r_max across `up`, those
//    whose corners lie a radius inside the walls 2 r_max under the level; a flat surface has
//    every column's top within a particle diameter of the level.
#include <cstdint>
#include <vector>

#include "core/geometry/bed_region.hpp"
#include "core/geometry/packing.hpp"
#include "core/metrics/container_volume_fraction.hpp"
#include "core/metrics/qmc.hpp"

namespace fp {

struct BedSurfaceTops {
  std::uint64_t columns = 0;   ///< columns clear of the walls holding a particle
  double mean = 0.0, std_dev = 0.0, min = 0.0, max = 0.0;  ///< heights of their highest tops above the floor
};

struct BedProfile {
  double height = 0.0;        ///< the fill height (level above the floor)
  double width = 0.0;         ///< of a slab; the last one ends at the level
  std::vector<Estimate> vf;   ///< per slab from the floor up
  Estimate bulk;              ///< the slabs from 2 r_max above the floor to 2 r_max below the level (NaN: none)
  Estimate top_layer;         ///< the last 2 r_max below the level
  double half_bulk_height = 0.0;  ///< NaN without a bulk
  BedSurfaceTops surface;     ///< columns 0 without the particles' tops

  bool computed() const { return !vf.empty(); }
  /// The height of slab k's middle above the floor.
  double middle(std::size_t k) const;
};

/// Slabs of at most max(r_max / 2, height / kMaxBedSlabs), a whole number of them in the height.
inline constexpr int kMaxBedSlabs = 400;

template <int D>
BedProfile bed_profile(const Packing<D>& packing, const BedRegion<D>& bed, double r_max);
/// Particles of any shape; `tops` (one per body, or none): each one's highest point along `up`
/// (up . x, the bed's frame), for the surface figure.
template <int D>
BedProfile bed_profile(const RegionBodies<D>& bodies, const BedRegion<D>& bed, double r_max, const QmcOptions& qmc = {},
                       const std::vector<double>& tops = {});

}  // namespace fp
