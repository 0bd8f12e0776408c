#pragma once
// The wall layers: the solid fraction against the distance from the container's boundary. Shell
// k holds the points at distance [k w, (k + 1) w) inside the boundary; its solid fraction is
// (S_k - S_{k+1}) / (M_k - M_{k+1}), with S_s and M_s the solid and the measure of the region
// {signed_distance <= -s} as container_volume_fraction.hpp's vf_region finds them (exact where it
// is: spheres in boxes, balls, cylinders; QMC otherwise). The two regions' errors are combined as
// if independent (an upper bound: their estimates share the shifts). Walls cost density for
// elongated particles over about half a particle length (Freeman et al. 2019, Granular Matter
// 21:84): the analysis reports shells of r_max / 4 out to 2 r_max, where its core begins.
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/metrics/container_volume_fraction.hpp"
#include "core/metrics/qmc.hpp"

namespace fp {

struct WallProfile {
  double width = 0.0;         ///< of a shell
  std::vector<Estimate> vf;   ///< per shell from the boundary inwards; a container thinner than the shells has fewer
  Estimate layer;             ///< the shells together: the solid fraction within shells x width of the boundary

  bool computed() const { return !vf.empty(); }
  /// The distance of shell k's middle from the boundary.
  double middle(std::size_t k) const { return (static_cast<double>(k) + 0.5) * width; }
};

/// The profile of balls (Packing) or of particles of any shape (RegionBodies), `shells` shells of
/// `width` (> 0). A shell of zero measure (the container is thinner) ends it.
template <int D>
WallProfile wall_profile(const Packing<D>& packing, const Container<D>& container, double width, int shells, const QmcOptions& qmc = {});
template <int D>
WallProfile wall_profile(const RegionBodies<D>& bodies, const Container<D>& container, double width, int shells,
                         const QmcOptions& qmc = {});

}  // namespace fp
