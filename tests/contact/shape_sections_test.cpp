// Sections of shapes against hand-worked areas: a cube turned about the plane's normal and about
// another axis, an ellipsoid (to its mesh), particles the planes miss, absolute coordinates, and a
// 2D packing's own outlines.
#include "contact/shape_sections.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <numbers>

#include "core/geometry/box_container.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/ellipsoid_shape.hpp"

namespace fp {
namespace {

double area(const std::vector<std::array<double, 2>>& loop) {
  double a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto& p = loop[i];
    const auto& q = loop[(i + 1) % loop.size()];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return std::abs(a) / 2;
}

std::shared_ptr<const Shape<3>> unit_cube() {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
  return std::make_shared<const ConvexPolytopeShape<3>>(ConvexPolytopeShape<3>::hull_of(corners));
}

TEST(ShapeSections, ACubeTurnedAboutZIsASquareAcrossZAndAWiderRectangleAlongIt) {
  const BoxContainer<3> box(Vec3::Zero(), Vec3(2, 2, 2));  // the planes x, y, z = 1
  ShapePacking<3> packing;
  Particle<3> cube;
  cube.shape = unit_cube();
  cube.pose.position = Vec3(1, 1, 1);
  cube.pose.rotation = Eigen::AngleAxisd(std::numbers::pi / 6, Vec3::UnitZ()).toRotationMatrix();
  cube.size = 0.7;
  packing.particles.push_back(cube);
  Particle<3> missed = cube;  // its bounding ball clear of all three planes
  missed.pose.position = Vec3(0.3, 0.3, 0.3);
  missed.pose.rotation.setIdentity();
  packing.particles.push_back(missed);

  const std::vector<PackingSection> s = shape_sections<3>(packing, box);
  ASSERT_EQ(s.size(), 3u);
  for (const PackingSection& plane : s) {
    ASSERT_EQ(plane.polygons.size(), 1u) << "normal " << plane.normal_axis;
    EXPECT_EQ(plane.polygons[0].particle, 0u);
    EXPECT_EQ(plane.polygons[0].size, 0.7);
    EXPECT_TRUE(plane.disks.empty());
    EXPECT_FALSE(plane.outline.empty());
    // Across z: the unit square. Along z (normal x or y): the chord of the turned square through
    // its centre, 1 / cos 30 degrees, times the height 1.
    const double expected = plane.normal_axis == 2 ? 1.0 : 1.0 / std::cos(std::numbers::pi / 6);
    EXPECT_NEAR(area(plane.polygons[0].points), expected, 1e-12) << "normal " << plane.normal_axis;
    EXPECT_GE(plane.polygons[0].points.size(), 4u);  // with the points where the faces' diagonals cross, collinear
    for (const auto& q : plane.polygons[0].points) {  // every corner within the cube's reach of its centre
      EXPECT_LE(std::hypot(q[0] - 1, q[1] - 1), std::sqrt(0.75) + 1e-12);
    }
  }
}

TEST(ShapeSections, AnEllipsoidGivesItsEllipseToTheMeshAndAFarFrameIsAdded) {
  const BoxContainer<3> box(Vec3::Zero(), Vec3(2, 2, 2));
  ShapePacking<3> packing;
  packing.origin = Vec3(1e3, -5, 0);
  Particle<3> e;
  e.shape = std::make_shared<const EllipsoidShape<3>>(Vec3(0.6, 0.4, 0.3));
  e.pose.position = Vec3(1, 1, 1);
  packing.particles.push_back(e);
  const std::vector<PackingSection> s = shape_sections<3>(packing, box);
  const double pi = std::numbers::pi;
  const double expected[3] = {pi * 0.4 * 0.3, pi * 0.6 * 0.3, pi * 0.6 * 0.4};  // normal x, y, z
  for (const PackingSection& plane : s) {
    ASSERT_EQ(plane.polygons.size(), 1u);
    const double a = area(plane.polygons[0].points);
    EXPECT_LT(a, expected[plane.normal_axis]);  // a polygon inscribed in the ellipse
    EXPECT_GT(a, 0.98 * expected[plane.normal_axis]);
    double mean_u = 0;
    for (const auto& q : plane.polygons[0].points) mean_u += q[0] / static_cast<double>(plane.polygons[0].points.size());
    EXPECT_NEAR(mean_u, 1 + packing.origin[plane.u_axis], 1e-9);  // absolute
    EXPECT_DOUBLE_EQ(plane.offset, 1 + packing.origin[plane.normal_axis]);
  }
}

TEST(ShapeSections, A2DPackingIsDrawnWhole) {
  const BoxContainer<2> box(Vec2::Zero(), Vec2(4, 4));
  ShapePacking<2> packing;
  const std::vector<Vec2> corners = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  Particle<2> square;
  square.shape = std::make_shared<const ConvexPolytopeShape<2>>(ConvexPolytopeShape<2>::hull_of(corners));
  for (const double x : {0.7, 2.1, 3.3}) {
    square.pose.position = Vec2(x, 1.5);
    square.pose.rotation = Eigen::Rotation2Dd(x).toRotationMatrix();
    packing.particles.push_back(square);
  }
  const std::vector<PackingSection> s = shape_sections<2>(packing, box);
  ASSERT_EQ(s.size(), 1u);
  ASSERT_EQ(s[0].polygons.size(), 3u);
  for (const SectionPolygon& p : s[0].polygons) EXPECT_NEAR(area(p.points), 1.0, 1e-12);
}

}  // namespace
}  // namespace fp
