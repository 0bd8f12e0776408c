#pragma once
// The void of a tetrahedron of sphere centres (paper 000, Sect. 2.3, Eqs. 10-14): its volume
// minus the part of each vertex's sphere inside it. That part is the sphere's volume times the
// tetrahedron's solid angle at the vertex over 4 pi: Eq. 10's S_i^t / S_i, with S_i^t the
// spherical triangle (alpha + beta + gamma - pi) r_i^2 of Eqs. 11-14. The solid angle is computed
// by Van Oosterom and Strackee's formula, tan(omega / 2) = |a . (b x c)| / (|a||b||c| + (a . b)|c|
// + (a . c)|b| + (b . c)|a|), the same angle as Eqs. 12-14 without their arccosines, which lose
// digits in flat tetrahedra. In 2D, the triangle's area minus the disks' sectors. As in the paper, a sphere is taken to stay within its corner (not
// to cross the opposite face, nor to overlap another sphere there); the void then is exact.
#include <array>
#include <cmath>
#include <cstddef>

#include <Eigen/Geometry>

#include "core/geometry/vec.hpp"

namespace fp {

/// The solid angle (steradians) under which the triangle (a, b, c) is seen from the origin.
inline double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = std::abs(a.dot(b.cross(c)));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

/// Eq. 10: the volume of the tetrahedron of the centres c minus the parts of the spheres (c_i, r_i)
/// in its corners.
inline double tet_void_volume(const std::array<Vec3, 4>& c, const std::array<double, 4>& r) {
  const double volume = std::abs((c[1] - c[0]).cross(c[2] - c[0]).dot(c[3] - c[0])) / 6.0;
  double solid = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3& o = c[static_cast<std::size_t>(i)];
    const Vec3 a = c[static_cast<std::size_t>((i + 1) % 4)] - o, b = c[static_cast<std::size_t>((i + 2) % 4)] - o,
               d = c[static_cast<std::size_t>((i + 3) % 4)] - o;
    const double ri = r[static_cast<std::size_t>(i)];
    solid += solid_angle(a, b, d) * ri * ri * ri / 3.0;  // (omega / 4 pi) (4/3) pi r^3
  }
  return volume - solid;
}

/// The 2D analogue: the area of the triangle of the centres c minus the sectors of the disks
/// (c_i, r_i) in its corners, (theta_i / 2) r_i^2 with theta_i the corner's angle.
inline double triangle_void_area(const std::array<Vec2, 3>& c, const std::array<double, 3>& r) {
  const auto cross = [](const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); };
  const double area = std::abs(cross(c[1] - c[0], c[2] - c[0])) / 2.0;
  double sectors = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec2 a = c[(i + 1) % 3] - c[i], b = c[(i + 2) % 3] - c[i];
    sectors += std::atan2(std::abs(cross(a, b)), a.dot(b)) * r[i] * r[i] / 2.0;
  }
  return area - sectors;
}

/// The void of a Delaunay simplex of sphere (disk) centres: Eq. 10 in 3D, its 2D analogue.
template <int D>
double simplex_void_measure(const std::array<Vec<D>, D + 1>& c, const std::array<double, D + 1>& r) {
  if constexpr (D == 3) return tet_void_volume(c, r);
  else return triangle_void_area(c, r);
}

}  // namespace fp
