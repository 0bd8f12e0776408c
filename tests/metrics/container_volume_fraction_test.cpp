// VF of the container and of its core (container_volume_fraction.hpp, paper 000 Eq. 16 with the
// region as probe, paper 002 Eq. 2 for lens cuts): closed forms
// for single balls, lattices in boxes whose sides are whole periods (exact packing fractions:
// simple cubic pi/6, FCC pi/(3 sqrt 2), hexagonal disks pi/(2 sqrt 3)), and the QMC path checked
// against the exact one on the same shape.
#include "core/metrics/container_volume_fraction.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/cylinder_container.hpp"
#include "core/geometry/mesh_container.hpp"
#include "core/geometry/polygon_container.hpp"
#include "core/metrics/lens.hpp"
#include "core/metrics/volume_fraction.hpp"
#include "tests/metrics/analysis_test_util.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

// Within k standard errors, and within an absolute rounding allowance when the error is 0.
void expect_within_error(const Estimate& e, double exact, double k = 4.0) {
  EXPECT_NEAR(e.value, exact, k * e.std_error + 1e-12 * std::abs(exact)) << "std error " << e.std_error;
}

TEST(RegionVolumeFraction, OneBallCutByOneFaceIsACapInClosedForm) {
  const BoxContainer<3> box(Vec3(0, 0, 0), Vec3(10, 10, 10));
  Packing<3> p;
  p.add(Vec3(5.0, 5.0, 1.5), 1.0);  // the core (shrink 1) starts at z = 1: cut at t = r / 2
  const RegionVolumeFraction v = vf_region(p, box, 1.0);
  EXPECT_TRUE(v.exact);
  EXPECT_EQ(v.balls_cut_exact, 1u);
  // Inside part: 4/3 pi - cap(h = 1/2) = 4/3 pi - 5 pi / 24 = 9 pi / 8.
  EXPECT_NEAR(v.vf.value * 512.0, 9.0 * kPi / 8.0, 1e-13);
  EXPECT_EQ(v.measure.value, 512.0);
  EXPECT_EQ(v.method, "exact");

  // A centre on the face: half the ball; in 2D half the disk, and a segment at t = -r / 2.
  p.centers[0] = Vec3(5.0, 1.0, 5.0);
  EXPECT_NEAR(vf_region(p, box, 1.0).vf.value * 512.0, 2.0 * kPi / 3.0, 1e-13);
  const BoxContainer<2> rect(Vec2(0, 0), Vec2(10, 10));
  Packing<2> q;
  q.add(Vec2(5.0, 1.0), 1.0);
  EXPECT_NEAR(vf_region(q, rect, 1.0).vf.value * 64.0, kPi / 2.0, 1e-13);
  q.centers[0] = Vec2(5.0, 0.5);  // centre outside the core: the segment of height 1/2
  EXPECT_NEAR(vf_region(q, rect, 1.0).vf.value * 64.0, kPi / 3.0 - std::sqrt(3.0) / 4.0, 1e-13);
}

TEST(RegionVolumeFraction, BallContainerCoreCutsWithExactLenses) {
  const BallContainer<3> ball(Vec3(1, 2, 3), 10.0);
  Packing<3> p;
  p.add(Vec3(1, 2, 3), 2.0);        // inside the core (radius 8)
  p.add(Vec3(1 + 8.5, 2, 3), 1.0);  // straddles the core boundary
  p.add(Vec3(1, 2 - 8.5, 3), 0.5);  // touches it from outside: nothing
  const RegionVolumeFraction v = vf_region(p, ball, 2.0);
  EXPECT_TRUE(v.exact);
  EXPECT_EQ(v.balls_inside, 1u);
  EXPECT_EQ(v.balls_cut_exact, 1u);
  EXPECT_EQ(v.measure.value, ball_measure<3>(8.0));
  EXPECT_NEAR(v.vf.value, (ball_measure<3>(2.0) + lens_volume(1.0, 8.0, 8.5)) / ball_measure<3>(8.0), 1e-15);
}

