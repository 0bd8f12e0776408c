#pragma once
// Finite circular cylinder (3D): a lateral Cylinder wall and two Plane caps.
#include "core/geometry/container.hpp"

namespace fp {

class CylinderContainer final : public Container<3> {
 public:
  /// The solid {base_center + t * axis + q : 0 <= t <= height, q _|_ axis, |q| <= radius}.
  /// `axis` need not be unit (it is normalised here) but must be non-zero; throws
  /// std::invalid_argument on a zero axis, non-positive radius/height or non-finite input.
  /// `base_center` is absolute; the cylinder is stored relative to `origin` (its local frame).
  CylinderContainer(const Vec3& base_center, const Vec3& axis, double radius, double height,
                    const Vec3& origin = Vec3::Zero());

  bool inside(const Vec3& p) const override;
  double signed_distance(const Vec3& p) const override;
  /// The exact bounding box of the solid (of its two cap disks).
  Aabb<3> bounds() const override;
  double measure() const override;
  /// Wall ids: 0 lateral surface, 1 bottom cap (at base_center), 2 top cap. A wall is returned
  /// when the distance from p to that finite surface patch is <= reach.
  void walls_near(const Vec3& p, double reach, std::vector<Wall<3>>& out) const override;
  Vec3 interior_point() const override { return base_ + 0.5 * height_ * axis_; }
  std::string describe() const override;
  bool contains_ball(const Vec3& c, double r, double rel_tol = 1e-9) const override;

  /// In the local frame.
  const Vec3& base_center() const { return base_; }
  const Vec3& axis() const { return axis_; }
  double radius() const { return radius_; }
  double height() const { return height_; }

 private:
  /// Axial coordinate t and distance rho from the axis.
  void local(const Vec3& p, double& t, double& rho) const {
    const Vec3 d = p - base_;
    t = d.dot(axis_);
    rho = (d - t * axis_).norm();
  }

  Vec3 base_, axis_;
  double radius_, height_;
};

}  // namespace fp
