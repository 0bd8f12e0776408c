#pragma once
// What a packer run returns: the particles and the counters that explain where time went.
#include <cstdint>
#include <functional>
#include <string>

#include "core/geometry/packing.hpp"

namespace fp {

enum class StopReason { FrontExhausted, ParticleCount, VolumeFraction, TimeLimit };
const char* to_string(StopReason r);

struct FrontCounters {
  std::uint64_t front_picks = 0;          ///< s0 selections (step 2.1)
  std::uint64_t front_removals = 0;       ///< s0 removed from F (step 2.3)
  std::uint64_t pairs_considered = 0;     ///< (si, sj) pairs enumerated
  std::uint64_t pairs_pruned = 0;         ///< pairs too far apart to touch one new particle
  std::uint64_t solves = 0;               ///< contact-solver calls
  std::uint64_t candidates = 0;           ///< positions returned by the solver
  std::uint64_t rejected_container = 0;   ///< candidates not inside the container
  std::uint64_t rejected_overlap = 0;     ///< candidates overlapping a neighbour
  std::uint64_t wall_bodies = 0;          ///< walls offered to the solver as bodies
  std::uint64_t radii_drawn = 0;          ///< radii drawn from the distribution
  std::uint64_t radii_unplaced = 0;       ///< radii drawn but never placed (the pool at the end)
  std::uint64_t max_neighbours = 0;       ///< largest |V| seen (bounded by r_max/r_min, paper 002 Sect. 6)
  std::uint64_t voids_reopened = 0;       ///< voids found after F ran empty, growth resumed from their surroundings
  std::uint64_t voids_seeded = 0;         ///< voids found after F ran empty and given a new seed particle
  std::uint64_t two_contact_placements = 0;  ///< 3D: particles placed touching only s0 and one body (no pair had a position)
  std::uint64_t contact_bodies_capped = 0;   ///< pair scans limited to the nearest contact bodies (a V of thousands)
};

template <int D>
struct PackResult {
  Packing<D> packing;
  StopReason stop = StopReason::FrontExhausted;
  FrontCounters counters;
  double seconds = 0.0;          ///< packing time (excludes I/O)
  double solid_measure = 0.0;    ///< sum of particle volumes (areas)
  std::size_t grid_bytes = 0;
  int grid_levels = 0;
};

/// Progress report for long runs: particles so far, elapsed seconds, volume fraction so far.
using ProgressFn = std::function<void(std::uint64_t n, double seconds, double volume_fraction)>;

}  // namespace fp
