#pragma once
// A container's boundary triangle seen as a shape of zero thickness (3D only), so that
// containment in a non-convex mesh is an ordinary particle-facet gap of the narrow phase. Not
// a particle family: contact/shape_containment.cpp builds one per facet. Vertices in the body
// frame, centred on the triangle's centroid.
#include <array>

#include "shapes/shape.hpp"

namespace fp {

class FacetShape final : public Shape<3> {
 public:
  explicit FacetShape(const std::array<Vec3, 3>& vertices) : v_(vertices) {}
  static constexpr const char* kKind = "facet";

  const char* kind() const override { return kKind; }
  double measure() const override { return 0.0; }
  double bounding_radius() const override;
  double inscribed_radius() const override { return 0.0; }
  Vec3 support(const Vec3& u) const override;
  /// Points of the closed triangle (within 1e-12 of its size off its plane).
  bool contains(const Vec3& x) const override;
  std::vector<Ball<3>> hull_balls() const override;
  SurfaceMesh<3> surface(int resolution) const override;
  /// A flat two-sided fcl::Convex: FCL's distance has no entry for its TriangleP (it returned
  /// DBL_MAX for every shape, so no facet was ever seen crossing a particle).
  std::vector<FclPart<3>> fcl_parts() const override;
  ShapePtr<3> scaled(double s) const override;
  std::string definition_json() const override;

 private:
  std::array<Vec3, 3> v_;
};

}  // namespace fp
