#include "core/geometry/ball_container.hpp"

#include <cmath>

#include "core/geometry/container_checks.hpp"

namespace fp {

template <int D>
BallContainer<D>::BallContainer(const Vec<D>& center, double radius, const Vec<D>& origin)
    : Container<D>(origin), center_(center - origin), radius_(radius) {
  detail::require_finite<D>(origin, "BallContainer", "origin");
  detail::require_finite<D>(center, "BallContainer", "center");
  detail::require_positive(radius, "BallContainer", "radius");
}

template <int D>
bool BallContainer<D>::inside(const Vec<D>& p) const {
  return (p - center_).squaredNorm() <= radius_ * radius_;
}

template <int D>
double BallContainer<D>::signed_distance(const Vec<D>& p) const {
  return (p - center_).norm() - radius_;
}

template <int D>
Aabb<D> BallContainer<D>::bounds() const {
  Aabb<D> b;
  b.lo = center_.array() - radius_;
  b.hi = center_.array() + radius_;
  return b;
}

template <int D>
double BallContainer<D>::measure() const {
  return ball_measure<D>(radius_);
}

template <int D>
void BallContainer<D>::walls_near(const Vec<D>& p, double reach, std::vector<Wall<D>>& out) const {
  if (std::abs(signed_distance(p)) <= reach) out.push_back(Wall<D>::sphere(center_, radius_, 0));
}

template <int D>
std::string BallContainer<D>::describe() const {
  return std::string(D == 2 ? "disk" : "ball") + " center " + detail::format_vec<D>(center_ + this->origin()) + " radius " +
         detail::format_number(radius_);
}

template <int D>
bool BallContainer<D>::contains_ball(const Vec<D>& c, double r, double rel_tol) const {
  return (c - center_).norm() <= radius_ - r + rel_tol * r;
}

template class BallContainer<2>;
template class BallContainer<3>;

}  // namespace fp
