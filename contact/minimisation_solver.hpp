#pragma once
// The potential-minimisation contact solver of paper 004 (Pérez Morales et al. 2016, Eq. 4):
// the mobile particle (fixed orientation) touches the D fixed bodies where
//     Σ_i |ω(p_i, p_mob[x])|  (or Σ_i ω_i², the smooth form gradient methods want)
// reaches zero. As in the paper the problem is solved twice, once in each half-space of the
// hyperplane through the fixed centres, from starting points that make the two solutions likely:
// the analytic solutions for equivalent spheres (radius between inscribed and circumscribed).
// ω is the signed gap of contact/narrow_phase.hpp: analytic for spheres and spherocylinders
// (Eq. 5-6 in distance form), FCL (GJK/EPA through libccd) otherwise.
//
// A solution is returned only if every |ω_i| <= gap_tolerance * min(size_i, size_mobile)
// (size = circumscribed radius); "no solution" is reported as 0, never as a wrong position.
// Overlap with the other neighbours is the caller's check (the front's candidate test).
#include <cstdint>
#include <memory>
#include <span>

#include "contact/contact_solver.hpp"
#include "contact/narrow_phase.hpp"
#include "core/io/scene.hpp"

namespace fp {

struct MinimisationStats {
  std::uint64_t solves = 0;          ///< solve() calls
  std::uint64_t minimisations = 0;   ///< NLopt runs (two or more per solve)
  std::uint64_t evaluations = 0;     ///< gap-vector evaluations (objective + polish)
  std::uint64_t accepted = 0;        ///< positions returned
  std::uint64_t rejected_gap = 0;    ///< minima whose gaps stayed above the tolerance
  std::uint64_t no_start = 0;        ///< solves without any starting point
};

template <int D>
class MinimisationSolver final : public ContactSolver<D> {
 public:
  MinimisationSolver(const NarrowPhase<D>& narrow_phase, const MinimisationOptions& options);
  ~MinimisationSolver() override;

  int solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile, std::span<Placement<D>> out) const override;

  const MinimisationStats& stats() const { return stats_; }
  const MinimisationOptions& options() const { return opt_; }

 private:
  struct Impl;
  const NarrowPhase<D>& np_;
  MinimisationOptions opt_;
  std::unique_ptr<Impl> impl_;
  mutable MinimisationStats stats_;
};

/// The algorithm names MinimisationOptions::algorithm accepts.
const char* minimisation_algorithms();

}  // namespace fp
