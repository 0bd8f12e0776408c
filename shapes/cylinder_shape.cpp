#include "shapes/cylinder_shape.hpp"

#include <fcl/geometry/shape/cylinder.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "shapes/contains_slack.hpp"
#include "shapes/json_text.hpp"
#include "shapes/round_families.hpp"
#include "shapes/shape_parameters.hpp"
#include "shapes/unit_ball_cover.hpp"

namespace fp {

double CylinderShape::measure() const { return 2 * kPi * r_ * r_ * h_; }

double CylinderShape::bounding_radius() const { return std::hypot(r_, h_); }

Vec3 CylinderShape::support(const Vec3& u) const {
  const double rho = std::hypot(u.y(), u.z());
  Vec3 p(u.x() >= 0 ? h_ : -h_, 0.0, 0.0);
  if (rho > 0) p.tail<2>() = u.tail<2>() * (r_ / rho);
  return p;
}

bool CylinderShape::contains(const Vec3& x) const {
  const double slack = kContainsSlack * bounding_radius();
  return std::abs(x.x()) <= h_ + slack && x.tail<2>().norm() <= r_ + slack;
}

std::vector<Ball<3>> CylinderShape::hull_balls() const {
  std::vector<Ball<3>> balls;
  for (double x : {-h_, h_})
    for (const Vec2& q : unit_ball_cover<2>()) balls.push_back({Vec3(x, r_ * q.x(), r_ * q.y()), 0.0});
  return balls;
}

SurfaceMesh<3> CylinderShape::surface(int resolution) const {
  const int n = std::max(3, resolution);
  SurfaceMesh<3> m;
  m.vertices.push_back(Vec3(-h_, 0, 0));
  m.vertices.push_back(Vec3(h_, 0, 0));
  for (double x : {-h_, h_})
    for (int j = 0; j < n; ++j) {
      const double t = 2 * kPi * j / n;
      m.vertices.push_back(Vec3(x, r_ * std::cos(t), r_ * std::sin(t)));
    }
  auto lo = [&](int j) { return 2 + j % n; };
  auto hi = [&](int j) { return 2 + n + j % n; };
  for (int j = 0; j < n; ++j) {
    // The angle turns from +y to +z, i.e. counter-clockwise about +x.
    m.facets.push_back({0, lo(j + 1), lo(j)});
    m.facets.push_back({1, hi(j), hi(j + 1)});
    m.facets.push_back({lo(j), lo(j + 1), hi(j + 1)});
    m.facets.push_back({lo(j), hi(j + 1), hi(j)});
  }
  return m;
}

std::vector<FclPart<3>> CylinderShape::fcl_parts() const {
  FclPart<3> p;
  p.geometry = std::make_shared<fcl::Cylinderd>(r_, 2 * h_);  // FCL's cylinder lies along its z axis
  p.rotation << 0, 0, 1,  //
      0, 1, 0,            //
      -1, 0, 0;           // z -> x (a rotation about y)
  return {p};
}

ShapePtr<3> CylinderShape::scaled(double s) const { return std::make_shared<CylinderShape>(r_ * s, h_ * s); }

std::string CylinderShape::definition_json() const {
  return R"({"kind": "cylinder", "radius": )" + json_number(r_) + R"(, "height": )" + json_number(2 * h_) +
         R"(, "axis": "body x"})";
}

ShapePrototype<3> cylinder_prototype(const ShapeParameters& p) {
  const ParameterReader r(p);
  const double k = width_over_length(r, "height", "diameter", /*rod_only=*/false);
  const double h = 1 / std::hypot(1.0, k);  // r = k h and r^2 + h^2 = 1
  auto shape = std::make_shared<CylinderShape>(k * h, h);
  return {shape,
          {{"circumscribed_radius", 1.0},
           {"radius", k * h},
           {"diameter", 2 * k * h},
           {"height", 2 * h},
           {"equivalent_radius", equivalent_radius<3>(shape->measure())}}};
}

}  // namespace fp
