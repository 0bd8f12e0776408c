#pragma once
// Wrapper-intersection solver for 3D convex polyhedra against polyhedra and plane walls (and
// reflex corners). Paper 004, Sect. 3.1, convex polyhedra: the wrapper of a fixed polyhedron B
// for the mobile polyhedron A at its fixed orientation is the boundary of O = B (+) (-A), a convex
// polyhedron whose faces are "equal to the sum of the number of faces, edges and vertices of the
// fixed polyhedron" (for a given mobile): one per face of B (with a vertex of -A), one per face of
// -A (with a vertex of B), and one per pair of edges whose Gauss-map arcs cross (edge-edge
// contacts). Each face plane is n . x = h_B(n) + h_-A(n) with the support functions h; only the
// planes are built, from the Gauss maps (shapes: ConvexPolytopeShape::edges), no hull. A plane
// wall's wrapper is a plane, a reflex corner's the polyhedron -A placed there.
//
// Positions touching three bodies are the points of the three wrappers' boundaries. They are found
// without enumerating face triples, by walking the intersection curve C of the first two
// boundaries (paper: "walk the intersection curve of two wrappers"): starts on C (damped Newton
// steps on the two piecewise-linear gap functions from points where equivalent spheres touch the
// two bodies), then along C face pair by face pair (each piece a segment on a face of each: the
// next face is where the segment leaves one), and on each segment the points where it crosses
// the third boundary (segment clipping). C is made of closed loops, each walked once: every
// isolated solution on them is found, exact up to rounding; no iterations beyond the starts.
// The front tries one (front particle, body) pair with many third bodies: C is walked once per
// pair and mobile, and only the clipping is repeated. A kept position touches each body within
// kContactTol of the smaller circumscribed radius (checked on the exact face planes).
#include <span>

#include "contact/contact_solver.hpp"

namespace fp {

class PolytopeWrapperSolver final : public ContactSolver<3> {
 public:
  /// A kept position's gap to each body lies within this fraction of the smaller circumscribed
  /// radius (the mobile's for a wall).
  static constexpr double kContactTol = 1e-9;

  /// Fixed bodies: polyhedra (ConvexPolytopeShape), plane walls and reflex corners; the mobile a
  /// polyhedron; the first body a particle. Returns up to out.size() distinct positions.
  int solve(std::span<const Body<3>> fixed, const Mobile<3>& mobile, std::span<Placement<3>> out) const override;
};

}  // namespace fp
