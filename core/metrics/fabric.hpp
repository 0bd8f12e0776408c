#pragma once
// Fabric tensor of the contact network, in its two forms (both have trace 1 and eigenvalues 1/D
// each for an isotropic network):
//  * per contact, paper 000 Eq. 17:          F = (1/Nc) sum_c n_c n_c^T;
//  * per particle averaged, paper 002 Eq. 1: F = (1/N) sum_p (1/M_p) sum_{c of p} n_c n_c^T,
//    M_p the contacts of particle p. Particles without contacts have no term and are not counted
//    in N (0/0 in the paper's formula). Computed as (1/N) sum_c (1/M_i + 1/M_j) n_c n_c^T.
// n_c is the unit vector between the two centres (its sign does not matter), or for shapes the
// contact normal. Particle-particle
// contacts only: walls are not in the network.
#include <cstdint>
#include <vector>

#include "core/geometry/packing.hpp"
#include "core/metrics/contacts.hpp"

namespace fp {

struct FabricTensor {
  std::vector<double> tensor;       ///< D x D, row-major (zeros without contacts)
  std::vector<double> eigenvalues;  ///< ascending
  std::uint64_t count = 0;          ///< contacts (per contact) or particles with a contact (per particle)
};

struct Fabric {
  FabricTensor per_contact;   ///< paper 000 Eq. 17
  FabricTensor per_particle;  ///< paper 002 Eq. 1
};

/// Both forms for the contacts of find_pair_contacts. O(Nc + N). Contacts between coincident
/// centres (no direction) are left out.
template <int D>
Fabric fabric_tensors(const Packing<D>& packing, const std::vector<PairContact>& contacts);

/// Both forms with the contact directions given, one per contact (any length; zero ones left
/// out): a packing of shapes passes its contact normals (contact_network.hpp).
template <int D>
Fabric fabric_tensors(std::size_t particles, const std::vector<PairContact>& contacts,
                      const std::vector<Vec<D>>& directions);

/// Per-contact form of a set of directions (normalised here; zero vectors are left out).
template <int D>
FabricTensor fabric_of_directions(const std::vector<Vec<D>>& directions);

}  // namespace fp
