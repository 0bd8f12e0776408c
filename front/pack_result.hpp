#pragma once
// What a packer run returns: the particles and the counters that explain where time went.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/geometry/packing.hpp"

namespace fp {

enum class StopReason { FrontExhausted, ParticleCount, VolumeFraction, TimeLimit };
const char* to_string(StopReason r);

struct FrontCounters {
  std::uint64_t front_picks = 0;          ///< s0 selections (step 2.1)
  std::uint64_t front_removals = 0;       ///< s0 removed from F (step 2.3)
  std::uint64_t pairs_considered = 0;     ///< (si, sj) pairs enumerated
  std::uint64_t pairs_pruned = 0;         ///< pairs too far apart to touch one new particle
  std::uint64_t solves = 0;               ///< contact-solver calls (the roll's too)
  std::uint64_t candidates = 0;           ///< positions returned by the solver
  std::uint64_t rejected_container = 0;   ///< candidates not inside the container
  std::uint64_t rejected_overlap = 0;     ///< candidates overlapping a neighbour
  std::uint64_t rejected_off_face = 0;    ///< candidates tangent to a wall's plane beyond its face (mesh facet, polygon edge)
  std::uint64_t rejected_block = 0;       ///< candidates outside their block (threads: front/block_front.hpp)
  std::uint64_t wall_bodies = 0;          ///< walls offered to the solver as bodies
  std::uint64_t radii_drawn = 0;          ///< radii drawn from the distribution
  std::uint64_t radii_unplaced = 0;       ///< radii drawn but never placed (the pool at the end)
  std::uint64_t radii_waited = 0;         ///< drafts set aside as waiting (no room at many s0 in a row)
  std::uint64_t radii_never_fit = 0;      ///< of radii_unplaced: waiting drafts that never found room
  std::uint64_t radii_dropped = 0;        ///< waiting drafts dropped onto the front (one contact)
  std::uint64_t radii_placed_ahead = 0;   ///< a rare large class: placed ahead of the front
  std::uint64_t radii_drawn_ahead = 0;    ///< of those, drawn before their turn (the law's next large draft skipped)
  std::uint64_t radii_on_skeleton = 0;    ///< fines put on a skeleton of the large class packed first
  std::uint64_t max_neighbours = 0;       ///< largest |V| seen (bounded by r_max/r_min, paper 002 Sect. 6)
  std::uint64_t voids_reopened = 0;       ///< voids found after F ran empty, growth resumed from their surroundings
  std::uint64_t voids_seeded = 0;         ///< voids found after F ran empty and given a new seed particle
  std::uint64_t two_contact_placements = 0;  ///< 3D: particles placed touching only s0 and one body (no pair had a position)
  std::uint64_t contact_bodies_capped = 0;   ///< pair scans limited to the nearest contact bodies (a V of thousands)
  std::uint64_t blocks = 0;               ///< threads: blocks the container was cut into (0: one front)
  std::uint64_t trimmed = 0;              ///< threads: particles placed, then dropped to honour a count or fraction stop
  std::uint64_t orientation_draws = 0;    ///< shapes: orientations drawn beyond the first (orientation_trials)
  std::uint64_t reframe_misses = 0;       ///< shapes, radial frame: placements left in s0's frame (no room in their own)
  std::uint64_t pocket_draws = 0;         ///< shapes: orientations drawn by the pocket trials
  std::uint64_t pocket_kept = 0;          ///< shapes: pocket trials kept (closer to the seed point)
  std::uint64_t roll_turns = 0;           ///< shapes: turns the roll tried
  std::uint64_t roll_kept = 0;            ///< shapes: turns the roll kept

