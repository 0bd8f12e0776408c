// Plane sections of a packing (core/metrics/packing_sections.hpp), against a hand-checked case:
// three spheres in a box [0, 2]^3 cut by the planes x = 1, y = 1, z = 1 (each sphere's section a
// disk of radius sqrt(r^2 - h^2), a sphere the plane misses left out), the box's outline a square
// of perimeter 8 on its walls, a cylinder's a circle, a 2D packing drawn whole; absolute
// coordinates far from the origin.
#include "core/metrics/packing_sections.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/cylinder_container.hpp"

namespace fp {
namespace {

double length(const PackingSection& s) {
  double sum = 0;
  for (const auto& g : s.outline) sum += std::hypot(g[2] - g[0], g[3] - g[1]);
  return sum;
}

TEST(PackingSections, ThreeSpheresInABox) {
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(2.0));
  Packing<3> p;
  p.add(Vec3(1, 1, 1), 0.5);      // cut by every plane through its centre: radius 0.5
  p.add(Vec3(1.5, 1.5, 1.3), 0.5);  // z = 1 at h = 0.3: radius 0.4; x = 1, y = 1 at h = 0.5: missed
  p.add(Vec3(0.3, 0.3, 0.3), 0.2);  // missed by all
  const std::vector<PackingSection> s = packing_sections<3>(p, box, 200);
  ASSERT_EQ(s.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(s[k].normal_axis, k);
    EXPECT_EQ(s[k].offset, 1.0);
    EXPECT_NE(s[k].u_axis, k);
    EXPECT_NE(s[k].v_axis, k);
    EXPECT_LT(s[k].u_axis, s[k].v_axis);
    EXPECT_NEAR(length(s[k]), 8.0, 0.05) << k;
    for (const auto& g : s[k].outline)  // ends on the walls: the box's distance is linear along each
      for (int e = 0; e < 4; e += 2)
        EXPECT_LT(std::min({std::abs(g[e]), std::abs(g[e] - 2), std::abs(g[e + 1]), std::abs(g[e + 1] - 2)}), 1e-9);
  }
  ASSERT_EQ(s[2].disks.size(), 2u);
  EXPECT_EQ(s[2].disks[0].radius, 0.5);
  EXPECT_EQ(s[2].disks[0].size, 0.5);
  EXPECT_EQ(s[2].disks[1].u, 1.5);
  EXPECT_EQ(s[2].disks[1].v, 1.5);
  EXPECT_NEAR(s[2].disks[1].radius, 0.4, 1e-15);
  EXPECT_EQ(s[0].disks.size(), 1u);  // h = 0.5 = r: tangent, no section
  EXPECT_EQ(s[1].disks.size(), 1u);
  EXPECT_EQ(s[0].disks[0].u, 1.0);  // x = 1: drawn in (y, z)
  EXPECT_EQ(s[0].disks[0].v, 1.0);
}

TEST(PackingSections, ACylindersOutlineIsACircleAndA2DPackingIsDrawnWhole) {
  const CylinderContainer cylinder(Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, 2.0);
  const std::vector<PackingSection> s = packing_sections<3>(Packing<3>{}, cylinder, 400);
  EXPECT_NEAR(length(s[2]), 2 * M_PI, 0.01);  // z = 1: the circle
  EXPECT_NEAR(length(s[0]), 8.0, 0.05);       // x = 0: the 2 x 2 rectangle
  for (const auto& g : s[2].outline) EXPECT_NEAR(std::hypot(g[0], g[1]), 1.0, 2e-3);

  const BallContainer<2> disk(Vec2(1e9, -1e9), 1.0, Vec2(1e9, -1e9));  // centre and frame absolute
  Packing<2> p;
  p.origin = Vec2(1e9, -1e9);
  p.add(Vec2(0.25, 0), 0.1);
  p.add(Vec2(-0.5, 0.5), 0.2);
  const std::vector<PackingSection> flat = packing_sections<2>(p, disk, 400);
  ASSERT_EQ(flat.size(), 1u);
  ASSERT_EQ(flat[0].disks.size(), 2u);
  EXPECT_EQ(flat[0].disks[1].u, 1e9 - 0.5);  // absolute
  EXPECT_EQ(flat[0].disks[1].v, -1e9 + 0.5);
  EXPECT_EQ(flat[0].disks[1].radius, 0.2);
  EXPECT_NEAR(length(flat[0]), 2 * M_PI, 0.01);
  for (const auto& g : flat[0].outline) EXPECT_NEAR(std::hypot(g[0] - 1e9, g[1] + 1e9), 1.0, 2e-3);
}

}  // namespace
}  // namespace fp
