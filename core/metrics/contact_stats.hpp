#pragma once
// Coordination summary of a packing: what the packer prints and the run record stores.
// Contacts follow the touching rule of contacts.hpp (gap <= tol * min(ri, rj)).
#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/metrics/contacts.hpp"

namespace fp {

struct ContactStats {
  double tolerance = 0.0;                    ///< rel_tol used for every contact
  std::uint64_t particles = 0;
  double mean_coordination = 0.0;            ///< 2 * contacts / particles (particle-particle only)
  double mean_coordination_with_walls = 0.0; ///< (2 * contacts + wall_contacts) / particles
  std::vector<std::uint64_t> histogram;      ///< histogram[z]: particles with z particle-particle contacts
  std::uint64_t contacts = 0;                ///< particle-particle contacts
  std::uint64_t wall_contacts = 0;           ///< balls touching the container (0 without a container)
  std::uint64_t rattlers = 0;                ///< balls with z (walls included) < 3 in 3D, < 2 in 2D (paper convention)
  double max_overlap_rel = 0.0;              ///< max over pairs of (ri + rj - d) / r_min, 0 if no pair overlaps
  std::int64_t worst_i = -1, worst_j = -1;   ///< the pair of max_overlap_rel, -1 if none

  /// e.g. "z = 5.832 (5.901 with walls), 291600 contacts, 1204 wall contacts, 312 rattlers,
  /// max overlap 0 r_min, tol 1e-09".
  std::string summary() const;
};

/// Contacts of every ball (container may be null: no wall contacts). Throws
/// std::invalid_argument unless rel_tol >= 0. Balls with a non-finite centre or radius are ignored.
template <int D>
ContactStats contact_stats(const Packing<D>& packing, const Container<D>* container_or_null, double rel_tol = 1e-9);

/// The same figures from contact lists found elsewhere (contact_network.hpp: a packing of
/// shapes): `walls` null means no container; overlaps are relative to `r_unit` (r_min).
ContactStats contact_stats_of(int dimension, std::size_t particles, const std::vector<PairContact>& pairs,
                              const std::vector<WallContact>* walls, double r_unit, double rel_tol);

}  // namespace fp
