#include "shapes/unit_ball_cover.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <Eigen/Geometry>

#include "shapes/regular_polytopes.hpp"

namespace fp {

namespace {

std::vector<Vec2> make_cover_2d() {
  constexpr int kSides = 32;
  std::vector<Vec2> v = regular_polygon(kSides);
  for (Vec2& p : v) p /= std::cos(kPi / kSides);  // the edges' midpoints touch the circle
  return v;
}

std::vector<Vec3> make_cover_3d() {
  constexpr int kSplits = 3;
  std::vector<Vec3> v = platonic_solid(20);
  // The icosahedron's faces: the triples of mutually nearest vertices.
  double edge = 1e300;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) edge = std::min(edge, (v[i] - v[j]).norm());
  auto adjacent = [&](int i, int j) { return (v[i] - v[j]).norm() < edge * (1 + 1e-9); };
  std::vector<std::array<int, 3>> faces;
  const int n = static_cast<int>(v.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k)
        if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k)) faces.push_back({i, j, k});
  // Split each triangle in four, new vertices on the sphere (shared along edges).
  for (int s = 0; s < kSplits; ++s) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto [it, added] = midpoint.try_emplace({key.first, key.second}, static_cast<int>(v.size()));
      if (added) v.push_back((v[a] + v[b]).normalized());
      return it->second;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : faces) {
      const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({b, bc, ab});
      finer.push_back({c, ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  double inradius = 1.0;
  for (const auto& [a, b, c] : faces) {
    const Vec3 normal = (v[b] - v[a]).cross(v[c] - v[a]).normalized();
    inradius = std::min(inradius, std::abs(normal.dot(v[a])));
  }
  for (Vec3& p : v) p /= inradius;
  return v;
}

}  // namespace

template <>
const std::vector<Vec2>& unit_ball_cover<2>() {
  static const std::vector<Vec2> v = make_cover_2d();
  return v;
}

template <>
const std::vector<Vec3>& unit_ball_cover<3>() {
  static const std::vector<Vec3> v = make_cover_3d();
  return v;
}

template <int D>
double unit_ball_cover_slack() {
  double r = 0.0;
  for (const Vec<D>& p : unit_ball_cover<D>()) r = std::max(r, p.norm());
  return r - 1;
}

template double unit_ball_cover_slack<2>();
template double unit_ball_cover_slack<3>();

}  // namespace fp
