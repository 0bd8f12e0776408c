#pragma once
// The radial frame of the front's orientation choice (packer.orientation_frame: radial).
//
// The front grows outwards from its seed point, and every choice it makes by the growth key
// (closest to the seed) couples a particle's orientation to the radius from the seed: the scan's
// choice of the side of s0, the roll and the pocket trials laid capsules, ellipsoids and dimers
// across the radius (<P2(a.r)> down to -0.40 for ellipsoids; 2D ellipses -0.72) while the
// marginal law passed its tests (experiments/shape-density). In the radial frame a draft's drawn
// orientation Q (isotropic) is read relative to the radius r at the position tried,
// R = A(r, phi) F(r) Q, with F(r) a fixed rotation taking the frame's axis e to r and A(r, phi)
// the rotation by phi about r: whatever phi the choices pick, the radius seen from the body,
// R^T r = Q^T e, is Q's, uniform. Only the turn about the radius is chosen, and a turn about the
// radius does not change the particle's relation to it.
#include <cmath>

#include <Eigen/Geometry>

#include "core/geometry/vec.hpp"
#include "core/sampling/orientation_law.hpp"
#include "shapes/pose.hpp"

namespace fp {

/// F(r): a rotation taking the frame's axis (z in 3D, x in 2D) to the direction of r; the
/// identity for r = 0 (the seed particle has no radius).
template <int D>
Mat<D> radial_frame(const Vec<D>& r) {
  const double n = r.norm();
  if (!(n > 0)) return Mat<D>::Identity();
  if constexpr (D == 2) {
    return rotation_about<2>(Vec2::Zero(), std::atan2(r.y(), r.x()));
  } else {
    return Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), Vec3(r / n)).toRotationMatrix();
  }
}

/// A(r, phi): the rotation by phi about the radius r (3D); the identity for r = 0 or phi = 0,
/// and in 2D, where no turn keeps the angle to the radius.
template <int D>
Mat<D> about_radius(const Vec<D>& r, double phi) {
  if constexpr (D == 2) {
    return Mat<2>::Identity();
  } else {
    const double n = r.norm();
    return n > 0 && phi != 0 ? rotation_about<3>(Vec3(r / n), phi) : Mat<3>::Identity();
  }
}

/// A(r, phi) F(r) Q: the drawn orientation Q read relative to the radius r, turned by phi about it.
template <int D>
Mat<D> at_radius(const Vec<D>& r, double phi, const Mat<D>& relative) {
  return about_radius<D>(r, phi) * radial_frame<D>(r) * relative;
}

}  // namespace fp
