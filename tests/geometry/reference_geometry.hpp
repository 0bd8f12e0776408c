#pragma once
// Slow, independent references for the container tests: none of this code is shared with
// core/geometry, so a bug there cannot hide in both.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp::testref {

/// Runs f, expects std::invalid_argument whose message contains every fragment.
inline void expect_invalid(const std::function<void()>& f, std::initializer_list<std::string> fragments) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one mentioning '" << *fragments.begin() << "'";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    for (const std::string& s : fragments)
      EXPECT_NE(what.find(s), std::string::npos) << "message '" << what << "' lacks '" << s << "'";
  }
}

template <int D>
double segment_distance(const Vec<D>& p, const Vec<D>& a, const Vec<D>& b) {
  // Foot of the perpendicular if it falls on the segment, else the nearer end.
  const Vec<D> ab = b - a;
  const double len2 = ab.squaredNorm();
  const double s = (p - a).dot(ab);
  if (s <= 0.0 || len2 == 0.0) return (p - a).norm();
  if (s >= len2) return (p - b).norm();
  return (p - (a + (s / len2) * ab)).norm();
}

/// Winding number by summing the signed angles the edges subtend at p.
inline int winding_by_angles(const std::vector<Vec2>& poly, const Vec2& p) {
  double total = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i] - p, b = poly[(i + 1) % poly.size()] - p;
    total += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  }
  return static_cast<int>(std::lround(total / (2.0 * kPi)));
}

inline double polygon_boundary_distance(const std::vector<Vec2>& poly, const Vec2& p) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < poly.size(); ++i) d = std::min(d, segment_distance<2>(p, poly[i], poly[(i + 1) % poly.size()]));
  return d;
}

/// Distance from p to triangle abc: to the plane if the projection falls inside (same-side
/// tests against the three edges), else to the nearest edge.
inline double triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  if (n2 > 0.0) {
    const Vec3 q = p - (p - a).dot(n) / n2 * n;
    const bool in = n.dot((b - a).cross(q - a)) >= 0 && n.dot((c - b).cross(q - b)) >= 0 && n.dot((a - c).cross(q - c)) >= 0;
    if (in) return std::abs((p - a).dot(n)) / std::sqrt(n2);
  }
  return std::min({segment_distance<3>(p, a, b), segment_distance<3>(p, b, c), segment_distance<3>(p, c, a)});
}

/// Parity of the crossings of a ray from p with the triangles (Moller-Trumbore). A ray that
/// passes too close to an edge or vertex is replaced by another direction.
inline bool inside_by_ray_parity(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& tris, const Vec3& p) {
  const Vec3 directions[] = {Vec3(0.5772, 0.8017, 0.1561), Vec3(-0.3141, 0.2718, 0.9093), Vec3(0.7071, -0.6180, -0.3437),
                             Vec3(-0.4142, -0.7320, 0.5412), Vec3(0.1234, -0.2345, -0.9642)};
  for (const Vec3& d0 : directions) {
    const Vec3 d = d0.normalized();
    int crossings = 0;
    bool ambiguous = false;
    for (const auto& t : tris) {
      const Vec3 e1 = v[t[1]] - v[t[0]], e2 = v[t[2]] - v[t[0]];
      const Vec3 h = d.cross(e2);
      const double det = e1.dot(h);
      const double scale = e1.norm() * e2.norm();
      if (std::abs(det) <= 1e-12 * scale) continue;  // ray parallel to the triangle
      const Vec3 s = p - v[t[0]];
      const double u = s.dot(h) / det;
      const Vec3 q = s.cross(e1);
      const double w = d.dot(q) / det;
      const double tt = e2.dot(q) / det;
      const double margin = 1e-9;
      if (u < -margin || w < -margin || u + w > 1 + margin || tt < -margin * std::sqrt(scale)) continue;
      if (u < margin || w < margin || u + w > 1 - margin || tt < margin * std::sqrt(scale)) {
        ambiguous = true;
        break;
      }
      ++crossings;
    }
    if (!ambiguous) return crossings % 2 == 1;
  }
  throw std::runtime_error("inside_by_ray_parity: every ray was ambiguous");
}

inline double mesh_distance(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& tris, const Vec3& p) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& t : tris) d = std::min(d, triangle_distance(p, v[t[0]], v[t[1]], v[t[2]]));
  return d;
}

}  // namespace fp::testref
