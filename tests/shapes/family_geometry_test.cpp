// Closed-form checks per family: measures, reference points, radii, hull reduction, presets,
// union measure of overlapping balls.
#include <gtest/gtest.h>

#include <cmath>

#include "shape_test_support.hpp"
#include "shapes/ball_union.hpp"
#include "shapes/cluster_shape.hpp"
#include "shapes/convex_hull_2.hpp"
#include "shapes/convex_hull_3.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/ellipsoid_shape.hpp"
#include "shapes/unit_ball_cover.hpp"

namespace fp {
namespace {

using test::numbers;
using test::prototype;

TEST(SphereFamily, Dimensions) {
  const auto p = prototype<3>("sphere");
  EXPECT_EQ(p.dimensions.at("radius"), 1.0);
  EXPECT_EQ(p.dimensions.at("diameter"), 2.0);
  EXPECT_NEAR(p.shape->measure(), 4 * kPi / 3, 1e-14);
  EXPECT_NEAR(prototype<2>("sphere").shape->measure(), kPi, 1e-14);
}

TEST(SpherocylinderFamily, AspectRatioIsWidthOverLength) {
  const auto p = prototype<2>("spherocylinder", numbers({{"aspect_ratio", 0.25}}));
  EXPECT_EQ(p.dimensions.at("radius"), 0.25);
  EXPECT_EQ(p.dimensions.at("width"), 0.5);
  EXPECT_EQ(p.dimensions.at("length"), 2.0);
  EXPECT_EQ(p.dimensions.at("cylinder_length"), 1.5);
  EXPECT_NEAR(p.shape->measure(), 4 * 0.75 * 0.25 + kPi * 0.0625, 1e-14);
  const auto q = prototype<3>("spherocylinder", numbers({{"aspect_ratio", 0.25}}));
  EXPECT_NEAR(q.shape->measure(), kPi * 0.0625 * 1.5 + 4 * kPi / 3 * std::pow(0.25, 3), 1e-14);
}

TEST(PolygonFamily, RegularPolygon) {
  for (int n : {3, 4, 5, 12}) {
    const auto p = prototype<2>("polygon", numbers({{"sides", n}}));
    EXPECT_NEAR(p.shape->measure(), 0.5 * n * std::sin(2 * kPi / n), 1e-14);
    EXPECT_NEAR(p.dimensions.at("inscribed_radius"), std::cos(kPi / n), 1e-14);
    EXPECT_NEAR(p.shape->inscribed_radius(), std::cos(kPi / n), 1e-14);
  }
  // A flat bottom edge: the square is axis-aligned.
  const auto sq = std::dynamic_pointer_cast<const ConvexPolytopeShape<2>>(prototype<2>("polygon", numbers({{"sides", 4}})).shape);
  for (const Vec2& v : sq->vertices()) EXPECT_NEAR(std::abs(v.x()), std::sqrt(0.5), 1e-15);
}

TEST(PolygonFamily, HullDropsDuplicatesCollinearAndInsidePointsAndCentresOnTheCentroid) {
  ShapeParameters p;
  p.point_lists["vertices"] = {{5, 5}, {9, 5}, {9, 7}, {5, 7}, {7, 5}, {9, 6}, {6, 6}, {9, 7}, {5, 5}};
  const auto proto = prototype<2>("polygon", p);
  const auto s = std::dynamic_pointer_cast<const ConvexPolytopeShape<2>>(proto.shape);
  ASSERT_TRUE(s);
  ASSERT_EQ(s->vertices().size(), 4u);
  const double R = std::hypot(2.0, 1.0);  // half-diagonal of the 4 x 2 rectangle about (7, 6)
  EXPECT_NEAR(s->measure(), 8 / (R * R), 1e-14);
  EXPECT_NEAR(s->inscribed_radius(), 1 / R, 1e-14);
  for (const Vec2& v : s->vertices()) EXPECT_NEAR(v.norm(), 1.0, 1e-14);
  EXPECT_TRUE(s->contains(Vec2(2 / R, 1 / R) * (1 - 1e-9)));
  EXPECT_FALSE(s->contains(Vec2(2 / R, 1 / R) * (1 + 1e-9)));
}

TEST(PolygonFamily, TriangleReferencePointIsTheVertexMean) {
  ShapeParameters p;
  p.point_lists["vertices"] = {{0, 0}, {4, 0}, {0, 3}};
  const auto s = std::dynamic_pointer_cast<const ConvexPolytopeShape<2>>(prototype<2>("polygon", p).shape);
  Vec2 sum = Vec2::Zero();
  for (const Vec2& v : s->vertices()) sum += v;
  EXPECT_LE(sum.norm(), 1e-14);
  const double R = (Vec2(4, 0) - Vec2(4.0 / 3, 1)).norm();
  EXPECT_NEAR(s->measure(), 6 / (R * R), 1e-14);
}

TEST(ConvexHull2, CounterClockwiseAndRejectsDegenerateInput) {
  const auto h = convex_hull_2({{0, 0}, {1, 1}, {1, 0}, {0, 1}, {0.5, 0.5}});
  ASSERT_EQ(h.size(), 4u);
  double twice_area = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Vec2 &a = h[i], &b = h[(i + 1) % h.size()];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_NEAR(twice_area, 2.0, 1e-15);
  EXPECT_THROW(convex_hull_2({{0, 0}, {1, 1}, {2, 2}, {3, 3}}), std::invalid_argument);
  EXPECT_THROW(convex_hull_2({{0, 0}, {0, 0}, {1, 0}}), std::invalid_argument);
}

TEST(ConvexHull3, CubeWithPointsOnFacesEdgesAndInside) {
  std::vector<Vec3> pts;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z) pts.emplace_back(x, y, z);  // corners, edge midpoints, face centres, centre
  pts.emplace_back(1, 1, 1);                                       // a duplicate
  const ConvexHull3 h = convex_hull_3(pts);
  EXPECT_EQ(h.vertices.size(), 8u);
  EXPECT_EQ(h.triangles.size(), 12u);
  double volume = 0;  // positive only if the triangles face outwards
  for (const auto& t : h.triangles) volume += h.vertices[t[0]].dot(h.vertices[t[1]].cross(h.vertices[t[2]])) / 6;
  EXPECT_NEAR(volume, 8.0, 1e-14);
  EXPECT_THROW(convex_hull_3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}}), std::invalid_argument);
  EXPECT_THROW(convex_hull_3({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}), std::invalid_argument);
}

