#pragma once
// Disk (2D) / sphere (3D) of radius r centred on the reference point. A scene made only of
// spheres never builds one: it takes the sphere fast path (front/advancing_front.hpp). This
// class exists so that spheres can be mixed with other shapes.
#include "shapes/shape.hpp"

namespace fp {

template <int D>
class SphereShape final : public Shape<D> {
 public:
  explicit SphereShape(double radius) : r_(radius) {}
  static constexpr const char* kKind = "sphere";
  double radius() const { return r_; }

  const char* kind() const override { return kKind; }
  double measure() const override;
  double bounding_radius() const override { return r_; }
  double inscribed_radius() const override { return r_; }
  void rounded_cores(std::vector<RoundedCore<D>>& out) const override {
    out.resize(1);
    out[0].points.assign(1, Vec<D>::Zero()), out[0].radius = r_;
  }
  Vec<D> support(const Vec<D>& u) const override;
  bool contains(const Vec<D>& x) const override { return x.squaredNorm() <= r_ * r_; }
  std::vector<Ball<D>> hull_balls() const override { return {Ball<D>{Vec<D>::Zero(), r_}}; }
  SurfaceMesh<D> surface(int resolution) const override;
  std::vector<FclPart<D>> fcl_parts() const override;
  ShapePtr<D> scaled(double s) const override;
  std::string definition_json() const override;

 private:
  double r_;
};

}  // namespace fp
