#pragma once
// The contact network of a packing of spheres (3D) or disks (2D), found independently of the
// packer. Touching rule (design notes): a pair is in contact when gap = d - ri - rj satisfies
// gap <= rel_tol * min(ri, rj); a ball touches the container when -signed_distance(c) - r <=
// rel_tol * r. Overlapping pairs (gap < 0) count as contacts too, so that packings with small
// interpenetrations (DEM outputs) keep their network; for a valid packing both readings agree.
// Distances are taken from the difference of the centres, never from |a|^2 - 2ab + |b|^2, so
// coordinates offset by 1e6 lose nothing. Later metrics (fabric tensor, partial coordination)
// start from these lists.
#include <cstdint>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"

namespace fp {

struct PairContact {
  std::uint32_t i, j;  ///< i < j
  double gap;          ///< d - ri - rj (< 0: overlap)
};

struct WallContact {
  std::uint32_t i;
  double gap;  ///< -signed_distance(c) - r (< 0: the ball crosses the boundary)
};

/// Every pair in contact, sorted by (i, j). Throws std::invalid_argument unless rel_tol >= 0.
/// Balls with a non-finite centre or radius, or a negative radius, are ignored.
template <int D>
std::vector<PairContact> find_pair_contacts(const Packing<D>& packing, double rel_tol = 1e-9);

/// Every ball touching the container boundary, by id. One entry per ball at most: the container
/// is seen through its signed distance, so a ball in a corner counts one wall contact.
template <int D>
std::vector<WallContact> find_wall_contacts(const Packing<D>& packing, const Container<D>& container,
                                            double rel_tol = 1e-9);

/// The centre line c_j - c_i of every contact (not normalised): the contact directions of spheres.
template <int D>
std::vector<Vec<D>> centre_lines(const Packing<D>& packing, const std::vector<PairContact>& contacts);

/// Particle-particle coordination number of every ball.
std::vector<std::uint32_t> coordination_numbers(std::size_t particle_count, const std::vector<PairContact>& contacts);

/// Smallest positive finite radius of the packing (0 when there is none): the length unit r_min
/// of every relative overlap.
template <int D>
double smallest_radius(const Packing<D>& packing);

}  // namespace fp
