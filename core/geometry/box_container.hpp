#pragma once
// Axis-aligned box (3D) or rectangle (2D). Its walls are the 2D face planes.
#include "core/geometry/container.hpp"

namespace fp {

template <int D>
class BoxContainer final : public Container<D> {
 public:
  /// lo and hi are absolute; the box is stored relative to `origin` (its local frame).
  /// Throws std::invalid_argument unless lo and hi are finite and lo < hi on every axis.
  BoxContainer(const Vec<D>& lo, const Vec<D>& hi, const Vec<D>& origin = Vec<D>::Zero());

  /// A box given in the local frame of `origin` (exactly: no round trip through absolute values).
  static BoxContainer from_local(const Vec<D>& lo, const Vec<D>& hi, const Vec<D>& origin) {
    BoxContainer b(lo + origin, hi + origin, origin);
    b.lo_ = lo;
    b.hi_ = hi;
    return b;
  }

  bool inside(const Vec<D>& p) const override;
  double signed_distance(const Vec<D>& p) const override;
  Aabb<D> bounds() const override;
  double measure() const override;
  /// Face walls as planes with inward normals; id = 2 * axis + (0 for the lo face, 1 for the hi face).
  /// A face is returned when the distance from p to the face itself (not its plane) is <= reach.
  void walls_near(const Vec<D>& p, double reach, std::vector<Wall<D>>& out) const override;
  Vec<D> interior_point() const override;
  std::string describe() const override;
  bool contains_ball(const Vec<D>& c, double r, double rel_tol = 1e-9) const override;

  /// Corners in the local frame.
  const Vec<D>& lo() const { return lo_; }
  const Vec<D>& hi() const { return hi_; }

 private:
  Vec<D> lo_, hi_;
};

extern template class BoxContainer<2>;
extern template class BoxContainer<3>;

}  // namespace fp