TEST(RegionVolumeFraction, WholeContainerOfAValidPackingIsExactForEveryShape) {
  const auto lat = test::simple_cubic(6, 1.0, Vec3(0.5, 0.5, 0.5));
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(6.0));
  const CylinderContainer cyl(Vec3(3, 3, -0.1), Vec3(0, 0, 1), 4.5, 6.2);
  const BallContainer<3> ball(Vec3::Constant(3.0), 5.3);
  for (const Container<3>* c : std::initializer_list<const Container<3>*>{&box, &cyl, &ball}) {
    const RegionVolumeFraction v = vf_region(lat.packing, *c, 0.0);
    EXPECT_TRUE(v.exact) << c->describe();
    EXPECT_EQ(v.balls_inside, lat.packing.size());
    EXPECT_EQ(v.vf.value, vf_container(lat.packing, c->measure())) << c->describe();
  }
}

TEST(RegionVolumeFraction, BallsTangentToAWallUpToRoundingCountAsInside) {
  // Walls are bodies for the packer: a tangent ball crosses the wall by rounding (~1e-15 r).
  // That must not send it to sampling; a real crossing (1e-6 r) still must.
  auto lat = test::simple_cubic(6, 1.0, Vec3(0.5, 0.5, 0.5));  // the outer layers touch the box's walls
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(6.0));
  for (Vec3& c : lat.packing.centers) c.x() -= 1e-13;
  RegionVolumeFraction v = vf_region(lat.packing, box, 0.0);
  EXPECT_TRUE(v.exact);
  EXPECT_EQ(v.balls_inside, lat.packing.size());
  for (Vec3& c : lat.packing.centers) c.x() -= 1e-6;
  v = vf_region(lat.packing, box, 0.0);
  EXPECT_EQ(v.balls_cut_exact + v.balls_sampled, 36u);  // the x = 0 layer now really crosses

  // The generic path (cylinder): one ball tangent to the lateral wall, up to rounding.
  const CylinderContainer cyl(Vec3::Zero(), Vec3(0, 0, 1), 1.0, 2.0);
  Packing<3> one;
  one.add(Vec3(0.75 + 1e-13, 0, 1), 0.25);
  EXPECT_TRUE(vf_region(one, cyl, 0.0).exact);
  one.centers[0].x() += 1e-6;
  EXPECT_EQ(vf_region(one, cyl, 0.0).balls_sampled, 1u);
}

TEST(RegionVolumeFraction, SimpleCubicCoreIsPiOverSix) {
  // Sites at 0.3 + k: the core faces cut spheres, its edges too (those are sampled).
  const auto lat = test::simple_cubic(14, 1.0, Vec3::Constant(0.3));
  const auto box = test::container_around_core<3>(Vec3(1.55, 1.1, 1.7), Vec3::Ones(), Vec3(10, 9, 11), 1.0);
  const RegionVolumeFraction v = vf_region(lat.packing, box, 1.0);
  EXPECT_FALSE(v.exact);
  EXPECT_EQ(v.balls_cut_exact, 2u * (8 * 10 + 9 * 10 + 9 * 8));  // one face each
  EXPECT_EQ(v.balls_sampled, 4u * (10 + 8 + 9) + 8);             // edges and corners
  EXPECT_EQ(v.measure.value, 990.0);
  EXPECT_LT(v.vf.std_error, 3e-4);  // 116 of 1116 balls sampled, 32 points x 16 shifts each
  expect_within_error(v.vf, kPi / 6.0);
  EXPECT_NE(v.method.find("straddling balls"), std::string::npos) << v.method;
}

TEST(RegionVolumeFraction, FaceCentredCubicCoreIs0_7405) {
  const auto lat = test::fcc(12, 0.5, Vec3::Zero());  // cubic cell 1
  const double shrink = 2.0 * 0.5 / std::sqrt(2.0);
  const auto box = test::container_around_core<3>(Vec3(1.23, 1.37, 1.11), Vec3::Ones(), Vec3(9, 9, 9), shrink);
  const RegionVolumeFraction v = vf_region(lat.packing, box, shrink);
  EXPECT_LT(v.vf.std_error, 1e-4);
  expect_within_error(v.vf, kPi / (3.0 * std::sqrt(2.0)));
}

