#include "shapes/ellipsoid_shape.hpp"

#include <fcl/geometry/shape/ellipsoid.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "shapes/contains_slack.hpp"
#include "shapes/fcl_embedding.hpp"
#include "shapes/json_text.hpp"
#include "shapes/round_families.hpp"
#include "shapes/round_surface.hpp"
#include "shapes/shape_parameters.hpp"
#include "shapes/unit_ball_cover.hpp"

namespace fp {

template <int D>
EllipsoidShape<D>::EllipsoidShape(const Vec<D>& semi_axes) : axes_(semi_axes) {}

template <int D>
double EllipsoidShape<D>::measure() const {
  return ball_measure<D>(1.0) * axes_.prod();
}

template <int D>
Vec<D> EllipsoidShape<D>::support(const Vec<D>& u) const {
  // The ellipsoid is A (unit ball), A = diag(axes): argmax u.x = A (A u / |A u|).
  const Vec<D> au = axes_.cwiseProduct(u);
  const double n = au.norm();
  return n > 0 ? Vec<D>(axes_.cwiseProduct(au) / n) : Vec<D>::Zero();
}

template <int D>
bool EllipsoidShape<D>::contains(const Vec<D>& x) const {
  return x.cwiseQuotient(axes_).squaredNorm() <= 1 + 2 * kContainsSlack * axes_.maxCoeff() / axes_.minCoeff();
}

template <int D>
std::vector<Ball<D>> EllipsoidShape<D>::hull_balls() const {
  std::vector<Ball<D>> balls;
  for (const Vec<D>& p : unit_ball_cover<D>()) balls.push_back({axes_.cwiseProduct(p), 0.0});
  return balls;
}

template <int D>
SurfaceMesh<D> EllipsoidShape<D>::surface(int resolution) const {
  SurfaceMesh<D> m = capsule_surface<D>(0.0, 1.0, resolution);  // the unit circle / sphere, stretched
  for (Vec<D>& v : m.vertices) v = axes_.cwiseProduct(v);
  return m;
}

template <int D>
std::vector<FclPart<D>> EllipsoidShape<D>::fcl_parts() const {
  FclPart<D> p;
  if constexpr (D == 2)
    p.geometry = std::make_shared<fcl::Ellipsoidd>(axes_.x(), axes_.y(), kEmbeddingDepth * axes_.maxCoeff());
  else
    p.geometry = std::make_shared<fcl::Ellipsoidd>(axes_.x(), axes_.y(), axes_.z());
  return {p};
}

template <int D>
ShapePtr<D> EllipsoidShape<D>::scaled(double s) const {
  return std::make_shared<EllipsoidShape<D>>(axes_ * s);
}

template <int D>
std::string EllipsoidShape<D>::definition_json() const {
  return std::string(R"({"kind": ")") + kKind + R"(", "semi_axes": )" + json_point<D>(axes_) + "}";
}

/// The smallest semi-axis a template may have, relative to its largest.
constexpr double kSmallestAxisRatio = 1e-12;

template <int D>
ShapePrototype<D> ellipsoid_prototype(const ShapeParameters& p) {
  const ParameterReader r(p);
  const auto axes = r.list("axes", D == 2 ? "the semi-axis ratios [a, b]" : "the semi-axis ratios [a, b, c]");
  if (static_cast<int>(axes.size()) != D)
    r.fail("axes", "needs " + std::to_string(D) + " semi-axes in " + std::to_string(D) + "D (got " +
                       std::to_string(axes.size()) + ")");
  Vec<D> a;
  for (int k = 0; k < D; ++k) {
    if (!(axes[k] > 0)) r.fail("axes", "semi-axis " + std::to_string(k) + " must be positive (got " + json_number(axes[k]) + ")");
    a[k] = axes[k];
  }
  a /= a.maxCoeff();
  // Measured: axes 1e-15 of the largest pack and validate; at 1e-300 the analysis, whose grid is
  // sized by the equivalent radius (1e-100 of the largest axis), asked for more cells than exist.
  if (a.minCoeff() < kSmallestAxisRatio) {
    char text[160];
    std::snprintf(text, sizeof text, "the smallest semi-axis is %.3g of the largest, below %.3g", a.minCoeff(), kSmallestAxisRatio);
    r.fail("axes", std::string(text) + ": no packing tells that ellipsoid from a disk (a needle); make it thicker");
  }
  auto shape = std::make_shared<EllipsoidShape<D>>(a);
  ShapePrototype<D> proto{shape, {{"circumscribed_radius", 1.0}, {"semi_axis_a", a[0]}, {"semi_axis_b", a[1]}}};
  if constexpr (D == 3) proto.dimensions["semi_axis_c"] = a[2];
  proto.dimensions["equivalent_radius"] = equivalent_radius<D>(shape->measure());
  return proto;
}

template class EllipsoidShape<2>;
template class EllipsoidShape<3>;
template ShapePrototype<2> ellipsoid_prototype<2>(const ShapeParameters&);
template ShapePrototype<3> ellipsoid_prototype<3>(const ShapeParameters&);

}  // namespace fp
