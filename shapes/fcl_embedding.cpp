#include "shapes/fcl_embedding.hpp"

#include <fcl/geometry/shape/convex.h>

namespace fp {

std::shared_ptr<fcl::CollisionGeometry<double>> make_fcl_convex(const std::vector<Eigen::Vector3d>& vertices,
                                                                const std::vector<std::vector<int>>& faces) {
  auto v = std::make_shared<std::vector<Eigen::Vector3d>>(vertices);
  auto f = std::make_shared<std::vector<int>>();
  for (const auto& face : faces) {  // FCL's encoding: [n, i0, ..., i(n-1), n, ...]
    f->push_back(static_cast<int>(face.size()));
    f->insert(f->end(), face.begin(), face.end());
  }
  auto convex = std::make_shared<fcl::Convexd>(v, static_cast<int>(faces.size()), f);
  convex->computeLocalAABB();
  return convex;
}

std::shared_ptr<fcl::CollisionGeometry<double>> make_fcl_prism(const std::vector<Vec2>& polygon, double half_height) {
  const int n = static_cast<int>(polygon.size());
  std::vector<Eigen::Vector3d> v;
  for (const Vec2& p : polygon) v.emplace_back(p.x(), p.y(), -half_height);
  for (const Vec2& p : polygon) v.emplace_back(p.x(), p.y(), half_height);
  std::vector<std::vector<int>> faces;
  std::vector<int> top, bottom;
  for (int i = 0; i < n; ++i) {
    top.push_back(n + i);          // counter-clockwise seen from +z
    bottom.push_back(n - 1 - i);   // reversed: counter-clockwise seen from -z
    const int j = (i + 1) % n;
    faces.push_back({i, j, n + j, n + i});  // outward normal = edge x z
  }
  faces.push_back(top);
  faces.push_back(bottom);
  return make_fcl_convex(v, faces);
}

}  // namespace fp
