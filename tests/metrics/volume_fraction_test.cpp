// Volume fraction in a reference ball (paper 002 Sect. 5) and over the container, on lattices
// whose packing fraction is known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "core/metrics/lens.hpp"
#include "core/metrics/volume_fraction.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

TEST(VfReferenceSphere, SingleBallInsideAndStraddling) {
  Packing<3> p;
  p.add(Vec3(1.0, 2.0, 3.0), 0.5);
  EXPECT_NEAR(vf_reference_sphere(p, Vec3(1.2, 2.0, 3.0), 2.0), std::pow(0.5 / 2.0, 3), 1e-15);
  EXPECT_NEAR(vf_reference_sphere(p, Vec3(1.0, 4.2, 3.0), 2.0), lens_volume(0.5, 2.0, 2.2) / ball_measure<3>(2.0),
              1e-15);
  EXPECT_EQ(vf_reference_sphere(p, Vec3(1.0, 4.6, 3.0), 2.0), 0.0);
  Packing<2> q;
  q.add(Vec2(0.0, 0.0), 1.0);
  EXPECT_NEAR(vf_reference_sphere(q, Vec2(0.5, 0.0), 4.0), 1.0 / 16.0, 1e-15);
  EXPECT_THROW(vf_reference_sphere(q, Vec2(0, 0), 0.0), std::invalid_argument);
}

TEST(VfReferenceSphere, SimpleCubicIsPiOverSix) {
  // Touching unit-spaced spheres, reference ball well inside the 30^3 lattice, off the sites.
  const auto lat = test::simple_cubic(30, 1.0, Vec3(0.0, 0.0, 0.0));
  const double vf = vf_reference_sphere(lat.packing, Vec3(14.3, 14.6, 14.1), 11.0);
  EXPECT_NEAR(vf, kPi / 6.0, 1e-3);
  // Large coordinate offsets change nothing.
  const auto far = test::simple_cubic(30, 1.0, Vec3(1e6, 1e6, -1e6));
  EXPECT_NEAR(vf_reference_sphere(far.packing, Vec3(1e6 + 14.3, 1e6 + 14.6, -1e6 + 14.1), 11.0), vf, 1e-9);
}

TEST(VfReferenceSphere, FaceCentredCubicIs0_7405) {
  const auto lat = test::fcc(14, 0.5, Vec3(0.0, 0.0, 0.0));  // cubic cell 1, 14^3 cells
  const double vf = vf_reference_sphere(lat.packing, Vec3(6.71, 6.93, 7.12), 5.5);
  EXPECT_NEAR(vf, kPi / (3.0 * std::sqrt(2.0)), 1e-3);
}

TEST(VfReferenceSphere, HexagonalDisksAre0_9069) {
  const auto lat = test::hexagonal(120, 140, 1.0, Vec2(0.0, 0.0));
  const double vf = vf_reference_sphere(lat.packing, Vec2(60.3, 60.2), 45.0);
  EXPECT_NEAR(vf, kPi / (2.0 * std::sqrt(3.0)), 1e-3);
}

TEST(VfReferenceCurve, ThirtyOneEquispacedRadii) {
  const auto lat = test::simple_cubic(16, 1.0, Vec3(0.0, 0.0, 0.0));
  const Vec3 c(7.5, 7.5, 7.5);
  const auto curve = vf_reference_curve(lat.packing, c, 0.5, 7.0);
  ASSERT_EQ(curve.size(), 31u);
  EXPECT_EQ(curve.front().first, 0.5);
  EXPECT_EQ(curve.back().first, 7.0);
  for (std::size_t k = 0; k < curve.size(); ++k) {
    EXPECT_NEAR(curve[k].first, 0.5 + 6.5 * k / 30.0, 1e-14);
    EXPECT_EQ(curve[k].second, vf_reference_sphere(lat.packing, c, curve[k].first));
  }
  // Converges to pi / 6 as the reference ball grows.
  EXPECT_GT(std::abs(curve[2].second - kPi / 6.0), std::abs(curve.back().second - kPi / 6.0));
  EXPECT_NEAR(curve.back().second, kPi / 6.0, 5e-3);
  EXPECT_EQ(vf_reference_curve(lat.packing, c, 2.0, 3.0, 1).size(), 1u);
  EXPECT_THROW(vf_reference_curve(lat.packing, c, 2.0, 1.0), std::invalid_argument);
}

TEST(VfContainer, ExactOnALatticeThatTilesTheBox) {
  // n^3 spheres of radius 1/2 tile [0, n]^3 exactly: VF = pi / 6 to rounding.
  const auto lat = test::simple_cubic(25, 1.0, Vec3(0.5, 0.5, 0.5));
  EXPECT_NEAR(vf_container(lat.packing, 25.0 * 25.0 * 25.0), kPi / 6.0, 1e-14);
  Packing<2> sq;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 30; ++j) sq.add(Vec2(i + 0.5, j + 0.5), 0.5);
  EXPECT_NEAR(vf_container(sq, 40.0 * 30.0), kPi / 4.0, 1e-14);
  EXPECT_THROW(vf_container(sq, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace fp
