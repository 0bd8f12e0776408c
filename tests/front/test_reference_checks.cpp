// The independent checks used by the front tests must themselves catch what they claim to:
// an overlap, a particle sticking out, a contact; and the brute-force distances must agree
// with the closed forms where both apply.
#include <gtest/gtest.h>

#include "core/sampling/rng.hpp"
#include "front_checks.hpp"

namespace fptest {
namespace {

TEST(ReferenceChecks, OverlapAndContactsFoundWhateverTheOrder) {
  fp::Packing<3> P;
  P.add(Vec3(0, 0, 0), 1.0);
  P.add(Vec3(5, 0, 0), 1.0);
  P.add(Vec3(0, 0, 2.0 - 1e-6), 1.0);  // overlaps particle 0 by 1e-6 (sweep axis is x: same x)
  P.add(Vec3(7, 0, 0), 1.0);           // touches particle 1 exactly
  const OverlapReport o = overlaps<3>(P);
  EXPECT_NEAR(o.max_over_rmin, 1e-6, 1e-15);
  EXPECT_EQ(o.worst_i, 0u);
  EXPECT_EQ(o.worst_j, 2u);
  const std::vector<int> z = particle_contacts<3>(P, 1e-9);
  EXPECT_EQ(z, (std::vector<int>{0, 1, 0, 1}));
}

TEST(ReferenceChecks, SweepFindsEveryPairOfARandomCloud) {
  fp::Rng rng(5);
  fp::Packing<2> P;
  for (int i = 0; i < 300; ++i) P.add(Vec2(rng.uniform01(), rng.uniform01()), 0.001 + 0.05 * rng.uniform01());
  double brute = 0;
  const double rmin = *std::min_element(P.radii.begin(), P.radii.end());
  for (std::size_t i = 0; i < P.size(); ++i)
    for (std::size_t j = i + 1; j < P.size(); ++j)
      brute = std::max(brute, (P.radii[i] + P.radii[j] - (P.centers[i] - P.centers[j]).norm()) / rmin);
  EXPECT_EQ(overlaps<2>(P).max_over_rmin, brute);
}

TEST(ReferenceChecks, ContainmentFlagsAParticleSticking) {
  fp::Packing<3> P;
  P.add(Vec3(0.5, 0.5, 0.5), 0.5);           // tangent to all six faces
  P.add(Vec3(0.2, 0.5, 0.5), 0.2 + 1e-7);    // sticks out of x = 0 by 1e-7
  const ContainmentReport c = containment<3>(P, box_distance<3>(Vec3::Zero(), Vec3::Ones()), 1e-9);
  EXPECT_EQ(c.worst, 1u);
  EXPECT_NEAR(c.max_outside_over_r, 1e-7 / (0.2 + 1e-7), 1e-12);
  EXPECT_EQ(c.touching_walls, 1u);
}

TEST(ReferenceChecks, MeshAndPolygonDistancesAgreeWithTheBox) {
  // The unit cube as 12 triangles (mixed orientation is fine for the winding number's sign),
  // and the unit square as a polygon.
  const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::vector<std::array<int, 3>> t = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                             {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  const auto mesh = mesh_distance(v, t);
  const auto box3 = box_distance<3>(Vec3::Zero(), Vec3::Ones());
  const auto poly = polygon_distance({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const auto box2 = box_distance<2>(Vec2::Zero(), Vec2::Ones());
  fp::Rng rng(9);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p(rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5));
    EXPECT_NEAR(mesh(p, Vec3::Zero()), box3(p, Vec3::Zero()), 1e-14) << p.transpose();
    const Vec2 q = p.head<2>();
    EXPECT_NEAR(poly(q, Vec2::Zero()), box2(q, Vec2::Zero()), 1e-14) << q.transpose();
    // In a frame with origin o the same point is p - o.
    const Vec3 o(0.5, -0.25, 1.0);
    EXPECT_NEAR(mesh(p - o, o), box3(p, Vec3::Zero()), 1e-14);
    EXPECT_NEAR(poly(q - o.head<2>(), o.head<2>()), box2(q, Vec2::Zero()), 1e-14);
  }
  const auto cyl = cylinder_distance(Vec3::Zero(), Vec3(0, 0, 2), 1.0, 2.0);
  EXPECT_DOUBLE_EQ(cyl(Vec3(0, 0, 1), Vec3::Zero()), -1.0);
  EXPECT_DOUBLE_EQ(cyl(Vec3(0.5, 0, 1.8), Vec3::Zero()), -0.2);
  EXPECT_DOUBLE_EQ(cyl(Vec3(2, 0, 3), Vec3::Zero()), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(cyl(Vec3(-1, 0, -1), Vec3(3, 0, 4)), std::sqrt(2.0));
}

}  // namespace
}  // namespace fptest
