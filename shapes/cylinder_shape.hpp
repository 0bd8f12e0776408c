#pragma once
// Circular cylinder (3D only; the example of "adding a shape" in the README): radius r, height
// 2h, axis along body x like the spherocylinder. Support, inside test and measure are exact; the
// hull balls are the rims' points of two circumscribing 32-gons (up to 0.5 % of r outside).
#include "shapes/shape.hpp"
#include "shapes/shape_registry.hpp"

namespace fp {

class CylinderShape final : public Shape<3> {
 public:
  CylinderShape(double radius, double half_height) : r_(radius), h_(half_height) {}
  static constexpr const char* kKind = "cylinder";
  double radius() const { return r_; }
  double half_height() const { return h_; }

  const char* kind() const override { return kKind; }
  double measure() const override;
  double bounding_radius() const override;
  double inscribed_radius() const override { return r_ < h_ ? r_ : h_; }
  Vec3 support(const Vec3& u) const override;
  bool contains(const Vec3& x) const override;
  std::vector<Ball<3>> hull_balls() const override;
  SurfaceMesh<3> surface(int resolution) const override;
  std::vector<FclPart<3>> fcl_parts() const override;
  ShapePtr<3> scaled(double s) const override;
  std::string definition_json() const override;

 private:
  double r_, h_;
};

/// "cylinder": elongation = height / diameter > 0 (or aspect_ratio, its inverse). Dimensions:
/// circumscribed_radius, radius, diameter, height, equivalent_radius.
ShapePrototype<3> cylinder_prototype(const ShapeParameters& p);

}  // namespace fp
