#pragma once
// Wrapper-intersection solver for particles made of balls: spheres and clusters of spheres (3D),
// disks and clusters of disks (2D), against each other and the container walls. Paper 004,
// Sect. 3.1 ("clusters of circles", "clusters of spheres"): the wrapper of a fixed body B for the
// mobile particle A at its fixed orientation is the locus of A's reference point x where A
// touches B from outside, the boundary of B (+) (-A). For balls it is a union of spheres: member
// k of B (centre c_k, radius r_k) and member j of A (offset m_j = R a_j from x, radius r_j) touch
// where |x + m_j - c_k| = r_j + r_k, a sphere of centre c_k - m_j. A wall's locus for member j is
// the wall's own centre locus for a ball of radius r_j, shifted by -m_j.
//
// A position touching D bodies is on one such sphere (or wall locus) of each body: every choice
// of one (fixed member or wall, mobile member) per body is solved in closed form, folded to a
// common mobile radius. The paper's O(n1 n2 n3 m^3) enumeration is pruned by the spheres' own
// geometry: a sphere inside another of the same body carries no boundary, and a choice whose
// spheres cannot meet pairwise is skipped before any solve. In 3D, with two particle bodies, the
// circles where a sphere of one meets a sphere of the other are built once per (particle,
// particle, mobile) and cut down to their exposed arcs (outside every other sphere of the two
// bodies; most circles of overlapping members have none); a third body's sphere or plane then
// meets a circle where a cos t + b sin t = c. Near-degenerate choices (tiny circles, a plane
// nearly parallel to the circle's, near tangency) and curved walls go to the analytic sphere
// solver (contact/sphere_contact_solver.hpp: radical planes, then a quadratic, verified). A candidate is kept only if, against
// every member of every fixed body, the mobile members overlap by at most kOverlapTol times the
// smaller radius (and it touches each body: that is how it was built, verified by the solver to
// 1e-10). Exact up to rounding, no iterations beyond the sphere solver's verification.
#include <span>

#include "contact/contact_solver.hpp"

namespace fp {

template <int D>
class BallWrapperSolver final : public ContactSolver<D> {
 public:
  /// A kept position overlaps no member of a fixed body by more than this fraction of the
  /// smaller radius of the two balls.
  static constexpr double kOverlapTol = 1e-9;

  /// Every fixed body is a wall, a sphere or a cluster, and so is the mobile (by its shape's kind;
  /// a mobile without a shape is a ball of its radius). Returns up to out.size() distinct positions.
  int solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile, std::span<Placement<D>> out) const override;
  BallWrapperSolver() = default;
  ~BallWrapperSolver() override;
  BallWrapperSolver(const BallWrapperSolver&) = delete;
  BallWrapperSolver& operator=(const BallWrapperSolver&) = delete;
  /// 3D: spheres and clusters among them also cut the pair circles of two particle bodies, so a
  /// third body is tried only where the mobile would overlap no obstacle beyond `tol`.
  void set_obstacles(std::span<const Particle<D>* const> obstacles, double tol) const override;
};

}  // namespace fp
