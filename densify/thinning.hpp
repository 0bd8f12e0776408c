#pragma once
// Thinning: a packing brought down to a target solid fraction, the same everywhere (the scene's
// `target:`). A packer that stops growing at phi0 leaves a dense part and an empty one (the
// valera-cube at 0.45: slabs from 0.29 at the walls to 0.56 in the middle); packing to the
// packer's own density and then removing particles spread over the whole container gives every
// part the target. What is removed is chosen so that:
//  * the size law is kept: the particles are split into classes of equal count by size and each
//    class owes the same share of its own measure (1 - target / solid), so the proportions stay
//    those of the packing (measured: the radii test's p stays at the packing's);
//  * the contacts are kept where they can be: a removal must leave every neighbour with at least
//    min(level, the contacts it had) contacts (walls count), at level = D first, then D - 1 ..
//    1, then 0 (any particle; reached only when no removal keeps every neighbour touched);
//  * the place is even: the particles are walked along a space-filling curve (`place`, a Hilbert
//    index of cells of about a diameter) and the share is paid by error diffusion along it: the
//    debt runs up with the measure walked, and once it reaches half of the best candidate among
//    the next few particles (its class the furthest behind, the contact rule allowing) that one
//    goes; so every stretch of the curve, hence every compact region of a few particles and more,
//    loses its share of its solid, and the classes keep pace everywhere. Measured (cells of 8
//    diameters, experiments/target-fraction): sd 0.004-0.007 in 3D, 0.014-0.035 in 2D (65 disks
//    a cell), where random removal leaves a binomial noise (2D: 0.03);
//  * the target is met as closely as a particle allows: a removal is made only while the solid
//    left stays at least half the particle above the target, so it ends within half the
//    largest particle's measure of it.
// Removal never creates an overlap or moves a particle: validity is the packing's own.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/geometry/hilbert_curve.hpp"
#include "core/geometry/vec.hpp"
#include "core/sampling/rng.hpp"

namespace fp {

struct ThinningContact {
  std::uint32_t i, j;
};

struct ThinningReport {
  std::uint64_t before = 0, removed = 0;
  double measure_before = 0.0, measure_after = 0.0;
  /// The contact level of the last removal: every particle left kept at least min(level, its
  /// contacts before) contacts. dimension (nothing needed relaxing) .. 0.
  int level = 0;
  /// Particles that had a contact before and have none after (rattlers made by the thinning).
  std::uint64_t lost_every_contact = 0;
  bool reached = false;  ///< the target is within half a particle (false: even removing freely missed it)
};

struct ThinningInput {
  std::span<const double> measure;          ///< each particle's volume (area)
  std::span<const double> size;             ///< each particle's size (radius), for the classes
  std::span<const ThinningContact> contacts;  ///< particle pairs in contact
  std::span<const std::uint32_t> wall_contacts;  ///< per particle: contacts with the container
  std::span<const std::uint64_t> place;      ///< per particle: its place along the walk (hilbert_key); empty: random
};

/// Which particles to keep (1) so that the kept measure comes to `target_measure`; the report in
/// `report`. Passes at contact levels D .. 0 (each repeated while it removes, up to 8 times), then
/// along the walk whatever brings the solid closer to the target (the classes' rounding). `dimension` (2, 3) sets the first contact level; `classes` the size classes (at
/// most one per 50 particles). Deterministic for a given rng state.
std::vector<char> thin_to_measure(const ThinningInput& input, double target_measure, int dimension, Rng& rng,
                                  ThinningReport& report, int classes = 16);

}  // namespace fp
