#pragma once
// Graded large-first stacking (paper 003, Sect. 2, steps (1)-(11)): a list of particles made
// from the gradation and the target void ratio (their solid is (1 - n) of the container), placed
// largest first, each at the first position that overlaps nothing, tried in the paper's order:
//   (5) completely random positions in the container;
//   (6) random positions near a nucleus (a placed ball): at r_b + r (1 + U) from its centre, Eq. 2;
//   (7) random positions touching a nucleus and one neighbour (Eqs. 3-4: a random point of the
//       curve of such positions);
//   (8) positions touching a nucleus and two neighbours (Eq. 5; walls are bodies too, so the layer
//       against the container is closed), 3D only: in 2D two contacts fix the position already,
//       (10), and they are this step.
// "The sequence ... random, contact random, double contact random, three contact ... highlights
// the nature of random generation, otherwise some balls are excessively clustered" (9).
//   (11) reshape: when a particle finds no place, the loose particles (placed by (5)-(7), fewer
// contacts than the dimension's) are moved, each to the position touching three of its
// neighbours nearest to where it is ("only relying on pure geometric properties"), which packs
// them and opens room; the particle is then tried again.
// Differences from the paper, each for speed and said here: nuclei for (8) are drawn among the
// balls still open (one whose every pair failed for a radius is closed until the radii are 10 %
// smaller); the neighbour search is frontpack's grid (core/geometry/neighbour_grid.hpp)
// rather than the paper's grid of cells with its ratio `gid`.
#include <cstdint>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/sampling/radius_distribution.hpp"
#include "core/sampling/rng.hpp"

namespace fp {

struct StackingOptions {
  int random_tries = 4;        ///< (5) completely random positions per particle
  int near_tries = 2;          ///< (6) random positions near a nucleus
  int two_contact_tries = 4;   ///< (7) random positions touching a nucleus and a neighbour
  /// (8) open nuclei tried per particle at most. Default: every one. A nucleus that fails is
  /// closed until the radii are 10 % smaller, so the scan is amortised (each ball fails at most
  /// once per such step); with 32 a particle was left out while open nuclei had room (3D R = 2,
  /// 323,955 spheres: 36 to the voids, 12.5 s; every one: none, 8.8 s).
  int nuclei = 1000000;
  int pairs_per_nucleus = 64;  ///< (8) pairs of bodies that can both touch, tried around one nucleus, nearest first
  int reshapes = 8;            ///< (11) reshape passes at most over the run (0: none)
  /// Try (8) first, then (7), (6), (5): growth in contact from random nuclei everywhere rather
  /// than random positions first (measured denser; not the paper's order).
  bool contacts_first = false;
  /// With contacts_first: the particles making the first `random_share` of the list's solid
  /// (the largest) are placed in the paper's order, spread over the container as nuclei, the
  /// rest contacts first (0: contacts first from the start, whose growth from one nucleus can
  /// use the list up before it reaches every part of the container).
  double random_share = 0.0;
};

struct StackingReport {
  std::uint64_t asked = 0, placed = 0, unplaced = 0;
  std::uint64_t by_random = 0, by_near = 0, by_two_contact = 0, by_three_contact = 0;
  std::uint64_t reshape_passes = 0, reshape_moves = 0;
  double solid_asked = 0.0, solid_placed = 0.0;  ///< measures
  double seconds = 0.0;
  std::vector<double> left_out;  ///< the radii without a place, largest first
  std::uint64_t by_voids = 0;    ///< (12) of them placed afterwards into the voids (cli/sphere_pack.cpp)
};

/// Places `radii` (any order: sorted largest first here) in `container`; the placed spheres are
/// appended to `out` (in the container's frame), in the order placed. `tol`: the contact
/// tolerance (relative to the smaller radius) of every overlap and containment test.
template <int D>
StackingReport stack_graded(const Container<D>& container, std::vector<double> radii, const StackingOptions& options,
                            std::uint64_t seed, double tol, Packing<D>& out);

/// The particle list of a target: radii drawn from `law` until their measure reaches `measure`
/// (the last one kept only if it brings the sum closer), largest first.
template <int D>
std::vector<double> radii_for_measure(const RadiusDistribution& law, double measure, Rng& rng);

}  // namespace fp