TEST(PolyhedronFamily, PlatonicSolidsAtCircumscribedRadiusOne) {
  const double s5 = std::sqrt(5.0);
  const double icosa_edge = 4 / std::sqrt(10 + 2 * s5), dodeca_edge = 4 / (std::sqrt(3.0) * (1 + s5));
  const double icosa_in = 0.79465447229176612;  // r / R of both the icosahedron and the dodecahedron
  const struct {
    int faces;
    double volume, inscribed;
    std::size_t vertices;
  } cases[] = {
      {4, 8 * std::sqrt(3.0) / 27, 1.0 / 3, 4},
      {6, 8 / (3 * std::sqrt(3.0)), 1 / std::sqrt(3.0), 8},
      {8, 4.0 / 3, 1 / std::sqrt(3.0), 6},
      {12, (15 + 7 * s5) / 4 * std::pow(dodeca_edge, 3), icosa_in, 20},
      {20, 5.0 / 12 * (3 + s5) * std::pow(icosa_edge, 3), icosa_in, 12},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.faces);
    const auto p = prototype<3>("polyhedron", numbers({{"platonic", c.faces}}));
    const auto s = std::dynamic_pointer_cast<const ConvexPolytopeShape<3>>(p.shape);
    EXPECT_EQ(s->vertices().size(), c.vertices);
    EXPECT_NEAR(s->measure(), c.volume, 1e-13);
    EXPECT_NEAR(p.dimensions.at("inscribed_radius"), c.inscribed, 1e-13);
    EXPECT_LE(s->centroid().norm(), 1e-14);
  }
}

