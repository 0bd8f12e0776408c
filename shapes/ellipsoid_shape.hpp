#pragma once
// Ellipse (2D, family "ellipse") / ellipsoid (3D, family "ellipsoid") with semi-axes along the
// body axes: sum (x_i / a_i)^2 <= 1. Support, inside test and measure are exact; the hull balls are
// points of a polytope circumscribing it (unit_ball_cover.hpp: up to 0.5 % of a semi-axis outside).
// FCL gets an fcl::Ellipsoidd; in 2D its third semi-axis is kEmbeddingDepth times the largest
// (fcl_embedding.hpp: distance and penetration depth then stay in the plane).
#include "shapes/shape.hpp"
#include "shapes/shape_registry.hpp"

namespace fp {

template <int D>
class EllipsoidShape final : public Shape<D> {
 public:
  explicit EllipsoidShape(const Vec<D>& semi_axes);
  static constexpr const char* kKind = D == 2 ? "ellipse" : "ellipsoid";
  const Vec<D>& semi_axes() const { return axes_; }

  const char* kind() const override { return kKind; }
  double measure() const override;
  double bounding_radius() const override { return axes_.maxCoeff(); }
  double inscribed_radius() const override { return axes_.minCoeff(); }
  Vec<D> support(const Vec<D>& u) const override;
  bool contains(const Vec<D>& x) const override;
  std::vector<Ball<D>> hull_balls() const override;
  SurfaceMesh<D> surface(int resolution) const override;
  std::vector<FclPart<D>> fcl_parts() const override;
  ShapePtr<D> scaled(double s) const override;
  std::string definition_json() const override;

 private:
  Vec<D> axes_;
};

/// "ellipse" / "ellipsoid": `axes: [a, b]` / `[a, b, c]`, semi-axis ratios (any positive numbers,
/// scaled so that the largest is 1). Dimensions: circumscribed_radius, semi_axis_a, semi_axis_b
/// (semi_axis_c), equivalent_radius.
template <int D>
ShapePrototype<D> ellipsoid_prototype(const ShapeParameters& p);

}  // namespace fp
