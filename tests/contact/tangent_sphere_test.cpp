// The sphere (disk) touching D + 1 others from outside (paper 000 Eqs. 1-9): built around a
// known sphere, the configuration gives it back; every solution touches every sphere within
// 1e-10 relative (the issue asks 1e-9); scaled by 2^+-60 the same digits; shifted by 1e9 as
// tangent as coordinates of 1e9 allow; radius ratios of 1000; coplanar centres give none.
#include "contact/tangent_sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/sampling/rng.hpp"

namespace fp {
namespace {

template <int D>
Vec<D> random_direction(Rng& rng) {
  for (;;) {
    Vec<D> v;
    for (int a = 0; a < D; ++a) v[a] = rng.uniform(-1, 1);
    if (v.norm() > 0.1 && v.norm() <= 1) return v.normalized();
  }
}

// D + 1 spheres of radii r_i touching the sphere (x, r) from outside, in random directions.
template <int D>
void around(Rng& rng, const Vec<D>& x, double r, double r_lo, double r_hi, std::array<Vec<D>, D + 1>& c,
            std::array<double, D + 1>& radii) {
  for (int i = 0; i <= D; ++i) {
    const auto k = static_cast<std::size_t>(i);
    radii[k] = r_lo * std::pow(r_hi / r_lo, rng.uniform01());
    c[k] = x + random_direction<D>(rng) * (r + radii[k]);
  }
}

template <int D>
double worst_tangency(const TangentSphere<D>& s, const std::array<Vec<D>, D + 1>& c, const std::array<double, D + 1>& radii) {
  double worst = 0;
  for (int i = 0; i <= D; ++i) {
    const auto k = static_cast<std::size_t>(i);
    worst = std::max(worst, std::abs((s.centre - c[k]).norm() - s.radius - radii[k]) / std::min(s.radius, radii[k]));
  }
  return worst;
}

template <int D>
void recovers_known_spheres(double r_lo, double r_hi, std::uint64_t seed) {
  Rng rng(seed);
  int found = 0, trials = 0;
  for (int t = 0; t < 2000; ++t) {
    const double r = r_lo * std::pow(r_hi / r_lo, rng.uniform01());
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = rng.uniform(-5, 5);
    std::array<Vec<D>, D + 1> c;
    std::array<double, D + 1> radii;
    around<D>(rng, x, r, r_lo, r_hi, c, radii);
    const TangentSpheres<D> s = spheres_tangent_to<D>(c, radii);
    ++trials;
    bool hit = false;
    for (int k = 0; k < s.count; ++k) {
      const TangentSphere<D>& q = s.at[static_cast<std::size_t>(k)];
      EXPECT_GT(q.radius, 0);
      EXPECT_LE(worst_tangency<D>(q, c, radii), 1e-10) << "trial " << t;
      hit |= std::abs(q.radius - r) <= 1e-9 * r && (q.centre - x).norm() <= 1e-9 * r;
    }
    found += hit;
  }
  // Nearly coplanar draws (the spheres all on one side) are ill-conditioned or refused; the rest
  // give the sphere back.
  EXPECT_GE(found, trials * 95 / 100) << found << " of " << trials;
}

TEST(TangentSphere, RecoversTheSphereItsNeighboursTouch3D) {
  recovers_known_spheres<3>(0.5, 1.0, 1);
  recovers_known_spheres<3>(0.01, 10.0, 2);  // radius ratios up to 1000
}

TEST(TangentSphere, RecoversTheDiskItsNeighboursTouch2D) {
  recovers_known_spheres<2>(0.5, 1.0, 3);
  recovers_known_spheres<2>(0.01, 10.0, 4);
}

TEST(TangentSphere, ScaledAndShiftedConfigurationsGiveTheSameDigits) {
  Rng rng(5);
  for (int t = 0; t < 200; ++t) {
    std::array<Vec3, 4> c;
    std::array<double, 4> radii;
    around<3>(rng, Vec3::Zero(), rng.uniform(0.5, 1.0), 0.5, 1.0, c, radii);
    const TangentSpheres<3> plain = spheres_tangent_to<3>(c, radii);
    for (const int e : {-60, 60}) {
      const double s = std::ldexp(1.0, e);
      std::array<Vec3, 4> cs = c;
      std::array<double, 4> rs = radii;
      for (int i = 0; i < 4; ++i) cs[static_cast<std::size_t>(i)] *= s, rs[static_cast<std::size_t>(i)] *= s;
      const TangentSpheres<3> scaled = spheres_tangent_to<3>(cs, rs);
      ASSERT_EQ(scaled.count, plain.count);
      for (int k = 0; k < plain.count; ++k) {  // a power of two scales every operation exactly
        EXPECT_EQ(scaled.at[static_cast<std::size_t>(k)].radius, plain.at[static_cast<std::size_t>(k)].radius * s);
        EXPECT_EQ(scaled.at[static_cast<std::size_t>(k)].centre, plain.at[static_cast<std::size_t>(k)].centre * s);
      }
    }
    // 1e9 away: the solver works relative to the first centre, so its solutions touch the
    // shifted spheres as closely as coordinates of 1e9 can say (their spacing is 1.2e-7), and
    // none is lost (squaring 1e9 in place would leave no digit of the offsets).
    const Vec3 far(1e9, -1e9, 1e9);
    std::array<Vec3, 4> cf = c;
    for (Vec3& p : cf) p += far;
    const TangentSpheres<3> shifted = spheres_tangent_to<3>(cf, radii);
    ASSERT_EQ(shifted.count, plain.count);
    for (int k = 0; k < shifted.count; ++k) {
      EXPECT_LE(worst_tangency<3>(shifted.at[static_cast<std::size_t>(k)], cf, radii), 2e-6);
      EXPECT_NEAR(shifted.at[static_cast<std::size_t>(k)].radius, plain.at[static_cast<std::size_t>(k)].radius,
                  1e-4 * plain.at[static_cast<std::size_t>(k)].radius);
    }
  }
}

TEST(TangentSphere, CoplanarCentresHaveNoSolution) {
  const std::array<Vec3, 4> c = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(2, 2, 0)};
  EXPECT_EQ((spheres_tangent_to<3>(c, {1, 1, 1, 1}).count), 0);
  const std::array<Vec2, 3> l = {Vec2(0, 0), Vec2(1, 0), Vec2(3, 0)};
  EXPECT_EQ((spheres_tangent_to<2>(l, {0.4, 0.4, 0.4}).count), 0);
  // Three mutually touching unit disks: the small disk in their middle (Soddy), r = 2/sqrt(3) - 1,
  // and no other with a positive radius.
  const std::array<Vec2, 3> tri = {Vec2(0, 0), Vec2(2, 0), Vec2(1, std::sqrt(3.0))};
  const TangentSpheres<2> soddy = spheres_tangent_to<2>(tri, {1, 1, 1});
  ASSERT_GE(soddy.count, 1);
  EXPECT_NEAR(soddy.at[0].radius, 2 / std::sqrt(3.0) - 1, 1e-15);
  EXPECT_NEAR((soddy.at[0].centre - Vec2(1, 1 / std::sqrt(3.0))).norm(), 0, 1e-15);
}

// Walls as planes: a sphere touching three spheres and a plane (a box face), two and two planes
// (an edge), one and three planes (a corner), built around a known sphere; the plane rows are
// exact, so the solution touches each body within 1e-10 relative; with radius ratios of 1000.
TEST(TangentSphere, PlanesStandForWalls) {
  Rng rng(11);
  int found = 0, trials = 0;
  for (int t = 0; t < 3000; ++t) {
    const int planes = 1 + t % 3;
    const double r = 0.01 * std::pow(1000.0, rng.uniform01());
    Vec3 x;
    for (int a = 0; a < 3; ++a) x[a] = rng.uniform(-5, 5);
    std::array<TangentBody<3>, 4> b;
    std::array<Vec3, 3> axes = {random_direction<3>(rng), Vec3::Zero(), Vec3::Zero()};
    axes[1] = axes[0].cross(random_direction<3>(rng)).normalized();
    axes[2] = axes[0].cross(axes[1]);
    for (int i = 0; i < 4; ++i) {
      if (i < planes) {  // mutually perpendicular walls at distance r, normals towards x
        const Vec3 n = axes[static_cast<std::size_t>(i)];
        b[static_cast<std::size_t>(i)] = TangentBody<3>::wall(x - r * n + rng.uniform(-3, 3) * axes[static_cast<std::size_t>((i + 1) % 3)], n);
      } else {  // spheres on the open side of every wall
        const double ri = 0.01 * std::pow(1000.0, rng.uniform01());
        Vec3 u = random_direction<3>(rng);
        for (int k = 0; k < planes; ++k) u += 1.5 * axes[static_cast<std::size_t>(k)];
        b[static_cast<std::size_t>(i)] = TangentBody<3>::sphere(x + u.normalized() * (r + ri), ri);
      }
    }
    const TangentSpheres<3> s = spheres_tangent_to<3>(b);
    ++trials;
    bool hit = false;
    for (int k = 0; k < s.count; ++k) {
      const TangentSphere<3>& q = s.at[static_cast<std::size_t>(k)];
      for (const TangentBody<3>& body : b) {
        const double gap = body.plane ? body.normal.dot(q.centre - body.point) - q.radius
                                      : (q.centre - body.point).norm() - q.radius - body.radius;
        EXPECT_LE(std::abs(gap), 1e-10 * (body.plane ? q.radius : std::min(q.radius, body.radius))) << "trial " << t;
      }
      hit |= std::abs(q.radius - r) <= 1e-9 * r && (q.centre - x).norm() <= 1e-9 * r;
    }
    found += hit;
  }
  EXPECT_GE(found, trials * 95 / 100) << found << " of " << trials;
  // Only planes: no sphere to square; refused.
  std::array<TangentBody<2>, 3> walls = {TangentBody<2>::wall(Vec2(0, 0), Vec2(1, 0)), TangentBody<2>::wall(Vec2(0, 0), Vec2(0, 1)),
                                         TangentBody<2>::wall(Vec2(1, 1), Vec2(-1, 0))};
  EXPECT_EQ(spheres_tangent_to<2>(walls).count, 0);
  // 2D: the disk in the corner of two walls touching a unit disk at (3, 3): r = 3 (2 - sqrt(2)) ... by brute force.
  walls[2] = TangentBody<2>::sphere(Vec2(3, 3), 1);
  const TangentSpheres<2> corner = spheres_tangent_to<2>(walls);
  ASSERT_GE(corner.count, 1);
  const TangentSphere<2>& q = corner.at[0];
  EXPECT_NEAR(q.centre.x(), q.radius, 1e-14);
  EXPECT_NEAR(q.centre.y(), q.radius, 1e-14);
  EXPECT_NEAR((q.centre - Vec2(3, 3)).norm(), q.radius + 1, 1e-14);
}

}  // namespace
}  // namespace fp
