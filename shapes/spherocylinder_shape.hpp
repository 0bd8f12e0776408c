#pragma once
// Spherocylinder (paper 004): every point within `radius` of the segment [-a e_x, +a e_x] in the
// body frame; a stadium in 2D, a capsule in 3D. Total length 2(a + r), width 2r, so the aspect
// ratio width / length is r / (a + r) and the circumscribed radius a + r.
#include "shapes/shape.hpp"

namespace fp {

template <int D>
class SpherocylinderShape final : public Shape<D> {
 public:
  SpherocylinderShape(double half_length, double radius) : a_(half_length), r_(radius) {}
  static constexpr const char* kKind = "spherocylinder";
  double half_length() const { return a_; }  ///< half the segment's length
  double radius() const { return r_; }
  /// Segment end points in the body frame.
  Vec<D> end_a() const { Vec<D> e = Vec<D>::Zero(); e[0] = -a_; return e; }
  Vec<D> end_b() const { Vec<D> e = Vec<D>::Zero(); e[0] = a_; return e; }

  const char* kind() const override { return kKind; }
  double measure() const override;
  double bounding_radius() const override { return a_ + r_; }
  double inscribed_radius() const override { return r_; }
  Vec<D> support(const Vec<D>& u) const override;
  bool contains(const Vec<D>& x) const override;
  std::vector<Ball<D>> hull_balls() const override { return {Ball<D>{end_a(), r_}, Ball<D>{end_b(), r_}}; }
  void rounded_cores(std::vector<RoundedCore<D>>& out) const override {
    out.resize(1);
    out[0].points.assign({end_a(), end_b()}), out[0].radius = r_;
  }
  SurfaceMesh<D> surface(int resolution) const override;
  std::vector<FclPart<D>> fcl_parts() const override;
  ShapePtr<D> scaled(double s) const override;
  std::string definition_json() const override;

 private:
  double a_, r_;
};

}  // namespace fp
