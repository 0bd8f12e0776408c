#pragma once
// Spheres and spherocylinders as swept balls: the segment [from, from + along] thickened by a
// radius (a sphere: along = 0), and the gap of two of them, paper 004 Eq. 6 in distance form (the
// segments' distance minus the radii). The narrow phase's analytic pairs and the gap Newton solver
// (which prepares the segments' directions once per solve) both compute it here.
#include <cstring>
#include <optional>

#include "contact/narrow_phase.hpp"
#include "contact/segment_distance.hpp"
#include "shapes/sphere_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace fp {

/// Unit vector along v, or along `fallback` when v is (numerically) zero (and e_x if both are).
template <int D>
Vec<D> unit_or(const Vec<D>& v, const Vec<D>& fallback) {
  const double n = v.norm();
  if (n > 0) return v / n;
  const double m = fallback.norm();
  if (m > 0) return fallback / m;
  Vec<D> e = Vec<D>::Zero();
  e[0] = 1;
  return e;
}

template <int D>
struct SweptBall {
  Vec<D> from = Vec<D>::Zero(), along = Vec<D>::Zero();
  double radius = 0;
};

/// A sphere's or spherocylinder's swept ball at a pose; none for other kinds. A spherocylinder's
/// segment ends are -+a e_x in the body frame: position -+ a R e_x (the bits of to_world(), without
/// its products by zeros).
template <int D>
std::optional<SweptBall<D>> swept_ball(const Shape<D>& shape, const Mat<D>& rotation, const Vec<D>& position) {
  if (std::strcmp(shape.kind(), SpherocylinderShape<D>::kKind) == 0) {
    const auto& c = static_cast<const SpherocylinderShape<D>&>(shape);
    const Vec<D> half = c.half_length() * rotation.col(0);
    const Vec<D> from = position - half;
    return SweptBall<D>{from, Vec<D>(position + half - from), c.radius()};
  }
  if (std::strcmp(shape.kind(), SphereShape<D>::kKind) == 0) return SweptBall<D>{position, Vec<D>::Zero(), shape.bounding_radius()};
  return std::nullopt;
}

/// The gap of two swept balls (radii ra, rb) from their segments' closest points, with its
/// gradient for the second; `fallback` is the direction where the segments meet (the first's
/// centre to the second's).
template <int D>
Gap<D> swept_ball_gap(const SegmentClosest<D>& c, double ra, double rb, const Vec<D>& fallback) {
  const Vec<D> d = c.on_second - c.on_first;
  return {d.norm() - ra - rb, unit_or<D>(d, fallback)};
}

}  // namespace fp