TEST(PolyhedronFamily, CornerTetrahedronIsCentredOnItsCentroid) {
  ShapeParameters p;
  p.point_lists["vertices"] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.1, 0.1, 0.1}};
  const auto s = std::dynamic_pointer_cast<const ConvexPolytopeShape<3>>(prototype<3>("polyhedron", p).shape);
  ASSERT_EQ(s->vertices().size(), 4u);
  const double R = Vec3(0.75, -0.25, -0.25).norm();
  EXPECT_NEAR(s->measure(), 1.0 / 6 / std::pow(R, 3), 1e-13);
  for (const Vec3& v : s->vertices()) EXPECT_TRUE(std::abs(v.norm() - 1) < 1e-14 || std::abs(v.norm() - Vec3(0.25, 0.25, 0.25).norm() / R) < 1e-14);
  // The slanted face x + y + z = 1 is the nearest: (1 - 3/4) / sqrt(3) from the centroid.
  EXPECT_NEAR(s->inscribed_radius(), 0.25 / std::sqrt(3.0) / R, 1e-14);
}

TEST(ClusterFamily, ReferencePointIsTheMeasureWeightedCentroidOfTheMembers) {
  for (int D : {2, 3}) {
    ShapeParameters p;
    p.lists["radii"] = {1.0, 0.5};
    const double w = D == 2 ? 0.25 : 0.125;  // r^D of the small member
    const double cx = 3 * w / (1 + w);
    if (D == 2) {
      p.point_lists["centers"] = {{0, 0}, {3, 0}};
      const auto s = std::dynamic_pointer_cast<const ClusterShape<2>>(prototype<2>("cluster", p).shape);
      const double R = 3 - cx + 0.5;
      EXPECT_NEAR(s->members()[0].center.x(), -cx / R, 1e-15);
      EXPECT_NEAR(s->members()[1].radius, 0.5 / R, 1e-15);
      EXPECT_NEAR(s->measure(), kPi * 1.25 / (R * R), 1e-14);  // apart: the sum
    } else {
      p.point_lists["centers"] = {{0, 0, 0}, {3, 0, 0}};
      const auto s = std::dynamic_pointer_cast<const ClusterShape<3>>(prototype<3>("cluster", p).shape);
      const double R = 3 - cx + 0.5;
      EXPECT_NEAR(s->members()[0].center.x(), -cx / R, 1e-15);
      EXPECT_NEAR(s->measure(), 4 * kPi / 3 * 1.125 / std::pow(R, 3), 1e-13);
    }
  }
}

TEST(BallUnion, TwoOverlappingDisksAreTwoDisksMinusTheLens) {
  const double r1 = 1.0, r2 = 0.6, d = 1.1;
  const double a1 = std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1)), a2 = std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2));
  const double lens = r1 * r1 * a1 + r2 * r2 * a2 - 0.5 * std::sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2));
  const std::vector<Ball<2>> disks = {{Vec2(0.3, -0.2), r1}, {Vec2(0.3 + d * 0.6, -0.2 + d * 0.8), r2}};
  EXPECT_NEAR(disk_union_area(disks), kPi * (r1 * r1 + r2 * r2) - lens, 1e-14);
}

TEST(BallUnion, TwoOverlappingBallsAreTwoBallsMinusTheLens) {
  const double r1 = 1.0, r2 = 0.6, d = 1.1;
  const double lens = kPi * std::pow(r1 + r2 - d, 2) * (d * d + 2 * d * (r1 + r2) - 3 * std::pow(r1 - r2, 2)) / (12 * d);
  const Vec3 dir = Vec3(1, 2, 2) / 3;
  const std::vector<Ball<3>> balls = {{Vec3(0.1, 0.2, 0.3), r1}, {Vec3(0.1, 0.2, 0.3) + d * dir, r2}};
  const double exact = 4 * kPi / 3 * (r1 * r1 * r1 + r2 * r2 * r2) - lens;
  EXPECT_NEAR(ball_union_volume(balls), exact, 1e-12 * exact);
}

