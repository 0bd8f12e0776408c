#pragma once
// The contact network of any packing as the validator finds it (validate_particles.hpp): the
// pairs in contact with their contact normals, and the particles touching the container. The
// touching rule is the one of contacts.hpp (gap <= tol x the smaller length unit; overlapping
// pairs count too). For spheres the normal is the centre line; for shapes it is the narrow
// phase's contact normal, which is not the centre line. The metrics of the contact network
// (contact_stats.hpp, fabric.hpp, contact_normals.hpp, partial_coordination.hpp) take it as is.
#include <vector>

#include "core/geometry/vec.hpp"
#include "core/metrics/contacts.hpp"

namespace fp {

template <int D>
struct ContactNetwork {
  std::vector<PairContact> pairs;  ///< i < j, gap absolute, sorted by (i, j)
  std::vector<Vec<D>> normals;     ///< per pair: unit, from i towards j (zero when undefined)
  std::vector<WallContact> walls;  ///< one per particle at most, sorted by i; gap = -protrusion
};

}  // namespace fp
