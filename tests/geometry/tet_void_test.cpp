// The void of a tetrahedron of spheres (paper 000 Eqs. 10-14): the solid angle against the
// spherical triangle of Eqs. 11-14 and known values; the void against a brute-force count of
// sample points outside every sphere.
#include "core/geometry/tet_void.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/sampling/rng.hpp"

namespace fp {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Eqs. 11-14 as the paper writes them: the spherical triangle cut by the three edges from the vertex.
double solid_angle_by_eqs_11_14(const Vec3& u, const Vec3& v, const Vec3& w) {
  const double a = std::acos(v.normalized().dot(w.normalized())), b = std::acos(u.normalized().dot(w.normalized())),
               c = std::acos(u.normalized().dot(v.normalized()));
  const double alpha = std::acos((std::cos(a) - std::cos(b) * std::cos(c)) / (std::sin(b) * std::sin(c)));
  const double beta = std::acos((std::cos(b) - std::cos(c) * std::cos(a)) / (std::sin(c) * std::sin(a)));
  const double gamma = std::acos((std::cos(c) - std::cos(a) * std::cos(b)) / (std::sin(a) * std::sin(b)));
  return alpha + beta + gamma - kPi;
}

TEST(TetVoid, SolidAnglesAgreeWithTheSphericalTriangleOfThePaper) {
  // The corner of a cube: an eighth of the sphere.
  EXPECT_NEAR(solid_angle(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()), kPi / 2, 1e-15);
  // A regular tetrahedron's vertex: arccos(23/27).
  const Vec3 p[4] = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  EXPECT_NEAR(solid_angle(p[1] - p[0], p[2] - p[0], p[3] - p[0]), std::acos(23.0 / 27.0), 1e-15);
  Rng rng(3);
  for (int t = 0; t < 1000; ++t) {
    Vec3 u, v, w;
    for (int a = 0; a < 3; ++a) u[a] = rng.uniform(-1, 1), v[a] = rng.uniform(-1, 1), w[a] = rng.uniform(-1, 1);
    EXPECT_NEAR(solid_angle(u, v, w), solid_angle_by_eqs_11_14(u, v, w), 1e-9) << t;
  }
}

TEST(TetVoid, VoidMatchesABruteForceCount) {
  // Regular tetrahedron of edge 2 with spheres touching along its edges (r = 1), and a
  // polydisperse one whose spheres stay in their corners.
  const std::array<Vec3, 4> regular = {Vec3(1, 1, 1) / std::sqrt(2.0), Vec3(1, -1, -1) / std::sqrt(2.0),
                                       Vec3(-1, 1, -1) / std::sqrt(2.0), Vec3(-1, -1, 1) / std::sqrt(2.0)};
  const std::array<Vec3, 4> skew = {Vec3(0, 0, 0), Vec3(3, 0.2, 0), Vec3(0.5, 2.6, 0.1), Vec3(1, 0.8, 2.4)};
  for (const auto& [c, r] : {std::pair{regular, std::array<double, 4>{1, 1, 1, 1}},
                             std::pair{skew, std::array<double, 4>{0.9, 1.1, 0.7, 0.5}}}) {
    const double volume = std::abs((c[1] - c[0]).cross(c[2] - c[0]).dot(c[3] - c[0])) / 6.0;
    // Uniform points in the tetrahedron (sorted barycentric coordinates), counted outside every sphere.
    Rng rng(7);
    const int n = 400000;
    int outside = 0;
    for (int k = 0; k < n; ++k) {
      double s[3] = {rng.uniform01(), rng.uniform01(), rng.uniform01()};
      std::sort(s, s + 3);
      const Vec3 x = c[0] * s[0] + c[1] * (s[1] - s[0]) + c[2] * (s[2] - s[1]) + c[3] * (1 - s[2]);
      bool in = false;
      for (int i = 0; i < 4 && !in; ++i) in = (x - c[static_cast<std::size_t>(i)]).norm() < r[static_cast<std::size_t>(i)];
      outside += !in;
    }
    const double brute = volume * outside / n;
    const double sigma = volume * std::sqrt(0.25 / n);
    EXPECT_NEAR(tet_void_volume(c, r), brute, 4 * sigma) << "volume " << volume;
    EXPECT_GT(tet_void_volume(c, r), 0);
  }
  // No spheres: the whole tetrahedron.
  EXPECT_NEAR(tet_void_volume(skew, {0, 0, 0, 0}), std::abs((skew[1] - skew[0]).cross(skew[2] - skew[0]).dot(skew[3] - skew[0])) / 6.0, 1e-15);
}

TEST(TetVoid, TriangleVoidIsTheAreaMinusTheSectors) {
  // Three mutually touching unit disks: the curvilinear triangle between them, sqrt(3) - pi / 2.
  const std::array<Vec2, 3> tri = {Vec2(0, 0), Vec2(2, 0), Vec2(1, std::sqrt(3.0))};
  EXPECT_NEAR(triangle_void_area(tri, {1, 1, 1}), std::sqrt(3.0) - kPi / 2, 1e-15);
  EXPECT_NEAR(simplex_void_measure<2>(tri, {0, 0, 0}), std::sqrt(3.0), 1e-15);
  // A right triangle, disks of different radii in their corners: sectors of pi/2, pi/4, pi/4.
  const std::array<Vec2, 3> right = {Vec2(0, 0), Vec2(4, 0), Vec2(0, 4)};
  EXPECT_NEAR(triangle_void_area(right, {1, 0.5, 2}), 8 - (kPi / 4 * 1 + kPi / 8 * 0.25 + kPi / 8 * 4), 1e-14);
}

}  // namespace
}  // namespace fp