TEST(BallUnion, NestedEqualAndTangentMembers) {
  std::vector<Ball<2>> disks = {{Vec2(0, 0), 1.0}, {Vec2(0.2, 0.1), 0.3}, {Vec2(0, 0), 1.0}, {Vec2(2, 0), 1.0}};
  EXPECT_NEAR(disk_union_area(disks), 2 * kPi, 1e-14);  // nested and duplicate add nothing; tangent adds all
  std::vector<Ball<3>> balls = {{Vec3(0, 0, 0), 1.0}, {Vec3(0.2, 0.1, 0), 0.3}, {Vec3(0, 0, 0), 1.0}, {Vec3(0, 0, 2), 1.0}};
  EXPECT_NEAR(ball_union_volume(balls), 8 * kPi / 3, 1e-12);
  // Exposed outline of two overlapping equal disks: two arcs of 240 degrees each.
  const std::vector<Ball<2>> two = {{Vec2(0, 0), 1.0}, {Vec2(1, 0), 1.0}};
  double turn = 0;
  for (const ExposedArc& a : exposed_arcs(two)) turn += a.t1 - a.t0;
  EXPECT_NEAR(turn, 2 * (2 * kPi - 2 * kPi / 3), 1e-14);
}

TEST(BallUnion, ManyBallsAgreeWithAFineGridCount) {
  // Nine overlapping balls; a 200^3 midpoint grid has an error of a few 1e-4 relative.
  std::vector<Ball<3>> balls;
  for (int i = 0; i < 9; ++i)
    balls.push_back({Vec3(std::cos(1.3 * i), std::sin(2.1 * i), 0.4 * std::cos(0.7 * i)), 0.45 + 0.1 * (i % 3)});
  const double v = ball_union_volume(balls);
  const int n = 200;
  const double lo = -1.7, hi = 1.7, h = (hi - lo) / n;
  long count = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vec3 x(lo + (i + 0.5) * h, lo + (j + 0.5) * h, lo + (k + 0.5) * h);
        for (const auto& b : balls)
          if ((x - b.center).squaredNorm() <= b.radius * b.radius) { ++count; break; }
      }
  EXPECT_NEAR(v, count * h * h * h, 2e-3 * v);
}

TEST(EllipseFamily, NormalisedAxesMeasureAndSupportNormal) {
  ShapeParameters p;
  p.lists["axes"] = {4.0, 1.0, 2.0};
  const auto proto = prototype<3>("ellipsoid", p);
  EXPECT_EQ(proto.dimensions.at("semi_axis_a"), 1.0);
  EXPECT_EQ(proto.dimensions.at("semi_axis_b"), 0.25);
  EXPECT_EQ(proto.dimensions.at("semi_axis_c"), 0.5);
  EXPECT_NEAR(proto.shape->measure(), 4 * kPi / 3 * 0.125, 1e-15);
  EXPECT_EQ(proto.shape->inscribed_radius(), 0.25);
  const Vec3 a(1, 0.25, 0.5);
  for (const Vec3& u : test::directions<3>(100)) {
    const Vec3 x = proto.shape->support(u);
    EXPECT_NEAR(x.cwiseQuotient(a).squaredNorm(), 1.0, 1e-14);
    const Vec3 normal = x.cwiseQuotient(a.cwiseProduct(a)).normalized();  // gradient of sum (x_i / a_i)^2
    EXPECT_NEAR(normal.dot(u), 1.0, 1e-14);
  }
  p.lists["axes"] = {1.0, 3.0};
  const auto e = prototype<2>("ellipse", p);
  EXPECT_NEAR(e.shape->measure(), kPi / 3, 1e-15);
  EXPECT_EQ(e.dimensions.count("semi_axis_c"), 0u);
}

TEST(UnitBallCover, CircumscribesTheBallWithTheStatedSlack) {
  EXPECT_NEAR(unit_ball_cover_slack<2>(), 1 / std::cos(kPi / 32) - 1, 1e-15);
  EXPECT_LT(unit_ball_cover_slack<3>(), 0.005);
  EXPECT_EQ(unit_ball_cover<3>().size(), 642u);
  for (const Vec3& u : test::directions<3>(20000)) {
    double h = -1;
    for (const Vec3& p : unit_ball_cover<3>()) h = std::max(h, u.dot(p));
    EXPECT_GE(h, 1 - 1e-12);
  }
}

}  // namespace
}  // namespace fp
