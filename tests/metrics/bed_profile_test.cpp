// The bed's profile against hand-worked cases: slab solids by integrating each sphere's sections,
// a simple cubic lattice whose bulk is pi / 6, the surface's columns, and the QMC path for
// particles of any shape against the closed form.
#include "core/metrics/bed_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/geometry/box_container.hpp"

namespace fp {
namespace {

/// The volume of a ball of radius r whose centre is at height c, between heights a and b, by
/// the midpoint rule over its disk sections.
double ball_between(double r, double c, double a, double b) {
  a = std::max(a, c - r), b = std::min(b, c + r);
  if (!(b > a)) return 0.0;
  const int n = 20000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double z = a + (i + 0.5) * (b - a) / n - c;
    sum += kPi * (r * r - z * z) * (b - a) / n;
  }
  return sum;
}

std::shared_ptr<const BoxContainer<3>> box(double x, double y, double z) {
  return std::make_shared<const BoxContainer<3>>(Vec3::Zero(), Vec3(x, y, z));
}

TEST(BedProfile, SlabsHoldEachSpheresSections) {
  const BedRegion<3> bed(box(4, 4, 3), Vec3(0, 0, 1), 1.0, BedSurface::Free);
  Packing<3> p;
  p.add(Vec3(1.5, 1.5, 0.25), 0.25);  // on the floor
  p.add(Vec3(2.5, 2.5, 0.6), 0.2);    // across three slabs
  p.add(Vec3(0.5, 3.5, 0.3), 0.25);   // in a column against the walls: no surface figure
  const BedProfile prof = bed_profile<3>(p, bed, 0.25);
  ASSERT_EQ(prof.vf.size(), 8u);  // slabs of r_max / 2 = 0.125
  EXPECT_DOUBLE_EQ(prof.width, 0.125);
  double total = 0.0;
  for (std::size_t k = 0; k < 8; ++k) {
    const double lo = 0.125 * k, hi = lo + 0.125;
    const double expected =
        (ball_between(0.25, 0.25, lo, hi) + ball_between(0.2, 0.6, lo, hi) + ball_between(0.25, 0.3, lo, hi)) / (16 * 0.125);
    EXPECT_NEAR(prof.vf[k].value, expected, 1e-8) << "slab " << k;
    EXPECT_EQ(prof.vf[k].std_error, 0.0);
    EXPECT_DOUBLE_EQ(prof.middle(k), lo + 0.0625);
    total += prof.vf[k].value * 16 * 0.125;
  }
  EXPECT_NEAR(total, 4.0 / 3 * kPi * (2 * 0.25 * 0.25 * 0.25 + 0.2 * 0.2 * 0.2), 1e-14);
  // Two columns of 4 r_max = 1 clear of the walls: tops 0.5 and 0.8.
  EXPECT_EQ(prof.surface.columns, 2u);
  EXPECT_DOUBLE_EQ(prof.surface.min, 0.5);
  EXPECT_DOUBLE_EQ(prof.surface.max, 0.8);
  EXPECT_DOUBLE_EQ(prof.surface.mean, 0.65);
  EXPECT_NEAR(prof.surface.std_dev, 0.15, 1e-15);
  // The bed is 1 high: no slab lies 2 r_max = 0.5 from both floor and level.
  EXPECT_TRUE(std::isnan(prof.bulk.value));
}

TEST(BedProfile, SimpleCubicLatticeHasItsBulkUpToItsSurface) {
  // Spheres of radius 0.25 on a lattice of 0.5 in a 4 x 4 bed 2 high: every whole period holds
  // pi / 6 of solid; the bulk (0.5 to 1.5) and the top layer (1.5 to 2) are whole periods.
  const BedRegion<3> bed(box(4, 4, 5), Vec3(0, 0, 1), 2.0, BedSurface::Flat);
  Packing<3> p;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 4; ++k) p.add(Vec3(0.25 + 0.5 * i, 0.25 + 0.5 * j, 0.25 + 0.5 * k), 0.25);
  const BedProfile prof = bed_profile<3>(p, bed, 0.25);
  ASSERT_EQ(prof.vf.size(), 16u);
  EXPECT_NEAR(prof.bulk.value, kPi / 6, 1e-14);
  EXPECT_NEAR(prof.top_layer.value, kPi / 6, 1e-14);
  // Each lattice layer's slabs: 0.125 at the sphere's ends, more through its middle.
  for (std::size_t k = 0; k < 16; ++k)
    EXPECT_NEAR(prof.vf[k].value, prof.vf[k % 4].value, 1e-13);
  EXPECT_GT(prof.vf[1].value, 2 * prof.vf[0].value);
  // Read down from the level, the first slab past half the bulk is the second from the top.
  EXPECT_GT(prof.half_bulk_height, 1.75);
  EXPECT_LE(prof.half_bulk_height, 2.0);
  EXPECT_EQ(prof.surface.columns, 4u);  // of the 16, those clear of the walls
  EXPECT_DOUBLE_EQ(prof.surface.min, 2.0);
  EXPECT_DOUBLE_EQ(prof.surface.std_dev, 0.0);
}

TEST(BedProfile, BodiesOfAnyShapeAgreeWithTheClosedFormWithinTheirError) {
  const BedRegion<3> bed(box(2, 2, 5), Vec3(0, 0, 1), 1.6, BedSurface::Free);
  Packing<3> p;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 5; ++k) p.add(Vec3(0.4 + 0.6 * i, 0.4 + 0.6 * j, 0.2 + 0.3 * k + 0.01 * i), 0.15 + 0.01 * j);
  RegionBodies<3> bodies;
  for (std::size_t i = 0; i < p.size(); ++i) {
    bodies.centres.push_back(p.centers[i]);
    bodies.bounding_radii.push_back(p.radii[i]);
    bodies.measures.push_back(4.0 / 3 * kPi * std::pow(p.radii[i], 3));
  }
  bodies.contains = [&](std::size_t i, const Vec3& x) { return (x - p.centers[i]).norm() <= p.radii[i]; };
  const double r_max = 0.17;
  const BedProfile exact = bed_profile<3>(p, bed, r_max);
  const BedProfile sampled = bed_profile<3>(bodies, bed, r_max, QmcOptions{});
  ASSERT_EQ(exact.vf.size(), sampled.vf.size());
  double largest_error = 0.0;  // the sampled path did sample
  for (std::size_t k = 0; k < exact.vf.size(); ++k) {
    largest_error = std::max(largest_error, sampled.vf[k].std_error);
    EXPECT_NEAR(sampled.vf[k].value, exact.vf[k].value, 5 * sampled.vf[k].std_error + 1e-12) << "slab " << k;
  }
  EXPECT_GT(largest_error, 0.0);
  EXPECT_NEAR(sampled.bulk.value, exact.bulk.value, 5 * sampled.bulk.std_error + 1e-12);
  EXPECT_EQ(sampled.surface.columns, 0u);  // without the particles' tops, no surface figure
  // With them (each sphere's centre height plus its radius), the spheres' own surface figure.
  std::vector<double> tops;
  for (std::size_t i = 0; i < p.size(); ++i) tops.push_back(p.centers[i].z() + p.radii[i]);
  const BedProfile topped = bed_profile<3>(bodies, bed, r_max, QmcOptions{}, tops);
  EXPECT_GT(topped.surface.columns, 0u);
  EXPECT_EQ(topped.surface.columns, exact.surface.columns);
  EXPECT_DOUBLE_EQ(topped.surface.mean, exact.surface.mean);
  EXPECT_DOUBLE_EQ(topped.surface.min, exact.surface.min);
}

}  // namespace
}  // namespace fp