TEST(RegionVolumeFraction, HexagonalDiskCoreIs0_9069) {
  const auto lat = test::hexagonal(60, 60, 1.0, Vec2::Zero());  // rows of 1, period sqrt(3) in y
  const auto rect = test::container_around_core<2>(Vec2(10.37, 5.21), Vec2(1.0, std::sqrt(3.0)), Vec2(30, 20), 1.0);
  const RegionVolumeFraction v = vf_region(lat.packing, rect, 1.0);
  EXPECT_LT(v.vf.std_error, 1e-4);
  expect_within_error(v.vf, kPi / (2.0 * std::sqrt(3.0)));
}

TEST(RegionVolumeFraction, SampledCutsAgreeWithTheClosedFormOnTheSameSquare) {
  // The rectangle as a polygon takes the generic path: QMC measure and QMC cuts.
  Packing<2> p = test::jittered_lattice<2>(30, 0.3, 0.9, 0.05, 3);  // sites 0, 2, ..., 58
  const Vec2 lo(-1.0, -1.0), hi(59.0, 59.5);
  const BoxContainer<2> rect(lo, hi);
  const PolygonContainer poly({lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())});
  for (const double shrink : {0.0, 1.8}) {
    const RegionVolumeFraction exact = vf_region(p, rect, shrink);
    const RegionVolumeFraction sampled = vf_region(p, poly, shrink);
    EXPECT_EQ(sampled.exact, shrink == 0.0);  // no ball crosses the container itself
    EXPECT_EQ(sampled.balls_inside, exact.balls_inside);
    EXPECT_EQ(sampled.balls_sampled, exact.balls_cut_exact + exact.balls_sampled);
    expect_within_error(sampled.vf, exact.vf.value);
    expect_within_error(sampled.measure, exact.measure.value);
  }
}

TEST(RegionVolumeFraction, SampledCutsAgreeWithTheClosedFormOnTheSameCube) {
  const auto mesh = MeshContainer::from_file(test::mesh_path("cube.stl"), 20.0);  // [0, 20]^3
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(20.0));
  const Packing<3> p = test::jittered_lattice<3>(10, 0.3, 0.9, 0.05, 5, 1.0);  // sites 1, 3, ..., 19
  const RegionVolumeFraction exact = vf_region(p, box, 1.7);
  const RegionVolumeFraction sampled = vf_region(p, *mesh, 1.7);
  EXPECT_FALSE(sampled.exact);
  EXPECT_GT(sampled.balls_sampled, 100u);
  EXPECT_GT(sampled.vf.std_error, 0.0);
  expect_within_error(sampled.vf, exact.vf.value);
  expect_within_error(region_measure<3>(*mesh, 1.7), std::pow(20.0 - 3.4, 3));
}

TEST(RegionVolumeFraction, RegionMeasuresInClosedForm) {
  EXPECT_EQ(region_measure<3>(BoxContainer<3>(Vec3::Zero(), Vec3(4, 5, 6)), 1.0).value, 2.0 * 3.0 * 4.0);
  EXPECT_DOUBLE_EQ(region_measure<2>(BallContainer<2>(Vec2::Zero(), 3.0), 1.0).value, 4.0 * kPi);
  const CylinderContainer cyl(Vec3(1, 1, 1), Vec3(1, 1, 0), 2.0, 10.0);
  const Estimate c = region_measure<3>(cyl, 0.5);
  EXPECT_DOUBLE_EQ(c.value, kPi * 1.5 * 1.5 * 9.0);
  EXPECT_EQ(c.std_error, 0.0);
  EXPECT_EQ(region_measure<3>(cyl, 2.5).value, 0.0);
}

