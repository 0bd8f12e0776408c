#pragma once
// Least-squares densification (paper 001, Labra, Onate and Escolano): a given packing improved
// towards contact. Its neighbours are the edges of the Delaunay triangulation of the centres
// (CGAL; the paper's finite element mesh), and the centres (with LeastSquaresRadii::Range, the
// radii too, each within the law's [r_min, r_max]) minimise Eq. 4:
//   F = sum over edges ij of d_ij^2 + sum over boundary pairs ik of R_ik^2,
//   d_ij = |x_i - x_j|^2 - (r_i + r_j)^2 (Eq. 1),  R_ik = |d_i|^2 - r_i^2 (Eq. 3),
// d_i joining the centre to its nearest point of wall k, for the particles within their radius
// of a wall (the paper's "external particles"). Two departures, both said: each d_ij is divided
// by (r_i + r_j)^2 and each R_ik by (2 r_i)^2 of the packing given (so a pair of small particles
// weighs as much as a pair of large ones; the paper's mesh had one size), and R_ik is signed
// (|d_i| |d_i| with the sign of the side), so a particle past a wall is drawn back, not out.
// The minimiser is NLopt's L-BFGS (bounds for the radii), in a frame centred on the packing and
// scaled by its mean radius, so that far-off and tiny scenes keep their digits.
//
// The least-squares optimum has overlaps (it weighs a gap and an overlap alike). They are then
// removed without losing a particle:
//  1. rounds of Eq. 4 plus a penalty on the overlaps squared (pairs and walls, one-sided), its
//     weight ten times larger each round, until the largest overlap is below half the stage's
//     tolerance (or the rounds run out): the pairs Eq. 4 draws together end in contact;
//  2. what is left comes off the radii: each pair gives up its overlap from both radii in
//     proportion to what each can give above its floor (Range: the law's r_min; Fixed: its own
//     radius less kClipAllowance of it, never below r_min), each ball past a wall shrinks to it;
//  3. sweeps of projections (radii held): each pair still overlapping is moved apart until it
//     touches, the smaller ball moving more, each ball past a wall moved back to it;
//  4. (Range) each ball in turn grows into the room left around it, up to r_max, until it
//     touches a neighbour or a wall (not in the paper: it closes the gaps Eq. 4 left);
//  5. if an overlap is still there (a floor was met), the move is taken back along the straight
//     path to the packing given, by bisection of the share t kept (t = 0 is the packing given,
//     which was valid): the largest t found whose packing is valid is kept.
// With Range, a result with less solid than the packing given is not kept (less_dense).
// Nothing is removed, and the packing returned has no overlap beyond the contact tolerance and
// every ball inside (as the one given had).
#include <cstddef>
#include <cstdint>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/io/scene.hpp"

namespace fp {

/// Step 2's largest radius change in Fixed mode, relative to the radius.
inline constexpr double kClipAllowance = 1e-4;

struct LeastSquaresReport {
  std::size_t particles = 0;
  std::size_t edges = 0;             ///< Delaunay edges in Eq. 4 (after LeastSquaresOptions::edge_gap)
  std::size_t boundary_terms = 0;    ///< particle-wall pairs in Eq. 4
  double objective_before = 0.0;     ///< Eq. 4 (normalised) on the packing given
  double objective_after = 0.0;      ///< at the least-squares optimum
  int evaluations = 0;               ///< of Eq. 4 and its gradient
  double solid_before = 0.0;         ///< sum of the sphere volumes (2D: areas) given
  double solid_solved = 0.0;         ///< at the least-squares optimum (before the overlaps are removed)
  double solid_after = 0.0;          ///< returned
  std::size_t overlaps_solved = 0;   ///< pairs overlapping beyond the tolerance at the optimum
  double max_overlap_solved = 0.0;   ///< the largest of them, relative to the smaller radius
  int relax_rounds = 0;              ///< step 1's rounds
  int relax_evaluations = 0;         ///< step 1's evaluations, in all
  double max_overlap_relaxed = 0.0;  ///< after step 1, relative to the smaller radius (or the radius, walls)
  int sweeps = 0;                    ///< step 3's sweeps
  std::size_t swelled = 0;           ///< step 4 (Range): radii grown into the room left
  std::size_t radii_clipped = 0;     ///< step 2: radii reduced
  double max_clip = 0.0;             ///< step 2: the largest reduction, relative to the radius
  double kept_share = 1.0;           ///< step 5: t
  bool less_dense = false;           ///< Range: the result had less solid than the packing given, which is returned (1: the whole move kept; 0: the packing given)
  double mean_radius_change = 0.0;   ///< mean of |r_after - r_given| / r_given
  double max_radius_change = 0.0;    ///< largest of them
  std::size_t radii_grown = 0;       ///< radii above their given value
  double mean_move = 0.0;            ///< mean centre displacement, relative to the radius given
  double max_move = 0.0;             ///< largest
  double seconds = 0.0;              ///< the whole stage
  double triangulation_seconds = 0.0;
  double solve_seconds = 0.0;        ///< the least-squares minimisation
};

/// Densifies `packing` (centres in `container`'s local frame; every ball inside, no overlap
/// beyond `contact_tolerance` times the smaller radius) in place; with Range, radii in
/// [r_min, r_max] (a given radius outside it widens its own bounds to itself). Deterministic.
template <int D>
LeastSquaresReport densify_least_squares(Packing<D>& packing, const Container<D>& container, double r_min,
                                         double r_max, const LeastSquaresOptions& options, double contact_tolerance);

}  // namespace fp
