// CylinderContainer against closed forms computed in the cylinder's own frame.
#include "core/geometry/cylinder_container.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <set>

#include "core/sampling/rng.hpp"
#include "tests/geometry/reference_geometry.hpp"

namespace fp {
namespace {

/// A tilted cylinder and the rotation that takes world coordinates into its frame (axis -> z).
struct Tilted {
  Vec3 base{0.3, -0.2, 0.5};
  Vec3 axis = Vec3(1.0, 2.0, -0.5);  // not unit on purpose
  double R = 0.4, H = 1.3;
  Eigen::Quaterniond to_local = Eigen::Quaterniond::FromTwoVectors(axis.normalized(), Vec3::UnitZ());
  CylinderContainer make() const { return CylinderContainer(base, axis, R, H); }
  Vec3 local(const Vec3& p) const { return to_local * (p - base); }
  Vec3 world(const Vec3& q) const { return base + to_local.inverse() * q; }
};

/// Distances to the three surface patches, in the local frame: lateral, bottom disk, top disk.
std::array<double, 3> patch_distances(const Vec3& q, double R, double H) {
  const double rho = std::hypot(q.x(), q.y());
  const double out_r = std::max(0.0, rho - R);
  const double out_z = std::max({0.0, -q.z(), q.z() - H});
  return {std::hypot(rho - R, out_z), std::hypot(q.z(), out_r), std::hypot(q.z() - H, out_r)};
}

bool local_inside(const Vec3& q, double R, double H) {
  return q.z() >= 0 && q.z() <= H && q.x() * q.x() + q.y() * q.y() <= R * R;
}

Vec3 random_near(Rng& rng, const Tilted& t) {
  // Local box around the cylinder, mapped to the world.
  const Vec3 q(rng.uniform(-1.5 * t.R, 1.5 * t.R), rng.uniform(-1.5 * t.R, 1.5 * t.R), rng.uniform(-0.3, t.H + 0.3));
  return t.world(q);
}

TEST(CylinderContainer, InsideAndSignedDistanceMatchPatchDistances) {
  const Tilted t;
  const CylinderContainer cyl = t.make();
  Rng rng(31);
  int inside = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 p = random_near(rng, t);
    const Vec3 q = t.local(p);
    const auto d = patch_distances(q, t.R, t.H);
    const double dist = std::min({d[0], d[1], d[2]});
    const bool in = local_inside(q, t.R, t.H);
    if (dist > 1e-12) { EXPECT_EQ(cyl.inside(p), in); }
    EXPECT_NEAR(cyl.signed_distance(p), in ? -dist : dist, 1e-12);
    inside += in;
  }
  EXPECT_GT(inside, 1000);
}

TEST(CylinderContainer, MeasureBoundsInterior) {
  const Tilted t;
  const CylinderContainer cyl = t.make();
  EXPECT_NEAR(cyl.measure(), kPi * t.R * t.R * t.H, 1e-14);
  EXPECT_NEAR(cyl.axis().norm(), 1.0, 1e-15);
  EXPECT_NEAR(cyl.signed_distance(cyl.interior_point()), -t.R, 1e-12);
  // Bounds: every rim point inside, and the rims reach every side of the box.
  const Aabb<3> b = cyl.bounds();
  Vec3 lo = Vec3::Constant(1e9), hi = Vec3::Constant(-1e9);
  for (int k = 0; k < 20000; ++k) {
    const double phi = 2 * kPi * k / 20000;
    for (double z : {0.0, t.H}) {
      const Vec3 p = t.world(Vec3(t.R * std::cos(phi), t.R * std::sin(phi), z));
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  EXPECT_TRUE(((lo - b.lo).array() >= -1e-12).all());
  EXPECT_TRUE(((b.hi - hi).array() >= -1e-12).all());
  EXPECT_LT((lo - b.lo).maxCoeff(), 1e-6);
  EXPECT_LT((b.hi - hi).maxCoeff(), 1e-6);
  EXPECT_NE(cyl.describe().find("cylinder"), std::string::npos);
}

TEST(CylinderContainer, WallsNearAreExactlyThePatchesWithinReach) {
  const Tilted t;
  const CylinderContainer cyl = t.make();
  Rng rng(32);
  std::vector<Wall<3>> walls;
  int gap_checks = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 p = random_near(rng, t);
    const auto d = patch_distances(t.local(p), t.R, t.H);
    const double reach = rng.uniform(0.0, 0.5);
    walls.clear();
    cyl.walls_near(p, reach, walls);
    std::set<int> got;
    for (const auto& w : walls) {
      got.insert(w.id);
      EXPECT_EQ(w.kind, w.id == 0 ? WallKind::Cylinder : WallKind::Plane);
      if (w.id == 1) { EXPECT_NEAR(w.normal.dot(cyl.axis()), 1.0, 1e-15); }   // bottom cap faces up (inward)
      if (w.id == 2) { EXPECT_NEAR(w.normal.dot(cyl.axis()), -1.0, 1e-15); }  // top cap faces down
    }
    for (int k = 0; k < 3; ++k) {
      if (d[k] <= reach * (1 - 1e-12)) { EXPECT_TRUE(got.count(k)) << "patch " << k; }
      if (d[k] > reach * (1 + 1e-12)) { EXPECT_FALSE(got.count(k)) << "patch " << k; }
    }
    // Convex: inside, the walls within |sd| give the exact clearance of a ball.
    const double sd = cyl.signed_distance(p);
    if (sd < 0) {
      walls.clear();
      cyl.walls_near(p, -sd * (1 + 1e-12), walls);
      const double r = rng.uniform(0.0, -sd);
      double gap = std::numeric_limits<double>::infinity();
      for (const auto& w : walls) gap = std::min(gap, w.gap(p, r));
      EXPECT_NEAR(gap, -sd - r, 1e-12);
      ++gap_checks;
    }
  }
  EXPECT_GT(gap_checks, 500);
}

TEST(CylinderContainer, ContainsBallAgreesWithSignedDistance) {
  const Tilted t;
  const CylinderContainer cyl = t.make();
  Rng rng(33);
  int accepted = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 c = random_near(rng, t);
    const double r = rng.uniform(0.0, 0.3);
    const bool expected = cyl.signed_distance(c) <= -r + 1e-9 * r;
    EXPECT_EQ(cyl.contains_ball(c, r), expected);
    accepted += expected;
  }
  EXPECT_GT(accepted, 100);
}

TEST(CylinderContainer, ImpossibleParametersNameTheParameter) {
  const Vec3 o = Vec3::Zero(), z = Vec3::UnitZ();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  testref::expect_invalid([&] { CylinderContainer(o, Vec3::Zero(), 1.0, 1.0); }, {"axis", "non-zero"});
  testref::expect_invalid([&] { CylinderContainer(o, z, 0.0, 1.0); }, {"radius"});
  testref::expect_invalid([&] { CylinderContainer(o, z, 1.0, -2.0); }, {"height"});
  testref::expect_invalid([&] { CylinderContainer(o, z, 1.0, nan); }, {"height"});
  testref::expect_invalid([&] { CylinderContainer(Vec3(nan, 0, 0), z, 1.0, 1.0); }, {"base_center", "finite"});
  testref::expect_invalid([&] { CylinderContainer(o, Vec3(0, 0, nan), 1.0, 1.0); }, {"axis", "finite"});
}

}  // namespace
}  // namespace fp
