#include "core/geometry/cylinder_container.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/geometry/container_checks.hpp"

namespace fp {

CylinderContainer::CylinderContainer(const Vec3& base_center, const Vec3& axis, double radius, double height,
                                     const Vec3& origin)
    : Container<3>(origin), base_(base_center - origin), radius_(radius), height_(height) {
  detail::require_finite<3>(origin, "CylinderContainer", "origin");
  detail::require_finite<3>(base_center, "CylinderContainer", "base_center");
  detail::require_finite<3>(axis, "CylinderContainer", "axis");
  detail::require_positive(radius, "CylinderContainer", "radius");
  detail::require_positive(height, "CylinderContainer", "height");
  const double len = axis.norm();
  if (!(len > 0.0) || !std::isfinite(len))
    throw std::invalid_argument("CylinderContainer: axis must be a non-zero vector, got " + detail::format_vec<3>(axis));
  axis_ = axis / len;
}

bool CylinderContainer::inside(const Vec3& p) const {
  double t, rho;
  local(p, t, rho);
  return t >= 0.0 && t <= height_ && rho <= radius_;
}

double CylinderContainer::signed_distance(const Vec3& p) const {
  double t, rho;
  local(p, t, rho);
  const double dr = rho - radius_;                 // > 0 outside the lateral surface
  const double dt = std::max(-t, t - height_);     // > 0 beyond a cap
  if (dr <= 0.0 && dt <= 0.0) return std::max(dr, dt);
  return std::hypot(std::max(dr, 0.0), std::max(dt, 0.0));
}

Aabb<3> CylinderContainer::bounds() const {
  // A cap disk of radius R with unit normal a extends R * sqrt(1 - a_i^2) along axis i.
  const Vec3 ext = radius_ * (Vec3::Ones() - axis_.cwiseProduct(axis_)).cwiseMax(0.0).cwiseSqrt();
  const Vec3 top = base_ + height_ * axis_;
  Aabb<3> b;
  b.lo = base_.cwiseMin(top) - ext;
  b.hi = base_.cwiseMax(top) + ext;
  return b;
}

double CylinderContainer::measure() const {
  return kPi * radius_ * radius_ * height_;
}

void CylinderContainer::walls_near(const Vec3& p, double reach, std::vector<Wall<3>>& out) const {
  double t, rho;
  local(p, t, rho);
  const double beyond_caps = std::max({0.0, -t, t - height_});
  const double beyond_rim = std::max(0.0, rho - radius_);
  if (std::hypot(rho - radius_, beyond_caps) <= reach) out.push_back(Wall<3>::cylinder(base_, axis_, radius_, 0));
  if (std::hypot(t, beyond_rim) <= reach) out.push_back(Wall<3>::plane(base_, axis_, 1));
  if (std::hypot(t - height_, beyond_rim) <= reach)
    out.push_back(Wall<3>::plane(base_ + height_ * axis_, -axis_, 2));
}

std::string CylinderContainer::describe() const {
  return "cylinder base " + detail::format_vec<3>(base_ + origin()) + " axis " + detail::format_vec<3>(axis_) + " radius " +
         detail::format_number(radius_) + " height " + detail::format_number(height_);
}

bool CylinderContainer::contains_ball(const Vec3& c, double r, double rel_tol) const {
  const double need = r - rel_tol * r;
  double t, rho;
  local(c, t, rho);
  return t >= need && t <= height_ - need && rho <= radius_ - need;
}

}  // namespace fp
