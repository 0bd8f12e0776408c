#pragma once
// Contact solver by Newton's method alone on the contact equations ω_i(x) = 0 (paper 004, Eq. 3:
// the zero of the potential Σω_i² that the minimisation solver reaches with NLopt, here without
// the minimiser). From each equivalent-sphere position (contact/gap_newton.hpp) it takes Newton
// steps with the narrow phase's exact gaps and normals, each kept only if it reduces the largest
// |ω_i|. Registered for every pair of kinds and every wall, below the closed-form solvers (which
// take precedence where they cover a problem: contact/solver_registry.hpp): its home is the pairs
// whose gap is analytic and continuously differentiable in the mobile's position outside deep
// overlap, 3D capsules with capsules, spheres and smooth walls (paper 004 Eq. 5-6, segment
// distance); elsewhere (polyhedra with spheres, capsules or curved walls, cylinders, mixes) the
// narrow phase's gap is piecewise smooth and a start that stalls on a kink gives nothing, where
// minimisation spent milliseconds on the same gaps. A position is kept when every
// |ω_i| <= 1e-3 x gap_tolerance x the smaller circumscribed radius (the minimisation solver's
// polish target); a start that does not get there gives nothing, so a position may be missed,
// never returned wrong. Where minimisation runs SLSQP twice per solve (~26 gap vectors), this evaluates ~9:
// 3D capsules pack 3.7x faster at the same density (experiments/one-front/RESULTS.md).
#include <span>

#include "contact/contact_solver.hpp"
#include "contact/narrow_phase.hpp"

namespace fp {

template <int D>
class GapNewtonSolver final : public ContactSolver<D> {
 public:
  /// Newton steps per start (a converging start needs 3-6; a stalled one stops at its first
  /// step without gain).
  static constexpr int kIterations = 16;
  /// With a needle among the bodies: halvings of a step that does not reduce the largest |ω_i|
  /// before the start is given up (elsewhere none).
  static constexpr int kHalvings = 3;
  /// A position is kept when every |ω_i| <= kAcceptance x gap_tolerance x the smaller size:
  /// polished to 1e-9 of the size at the default tolerance (Newton's quadratic convergence gets
  /// there from a solution's basin; a start that stalls above it gives nothing).
  static constexpr double kAcceptance = 1e-3;
  /// A shape with inscribed radius below this fraction of its circumscribed radius is a needle.
  static constexpr double kElongated = 0.25;

  GapNewtonSolver(const NarrowPhase<D>& narrow_phase, double gap_tolerance);

  /// Every fixed body and the mobile must have gaps in the narrow phase (a body or mobile
  /// without a shape is a sphere of its radius). Returns up to out.size() distinct positions.
  int solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile, std::span<Placement<D>> out) const override;

 private:
  const NarrowPhase<D>& np_;
  double tol_;
};

}  // namespace fp