TEST(RegionVolumeFraction, FemurCoreHasAnErrorBarAndIsReproducible) {
  const auto femur = MeshContainer::from_file(test::mesh_path("femur.off"));
  const Aabb<3> b = femur->bounds();
  const double r = 0.035 * b.size().minCoeff();
  // Balls of radius r on a lattice of spacing 2.2 r, those inside the femur.
  Packing<3> p;
  for (double x = b.lo.x(); x < b.hi.x(); x += 2.2 * r)
    for (double y = b.lo.y(); y < b.hi.y(); y += 2.2 * r)
      for (double z = b.lo.z(); z < b.hi.z(); z += 2.2 * r)
        if (femur->contains_ball(Vec3(x, y, z), r, 0.0)) p.add(Vec3(x, y, z), r);
  ASSERT_GT(p.size(), 500u);
  const RegionVolumeFraction whole = vf_region(p, *femur, 0.0);
  EXPECT_TRUE(whole.exact);
  EXPECT_EQ(whole.vf.value, vf_container(p, femur->measure()));

  QmcOptions quick;  // the femur's signed distance costs ~1.5 us: keep the test short
  quick.replicates = 8;
  quick.region_points = 1024;
  const RegionVolumeFraction core = vf_region(p, *femur, 2.0 * r, quick);
  EXPECT_FALSE(core.exact);
  EXPECT_GT(core.vf.std_error, 0.0);
  EXPECT_LT(core.vf.std_error, 0.02 * core.vf.value);
  EXPECT_GT(core.measure.std_error, 0.0);
  // A lattice with spacing 2.2 r: pi / 6 / 1.1^3 in the bulk.
  EXPECT_NEAR(core.vf.value, kPi / 6.0 / std::pow(1.1, 3), 0.05);
  QmcOptions reseed = quick;
  reseed.seed = 99;
  const RegionVolumeFraction other = vf_region(p, *femur, 2.0 * r, reseed);
  EXPECT_NE(other.vf.value, core.vf.value);
  EXPECT_NEAR(other.vf.value, core.vf.value, 5.0 * std::hypot(core.vf.std_error, other.vf.std_error));
  // With a budget too small for 32 points per ball: 4 points, a wider error bar, the same value.
  QmcOptions lean = quick;
  lean.max_ball_points = 8 * 4 * core.balls_sampled;
  const RegionVolumeFraction cheap = vf_region(p, *femur, 2.0 * r, lean);
  EXPECT_NE(cheap.method.find("(8 x 4 points each)"), std::string::npos) << cheap.method;
  EXPECT_NEAR(cheap.vf.value, core.vf.value, 5.0 * std::hypot(core.vf.std_error, cheap.vf.std_error));
}

TEST(RegionVolumeFraction, SameSeedSameEstimate) {
  const Packing<2> p = test::jittered_lattice<2>(20, 0.3, 0.9, 0.05, 8);
  const PolygonContainer tri({Vec2(-1, -1), Vec2(60, -1), Vec2(-1, 60)});
  const RegionVolumeFraction a = vf_region(p, tri, 2.0), b = vf_region(p, tri, 2.0);
  EXPECT_FALSE(a.exact);
  EXPECT_EQ(a.vf.value, b.vf.value);
  EXPECT_EQ(a.vf.std_error, b.vf.std_error);
  EXPECT_EQ(a.measure.value, b.measure.value);
  // The shrunk triangle is similar, scaled about the incentre by (rho - 2) / rho, rho the
  // inradius (a + b - c) / 2 of the right triangle with legs 61.
  const double rho = 61.0 * (2.0 - std::sqrt(2.0)) / 2.0, leg = 61.0 * (rho - 2.0) / rho;
  EXPECT_NEAR(a.measure.value, leg * leg / 2.0, 4.0 * a.measure.std_error);
}

TEST(RegionVolumeFraction, EmptyRegionAndBadShrink) {
  const auto lat = test::simple_cubic(3, 1.0, Vec3::Zero());
  const BoxContainer<3> box(Vec3::Constant(-0.5), Vec3::Constant(2.5));
  const RegionVolumeFraction v = vf_region(lat.packing, box, 1.6);
  EXPECT_TRUE(std::isnan(v.vf.value));
  EXPECT_EQ(v.measure.value, 0.0);
  EXPECT_EQ(v.method, "empty region");
  EXPECT_THROW(vf_region(lat.packing, box, -1.0), std::invalid_argument);
  EXPECT_THROW(vf_region(lat.packing, box, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace fp
