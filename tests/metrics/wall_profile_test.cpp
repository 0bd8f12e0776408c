// The wall profile (wall_profile.hpp): shells of the container by distance from its boundary, in
// closed form for balls against a box's faces, sampled for particles of any shape, and adding up
// to the container's solid.
#include "core/metrics/wall_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/box_container.hpp"

namespace fp {
namespace {

// The measure of the shell [a, b) from the boundary of the box [0, L]^3.
double box_shell(double L, double a, double b) { return std::pow(L - 2 * a, 3) - std::pow(L - 2 * b, 3); }
// The volume of a ball of radius r below height h (0 <= h <= 2r) above its lowest point.
double cap(double r, double h) { return kPi * h * h * (3 * r - h) / 3; }

TEST(WallProfile, OneBallOnTheFloorInClosedForm) {
  // A ball of radius 1 resting on the floor of a box of side 10, far from the other faces: shell
  // k of width 0.25 holds the slice of the ball between heights k/4 and (k+1)/4.
  const double L = 10, r = 1, w = 0.25;
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(L));
  Packing<3> p;
  p.add(Vec3(5, 5, r), r);
  const WallProfile prof = wall_profile<3>(p, box, w, 8);
  ASSERT_EQ(prof.vf.size(), 8u);
  EXPECT_EQ(prof.width, w);
  for (std::size_t k = 0; k < 8; ++k) {
    const double a = k * w, b = a + w;
    EXPECT_NEAR(prof.vf[k].value, (cap(r, b) - cap(r, a)) / box_shell(L, a, b), 1e-12) << k;
    EXPECT_EQ(prof.vf[k].std_error, 0.0);
    EXPECT_DOUBLE_EQ(prof.middle(k), a + w / 2);
  }
  // The whole ball lies within 2 of the floor: the layer holds all of it.
  EXPECT_NEAR(prof.layer.value, (4.0 / 3 * kPi) / box_shell(L, 0, 2), 1e-12);
}

TEST(WallProfile, ShellsAndCoreAddUpToTheContainer) {
  // Balls on a lattice filling a box: the shells' solid plus the core's is the container's.
  const double L = 6;
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(L));
  Packing<3> p;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) p.add(Vec3(i + 0.5, j + 0.5, k + 0.5), 0.45);
  const WallProfile prof = wall_profile<3>(p, box, 0.25, 8);
  ASSERT_EQ(prof.vf.size(), 8u);
  double solid = 0;
  for (std::size_t k = 0; k < prof.vf.size(); ++k) solid += prof.vf[k].value * box_shell(L, k * 0.25, (k + 1) * 0.25);
  const RegionVolumeFraction core = vf_region<3>(p, box, 2.0);
  solid += core.vf.value * core.measure.value;
  EXPECT_NEAR(solid, 216 * 4.0 / 3 * kPi * std::pow(0.45, 3), 1e-9);
  // The layer is the shells together.
  EXPECT_NEAR(prof.layer.value * box_shell(L, 0, 2) + core.vf.value * core.measure.value, solid, 1e-9);
}

TEST(WallProfile, ParticlesOfAnyShapeAreSampled) {
  // Cubes of side 1 lying flat on the floor of a box of side 10 (a 4 x 4 tile, not touching the
  // other walls): every shell within 1 of the floor holds 16 w of their volume; none beyond.
  const double L = 10, w = 0.25;
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(L));
  RegionBodies<3> cubes;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      cubes.centres.push_back(Vec3(3.5 + i, 3.5 + j, 0.5));
      cubes.bounding_radii.push_back(std::sqrt(3.0) / 2);
      cubes.measures.push_back(1.0);
    }
  cubes.contains = [&](std::size_t i, const Vec3& x) { return ((x - cubes.centres[i]).cwiseAbs().array() <= 0.5).all(); };
  const WallProfile prof = wall_profile<3>(cubes, box, w, 8);
  ASSERT_EQ(prof.vf.size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    const double expect = k < 4 ? 16 * w / box_shell(L, k * w, (k + 1) * w) : 0.0;
    EXPECT_NEAR(prof.vf[k].value, expect, 4 * prof.vf[k].std_error + 1e-12) << k;
    if (k < 4) {
      EXPECT_GT(prof.vf[k].std_error, 0.0);
    }
  }
}

TEST(WallProfile, AContainerThinnerThanTheShellsEndsThem) {
  const BoxContainer<3> slab(Vec3::Zero(), Vec3(10, 10, 1));
  Packing<3> p;
  p.add(Vec3(5, 5, 0.5), 0.5);
  const WallProfile prof = wall_profile<3>(p, slab, 0.25, 8);
  EXPECT_EQ(prof.vf.size(), 2u);  // half the thickness
  EXPECT_THROW(wall_profile<3>(p, slab, 0.0, 8), std::invalid_argument);
}

}  // namespace
}  // namespace fp
