#pragma once
// The contact network of any packing as the validator finds it (validate_particles.hpp): the
// pairs in contact with their contact normals, and the particles touching the container. The
// touching rule is the one of contacts.hpp (gap <= tol x the smaller length unit; overlapping
// pairs count too). For spheres the normal is the centre line; for shapes it is the narrow
// phase's contact normal, which is not the centre line. The metrics of the contact network
// (contact_stats.hpp, fabric.hpp, contact_normals.hpp, partial_coordination.hpp) take it as is.
#include <cstddef>
#include <utility>
#include <vector>

#include "core/geometry/vec.hpp"
#include "core/metrics/contacts.hpp"

namespace fp {

template <int D>
struct ContactNetwork {
  std::vector<PairContact> pairs;  ///< i < j, gap absolute, sorted by (i, j)
  /// Per pair: unit, from i towards j (zero when undefined); empty for spheres, whose normals
  /// are their centre lines.
  std::vector<Vec<D>> normals;
  std::vector<WallContact> walls;  ///< one per particle at most, sorted by i; gap = -protrusion
};

/// Sorts the pairs of a network by (i, j), their normals (if any) with them, in O(pairs +
/// particle_count): a counting sort on i, then an insertion sort of each particle's few partners.
template <int D>
void sort_by_pair(ContactNetwork<D>& net, std::size_t particle_count) {
  const bool normals = !net.normals.empty();
  std::vector<std::size_t> start(particle_count + 1, 0);
  for (const PairContact& c : net.pairs) ++start[c.i + 1];
  for (std::size_t k = 0; k < particle_count; ++k) start[k + 1] += start[k];
  std::vector<PairContact> pairs(net.pairs.size());
  std::vector<Vec<D>> along(normals ? net.pairs.size() : 0);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t q = 0; q < net.pairs.size(); ++q) {
      const std::size_t at = fill[net.pairs[q].i]++;
      pairs[at] = net.pairs[q];
      if (normals) along[at] = net.normals[q];
    }
  }
  std::vector<PairContact>().swap(net.pairs);
  std::vector<Vec<D>>().swap(net.normals);
  for (std::size_t k = 0; k < particle_count; ++k)
    for (std::size_t a = start[k]; a < start[k + 1]; ++a)
      for (std::size_t b = a; b > start[k] && pairs[b - 1].j > pairs[b].j; --b) {
        std::swap(pairs[b - 1], pairs[b]);
        if (normals) std::swap(along[b - 1], along[b]);
      }
  net.pairs = std::move(pairs);
  net.normals = std::move(along);
}

}  // namespace fp
