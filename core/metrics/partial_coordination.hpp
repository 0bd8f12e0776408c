#pragma once
// Partial coordination number z(xi), paper 000 Sect. 3.2 (after Eq. 16): the mean number of
// contacts per particle among the particles of radius r >= r_min + xi (r_max - r_min), xi in
// [0, 1], once the smaller ones are taken off (contacts with a removed particle no longer count).
// z(0) is the coordination number z of Eq. 15. r_min and r_max are those of the packing.
#include <cstdint>
#include <vector>

#include "core/metrics/contacts.hpp"

namespace fp {

struct PartialCoordination {
  std::vector<double> xi;                  ///< equispaced in [0, 1]
  std::vector<double> radius;              ///< threshold r_min + xi (r_max - r_min)
  std::vector<std::uint64_t> particles;    ///< with r >= threshold
  std::vector<std::uint64_t> contacts;     ///< between two such particles
  std::vector<double> z;                   ///< 2 contacts / particles (0 when no particle is left)
};

/// z(xi) at `points` (>= 2) equispaced xi. Radii that are not finite and positive are ignored
/// (and their contacts). O((N + Nc) log N). Throws std::invalid_argument for points < 2.
PartialCoordination partial_coordination(const std::vector<double>& radii, const std::vector<PairContact>& contacts,
                                         int points = 21);

}  // namespace fp
