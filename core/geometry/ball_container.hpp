#pragma once
// Ball (3D) or disk (2D). Its one wall is the sphere (the circle in 2D) seen from inside.
#include "core/geometry/container.hpp"

namespace fp {

template <int D>
class BallContainer final : public Container<D> {
 public:
  /// `center` is absolute; the ball is stored relative to `origin` (its local frame).
  /// Throws std::invalid_argument unless center is finite and radius positive and finite.
  BallContainer(const Vec<D>& center, double radius, const Vec<D>& origin = Vec<D>::Zero());

  bool inside(const Vec<D>& p) const override;
  double signed_distance(const Vec<D>& p) const override;
  Aabb<D> bounds() const override;
  double measure() const override;
  /// The sphere wall (id 0) when p is within reach of the sphere.
  void walls_near(const Vec<D>& p, double reach, std::vector<Wall<D>>& out) const override;
  Vec<D> interior_point() const override { return center_; }
  std::string describe() const override;
  bool contains_ball(const Vec<D>& c, double r, double rel_tol = 1e-9) const override;

  /// In the local frame.
  const Vec<D>& center() const { return center_; }
  double radius() const { return radius_; }

 private:
  Vec<D> center_;
  double radius_;
};

extern template class BallContainer<2>;
extern template class BallContainer<3>;

}  // namespace fp
