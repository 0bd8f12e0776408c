#pragma once
// Where a particle sits: position of its reference point plus a rotation (body -> world).
// 2D rotations are about z; quaternions (w, x, y, z) are what the output formats carry.
#include <Eigen/Geometry>
#include <cmath>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D>
using Mat = Eigen::Matrix<double, D, D>;

template <int D>
struct Pose {
  Vec<D> position = Vec<D>::Zero();
  Mat<D> rotation = Mat<D>::Identity();  ///< body frame -> world frame

  Vec<D> to_world(const Vec<D>& body) const { return position + rotation * body; }
  Vec<D> to_body(const Vec<D>& world) const { return rotation.transpose() * (world - position); }
  Vec<D> direction_to_body(const Vec<D>& u) const { return rotation.transpose() * u; }
};

/// Unit quaternion (w, x, y, z) of a rotation; a 2D angle theta is the rotation by theta about z.
template <int D>
Eigen::Vector4d quaternion_of(const Mat<D>& R) {
  if constexpr (D == 2) {
    const double half = 0.5 * std::atan2(R(1, 0), R(0, 0));
    return {std::cos(half), 0.0, 0.0, std::sin(half)};
  } else {
    Eigen::Quaterniond q(R);
    q.normalize();
    if (q.w() < 0) q.coeffs() *= -1;  // one sign, so equal rotations print equal
    return {q.w(), q.x(), q.y(), q.z()};
  }
}

/// Rotation matrix of a unit quaternion (w, x, y, z); in 2D the quaternion must be about z.
template <int D>
Mat<D> rotation_of(const Eigen::Vector4d& wxyz) {
  if constexpr (D == 2) {
    const double theta = 2 * std::atan2(wxyz[3], wxyz[0]);
    Mat<2> R;
    R << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
    return R;
  } else {
    return Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).normalized().toRotationMatrix();
  }
}

/// The rotation by `angle` about z (2D).
inline Mat<2> rotation_2d(double angle) {
  Mat<2> R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return R;
}

}  // namespace fp
