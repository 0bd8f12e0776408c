#include "core/geometry/box_container.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/geometry/container_checks.hpp"

namespace fp {

template <int D>
BoxContainer<D>::BoxContainer(const Vec<D>& lo, const Vec<D>& hi, const Vec<D>& origin)
    : Container<D>(origin), lo_(lo - origin), hi_(hi - origin) {
  detail::require_finite<D>(lo, "BoxContainer", "lo");
  detail::require_finite<D>(hi, "BoxContainer", "hi");
  detail::require_finite<D>(origin, "BoxContainer", "origin");
  for (int a = 0; a < D; ++a)
    if (!(lo[a] < hi[a]))
      throw std::invalid_argument("BoxContainer: lo must be < hi on every axis (size must be positive), got lo " +
                                  detail::format_vec<D>(lo) + " and hi " + detail::format_vec<D>(hi) +
                                  " on axis " + std::to_string(a));
}

template <int D>
bool BoxContainer<D>::inside(const Vec<D>& p) const {
  return (p.array() >= lo_.array()).all() && (p.array() <= hi_.array()).all();
}

template <int D>
double BoxContainer<D>::signed_distance(const Vec<D>& p) const {
  // Per axis, the signed distance to the slab; the box is their intersection.
  const Vec<D> d = (lo_ - p).cwiseMax(p - hi_);
  const double worst = d.maxCoeff();
  if (worst <= 0.0) return worst;
  return d.cwiseMax(0.0).norm();
}

template <int D>
Aabb<D> BoxContainer<D>::bounds() const {
  Aabb<D> b;
  b.lo = lo_;
  b.hi = hi_;
  return b;
}

template <int D>
double BoxContainer<D>::measure() const {
  return (hi_ - lo_).prod();
}

template <int D>
void BoxContainer<D>::walls_near(const Vec<D>& p, double reach, std::vector<Wall<D>>& out) const {
  // Excess of p outside the box along each axis: the lateral part of the distance to a face.
  const Vec<D> excess = (lo_ - p).cwiseMax(p - hi_).cwiseMax(0.0);
  const double reach2 = reach * reach;
  for (int a = 0; a < D; ++a) {
    double lateral2 = 0.0;
    for (int b = 0; b < D; ++b)
      if (b != a) lateral2 += excess[b] * excess[b];
    for (int side = 0; side < 2; ++side) {
      const double along = side == 0 ? p[a] - lo_[a] : hi_[a] - p[a];
      if (along * along + lateral2 > reach2) continue;
      Vec<D> n = Vec<D>::Zero();
      n[a] = side == 0 ? 1.0 : -1.0;
      out.push_back(Wall<D>::plane(side == 0 ? lo_ : hi_, n, 2 * a + side));
    }
  }
}

template <int D>
Vec<D> BoxContainer<D>::interior_point() const {
  return 0.5 * (lo_ + hi_);
}

template <int D>
std::string BoxContainer<D>::describe() const {
  return std::string(D == 2 ? "rectangle " : "box ") + detail::format_vec<D>(lo_ + this->origin()) + "-" +
         detail::format_vec<D>(hi_ + this->origin());
}

template <int D>
bool BoxContainer<D>::contains_ball(const Vec<D>& c, double r, double rel_tol) const {
  const double need = r - rel_tol * r;
  return ((c - lo_).array() >= need).all() && ((hi_ - c).array() >= need).all();
}

template class BoxContainer<2>;
template class BoxContainer<3>;

}  // namespace fp
