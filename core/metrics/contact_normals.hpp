#pragma once
// Angular distribution of the contacts through the relative projections of paper 002 Sect. 1
// (after He et al.): for touching particles 1, 2 the projection of the centre-to-centre line on
// axis k divided by r1 + r2. For a contact that distance is r1 + r2 to within the contact
// tolerance, so here it is |n . e_k| with n the unit centre-to-centre vector (exactly in [0, 1]).
// The paper calls a packing isotropic when they are uniform on [0, 1]: that is the law of |n_k|
// for isotropic directions in 3D (Archimedes' hat-box theorem); in 2D the isotropic law is the
// arcsine law P(|n_k| <= t) = (2/pi) asin t, which is used instead.
#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/packing.hpp"
#include "core/metrics/contacts.hpp"
#include "core/metrics/ks_result.hpp"

namespace fp {

struct RelativeProjections {
  int bins = 0;
  std::vector<std::vector<std::uint64_t>> histogram;  ///< per axis, `bins` equal bins on [0, 1]
  std::vector<KsResult> ks;                           ///< per axis, against the isotropic law
  std::string reference;                              ///< the isotropic law, in words
  std::uint64_t contacts = 0;                         ///< contacts with a direction
};

/// CDF of |n . e_k| for isotropic unit vectors n: t in 3D, (2/pi) asin t in 2D (t clamped to [0, 1]).
template <int D>
double isotropic_projection_cdf(double t);

/// O(Nc log Nc). Throws std::invalid_argument unless bins >= 1. Contacts between coincident
/// centres (no direction) are left out.
template <int D>
RelativeProjections relative_projections(const Packing<D>& packing, const std::vector<PairContact>& contacts,
                                         int bins = 20);

/// The same for contact directions given (any length; zero ones left out): a packing of shapes
/// passes its contact normals (contact_network.hpp), for which the centre line is not the normal.
template <int D>
RelativeProjections relative_projections(const std::vector<Vec<D>>& directions, int bins = 20);

}  // namespace fp
