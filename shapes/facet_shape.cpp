#include "shapes/facet_shape.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <memory>

#include "shapes/fcl_embedding.hpp"
#include "shapes/json_text.hpp"

namespace fp {

double FacetShape::bounding_radius() const {
  return std::max({v_[0].norm(), v_[1].norm(), v_[2].norm()});
}

Vec3 FacetShape::support(const Vec3& u) const {
  std::size_t k = 0;
  for (std::size_t q = 1; q < 3; ++q)
    if (u.dot(v_[q]) > u.dot(v_[k])) k = q;
  return v_[k];
}

bool FacetShape::contains(const Vec3& x) const {
  const Vec3 n = (v_[1] - v_[0]).cross(v_[2] - v_[0]);
  const double area2 = n.norm();
  if (!(area2 > 0)) return false;
  const double slack = 1e-12 * bounding_radius();
  if (std::abs(n.dot(x - v_[0])) > slack * area2) return false;
  for (std::size_t q = 0; q < 3; ++q)  // on the inner side of every edge
    if ((v_[(q + 1) % 3] - v_[q]).cross(x - v_[q]).dot(n) < -slack * area2) return false;
  return true;
}

std::vector<Ball<3>> FacetShape::hull_balls() const {
  return {Ball<3>{v_[0], 0.0}, Ball<3>{v_[1], 0.0}, Ball<3>{v_[2], 0.0}};
}

SurfaceMesh<3> FacetShape::surface(int) const {
  SurfaceMesh<3> m;
  m.vertices.assign(v_.begin(), v_.end());
  m.facets.push_back({0, 1, 2});
  return m;
}

std::vector<FclPart<3>> FacetShape::fcl_parts() const {
  FclPart<3> p;
  p.geometry = make_fcl_convex({v_[0], v_[1], v_[2]}, {{0, 1, 2}, {0, 2, 1}});  // both sides
  return {p};
}

ShapePtr<3> FacetShape::scaled(double s) const {
  return std::make_shared<FacetShape>(std::array<Vec3, 3>{s * v_[0], s * v_[1], s * v_[2]});
}

std::string FacetShape::definition_json() const {
  return std::string(R"({"kind": "facet", "vertices": [)") + json_point<3>(v_[0]) + ", " + json_point<3>(v_[1]) + ", " +
         json_point<3>(v_[2]) + "]}";
}

}  // namespace fp
