#pragma once
// Contact solver for ellipsoids (3D) and ellipses (2D), mobile or fixed, with spheres (disks) and
// plane walls, by Newton's method on the wrappers (paper 004 Sect. 3.1: the wrapper of a fixed
// body F for the mobile A is the boundary of F (+) (-A), the locus of A's centre where A touches
// F from outside).
//
// For smooth convex bodies {c + M u + rho w : |u|, |w| <= 1} the wrapper's support function is
//   h(n) = c.n + |M_F^T n| + |M_A^T n| + rho_F + rho_A,
// and its boundary point of outward normal n is the gradient P(n) = grad h(n), explicit in n.
// A plane wall's wrapper is the offset plane w.x = w.p + |M_A^T w| + rho_A. A position touching
// the D bodies is x with x = P_i(n_i) for every curved body and the offset-plane equation for
// every wall: D + (D-1)k unknowns (x and k unit normals) for as many equations. Newton's method
// solves them (Jacobian: the Hessians of the h_i on the normals' tangent planes), started from
// the positions of the problem's equivalent spheres (circumscribed and volume-equivalent radii,
// solved by the analytic sphere solver). Every converged solution lies on every wrapper by
// construction (the residual is at most 1e-12 of the size); a start that does not converge gives nothing, so
// a position can be missed, never returned wrong. Where the minimisation needs ~30 gap queries
// per solve through FCL's GJK, this is a few 9 x 9 linear solves.
#include <span>

#include "contact/contact_solver.hpp"

namespace fp {

template <int D>
class EllipsoidContactSolver final : public ContactSolver<D> {
 public:
  /// Every fixed body is an ellipsoid, a sphere or a plane wall, and so is the mobile (a mobile
  /// without a shape is a ball of its radius). Returns up to out.size() distinct positions.
  int solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile, std::span<Placement<D>> out) const override;
};

}  // namespace fp
