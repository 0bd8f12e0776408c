#pragma once
// The central interface of design.md: given D fixed bodies (particles or walls) and a mobile
// particle of known shape and orientation, return the positions where the mobile particle
// touches all of them from outside (inside for a concave wall) without overlapping them.
// The front manager calls solvers only through this contract; the sphere solver is also
// usable as a concrete (final) type so the sphere fast path is resolved at compile time.
#include <span>

#include "contact/body.hpp"

namespace fp {

template <int D>
class ContactSolver {
 public:
  /// Most solutions the analytic sphere solver returns for one call (circle-cylinder
  /// intersections give 4); the buffer the sphere front passes.
  static constexpr int kMaxSolutions = 4;
  /// The buffer the general front passes: a wrapper of non-convex particles (clusters) can have
  /// more than 4 solutions.
  static constexpr int kMaxCandidates = 16;
  virtual ~ContactSolver() = default;
  /// `fixed` holds exactly D bodies; writes up to out.size() placements into `out` and returns
  /// how many. Never returns a position it has not solved for: degenerate configurations
  /// return 0.
  virtual int solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile,
                    std::span<Placement<D>> out) const = 0;
  /// The other particles of the placement the next solves serve (the front's V): a position
  /// overlapping one of them by more than tol x the smaller circumscribed radius is rejected by
  /// the front anyway, so a solver may leave it out, and search only where they leave room. A
  /// solver that ignores this loses nothing. The pointers stay valid until the next call.
  virtual void set_obstacles(std::span<const Particle<D>* const> obstacles, double tol) const {
    (void)obstacles;
    (void)tol;
  }
};

}  // namespace fp