  /// Every counter with its name in the run record, in the record's order (adding, sending and
  /// listing them all alike).
  struct Field {
    const char* name;
    std::uint64_t FrontCounters::*member;
  };
  static constexpr Field kFields[] = {
      {"front_picks", &FrontCounters::front_picks},
      {"front_removals", &FrontCounters::front_removals},
      {"pairs_considered", &FrontCounters::pairs_considered},
      {"pairs_pruned", &FrontCounters::pairs_pruned},
      {"solves", &FrontCounters::solves},
      {"candidates", &FrontCounters::candidates},
      {"rejected_overlap", &FrontCounters::rejected_overlap},
      {"rejected_container", &FrontCounters::rejected_container},
      {"rejected_off_face", &FrontCounters::rejected_off_face},
      {"rejected_block", &FrontCounters::rejected_block},
      {"wall_bodies", &FrontCounters::wall_bodies},
      {"radii_drawn", &FrontCounters::radii_drawn},
      {"radii_unplaced", &FrontCounters::radii_unplaced},
      {"radii_waited", &FrontCounters::radii_waited},
      {"radii_never_fit", &FrontCounters::radii_never_fit},
      {"radii_dropped", &FrontCounters::radii_dropped},
      {"radii_placed_ahead", &FrontCounters::radii_placed_ahead},
      {"radii_drawn_ahead", &FrontCounters::radii_drawn_ahead},
      {"radii_on_skeleton", &FrontCounters::radii_on_skeleton},
      {"max_neighbours", &FrontCounters::max_neighbours},
      {"voids_reopened", &FrontCounters::voids_reopened},
      {"voids_seeded", &FrontCounters::voids_seeded},
      {"two_contact_placements", &FrontCounters::two_contact_placements},
      {"contact_bodies_capped", &FrontCounters::contact_bodies_capped},
      {"blocks", &FrontCounters::blocks},
      {"trimmed", &FrontCounters::trimmed},
      {"orientation_draws", &FrontCounters::orientation_draws},
      {"reframe_misses", &FrontCounters::reframe_misses},
      {"pocket_draws", &FrontCounters::pocket_draws},
      {"pocket_kept", &FrontCounters::pocket_kept},
      {"roll_turns", &FrontCounters::roll_turns},
      {"roll_kept", &FrontCounters::roll_kept}};

  /// The counters of two fronts run side by side (the blocks of front/block_front.hpp); the
  /// largest |V| is the larger one.
  FrontCounters& operator+=(const FrontCounters& o) {
    for (const Field& f : kFields) this->*f.member += o.*f.member;
    max_neighbours = std::max(max_neighbours - o.max_neighbours, o.max_neighbours);
    return *this;
  }
};

/// Where the contact solves of non-spherical particles went (all zero for spheres, whose analytic
/// solver is inlined in the front and counted by FrontCounters::solves alone).
struct SolverCounters {
  std::uint64_t analytic_solves = 0;       ///< solves the registry sent to any solver but minimisation (wrappers, spheres, gap Newton)
  std::uint64_t minimisation_solves = 0;   ///< solves sent to the minimisation solver
  std::uint64_t minimisations = 0;         ///< NLopt runs (two or more per minimisation solve)
  std::uint64_t gap_evaluations = 0;       ///< gap-vector evaluations by the minimisation solver
  std::uint64_t minima_rejected = 0;       ///< minima whose gaps stayed above the tolerance
  std::uint64_t fcl_queries = 0;           ///< FCL distance queries of the narrow phase

  SolverCounters& operator+=(const SolverCounters& o) {
    analytic_solves += o.analytic_solves;
    minimisation_solves += o.minimisation_solves;
    minimisations += o.minimisations;
    gap_evaluations += o.gap_evaluations;
    minima_rejected += o.minima_rejected;
    fcl_queries += o.fcl_queries;
    return *this;
  }
};

/// The work of one MPI rank of a packing grown by several (front/block_front.hpp): what the plan
/// for many ranks is measured from (experiments/scale).
struct RankWork {
  std::uint64_t blocks = 0;          ///< blocks it grew
  std::uint64_t particles = 0;       ///< particles they hold (before a stop's trimming)
  std::uint64_t fixed = 0;           ///< particles of earlier neighbours its blocks grew against
  std::uint64_t doubles_sent = 0;    ///< block data sent to other ranks (8 bytes each)
  double grow_seconds = 0.0;         ///< growing its blocks
  double wait_seconds = 0.0;         ///< waiting for other ranks' blocks
};

/// What one run of the front returns, for spheres (`Particles` = Packing<D>, SoA) and for
/// shapes (ShapePacking<D>, front/shape_front.hpp) alike.
template <int D, class Particles = Packing<D>>
struct PackResult {
  Particles packing;
  StopReason stop = StopReason::FrontExhausted;
  FrontCounters counters;
  SolverCounters solver;
  double seconds = 0.0;             ///< packing time (excludes I/O)
  double solid_measure = 0.0;       ///< sum of particle volumes (areas)
  double contact_tolerance = 0.0;   ///< contact / overlap allowance, relative to the smaller (circumscribed) radius
  std::size_t grid_bytes = 0;
  int grid_levels = 0;
  std::vector<RankWork> ranks;      ///< per MPI rank, when several grew it (empty otherwise)
  /// The (circumscribed) radii of the drafts that waited and never found room (counted by
  /// counters.radii_never_fit; across MPI ranks only rank 0's are listed).
  std::vector<double> never_fit_radii;
};

/// Progress report for long runs: particles so far, elapsed seconds, volume fraction so far.
using ProgressFn = std::function<void(std::uint64_t n, double seconds, double volume_fraction)>;

}  // namespace fp
