#pragma once
// Wrapper-intersection solver for 2D particles made of rounded convex cores (shapes/shape.hpp,
// Shape::rounded_cores): disks, stadiums, convex polygons, clusters of disks and any union of
// such, against each other and the walls. Paper 004, Sect. 3.1: "the wrappers obtained here are
// circles, polygons, or circumpolygons, which are formed by line segments and arcs of circles
// interleaved", and "the intersection of two circumpolygons is reduced to finding intersections
// between sets of line segments and arcs of circles".
//
// The wrapper of a fixed core F (points f_i, radius rf) for a mobile core M (points m_j turned to
// the mobile's orientation, radius rm) is the boundary of Q (+) disk(rf + rm) with Q the convex
// hull of the differences f_i - m_j (the Minkowski sum F (+) (-M), built as a hull of at most
// |F| |M| points): offset edges of Q and arcs around its vertices (a circumpolygon); a polygon when
// both radii are 0. A plane wall's wrapper is a line, a disk wall's a set of circles (the mobile's
// core points must all stay inside), a reflex corner's the wrapper of a point. A body made of
// several cores (a cluster) has one wrapper per (fixed core, mobile core).
//
// Positions touching s0 and the other body are the intersections of a wrapper of each (segment-
// segment, segment-arc, arc-arc, with lines and circles for walls: closed forms). A candidate is
// kept when, against each body, the least signed gap over its wrappers is within kContactTol of
// zero relative to the smaller circumscribed radius: it touches the body and overlaps none of its
// cores. Exact up to rounding, no iterations. Computed in a frame centred on s0.
#include <span>

#include "contact/contact_solver.hpp"

namespace fp {

class PolygonWrapperSolver final : public ContactSolver<2> {
 public:
  /// A kept position's signed gap to each body lies within this fraction of the smaller
  /// circumscribed radius (the body's and the mobile's; the mobile's for a wall).
  static constexpr double kContactTol = 1e-9;

  /// Every fixed particle and the mobile must have rounded cores (a mobile without a shape is a
  /// disk of its radius). Returns up to out.size() distinct positions.
  int solve(std::span<const Body<2>> fixed, const Mobile<2>& mobile, std::span<Placement<2>> out) const override;
};

}  // namespace fp
