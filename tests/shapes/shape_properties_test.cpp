// Properties every shape must have, checked for every family and several parameter sets, in 2D
// and 3D: support function against the inside test, bounding and inscribed radii, hull balls,
// measure against Monte-Carlo, scaling, display surface, FCL parts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "shape_test_support.hpp"
#include "shapes/unit_ball_cover.hpp"

namespace fp {
namespace {

using test::catalogue;
using test::directions;

/// How far a family's hull balls may stick out of the shape, in bounding radii.
template <int D>
double hull_slack(const std::string& family) {
  if (family == "ellipse" || family == "ellipsoid") return unit_ball_cover_slack<D>();
  if (family == "cylinder") return unit_ball_cover_slack<2>();
  return 1e-12;
}

template <int D>
double ball_support(const std::vector<Ball<D>>& balls, const Vec<D>& u) {
  double h = -1e300;
  for (const Ball<D>& b : balls) h = std::max(h, u.dot(b.center) + b.radius * u.norm());
  return h;
}

/// Points of the shape, uniform in its bounding box: `tries` draws, or more until `at_least` hit.
template <int D>
std::vector<Vec<D>> inside_samples(const Shape<D>& s, int tries, std::uint64_t seed, std::size_t at_least = 0) {
  std::mt19937_64 rng(seed);
  std::vector<Vec<D>> in;
  for (int i = 0; i < tries || (in.size() < at_least && i < 100 * tries); ++i)
    if (const Vec<D> x = test::uniform_box<D>(rng, s.bounding_radius()); s.contains(x)) in.push_back(x);
  return in;
}

template <class T>
class ShapeProperties : public ::testing::Test {};
using Dims = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(ShapeProperties, Dims);

TYPED_TEST(ShapeProperties, PrototypeHasCircumscribedRadiusOne) {
  constexpr int D = TypeParam::value;
  for (const auto& c : catalogue<D>()) {
    SCOPED_TRACE(c.name);
    const auto proto = test::prototype<D>(c.family, c.parameters);
    EXPECT_NEAR(proto.shape->bounding_radius(), 1.0, 1e-12);
    EXPECT_EQ(proto.dimensions.at("circumscribed_radius"), 1.0);
    EXPECT_STREQ(proto.shape->kind(), c.family.c_str());
    ASSERT_TRUE(proto.dimensions.count("equivalent_radius"));
    EXPECT_NEAR(ball_measure<D>(proto.dimensions.at("equivalent_radius")), proto.shape->measure(),
                1e-12 * proto.shape->measure());
  }
}

TYPED_TEST(ShapeProperties, BoundingRadiusIsTheFarthestSupportAndSurfacePoint) {
  constexpr int D = TypeParam::value;
  for (const auto& c : catalogue<D>()) {
    SCOPED_TRACE(c.name);
    const auto s = test::prototype<D>(c.family, c.parameters).shape->scaled(1.7);
    const double R = s->bounding_radius();
    double far_support = 0.0, far_vertex = 0.0;
    for (const Vec<D>& u : directions<D>(D == 2 ? 4000 : 40000)) far_support = std::max(far_support, s->support(u).norm());
    for (const Vec<D>& v : s->surface(256).vertices) far_vertex = std::max(far_vertex, v.norm());
    EXPECT_LE(far_support, R * (1 + 1e-12));
    EXPECT_GE(far_support, R * (1 - 1e-3));
    EXPECT_LE(far_vertex, R * (1 + 1e-12));
    EXPECT_GE(far_vertex, R * (1 - 1e-3));
    if (c.family == "polygon" || c.family == "polyhedron") {
      EXPECT_NEAR(far_vertex, R, 1e-12 * R);
    }
  }
}

TYPED_TEST(ShapeProperties, SupportPointIsInsideAndMaximisesOverInsidePoints) {
  constexpr int D = TypeParam::value;
  for (const auto& c : catalogue<D>()) {
    SCOPED_TRACE(c.name);
    const auto s = test::prototype<D>(c.family, c.parameters).shape->scaled(0.6);
    const double R = s->bounding_radius();
    const auto in = inside_samples<D>(*s, 40000, 7, 10000);
    ASSERT_GE(in.size(), 10000u);
    for (const Vec<D>& u : directions<D>(300)) {
      const Vec<D> p = s->support(3.5 * u);  // u need not be unit
      EXPECT_TRUE(s->contains(p) || s->contains(p * (1 - 1e-12))) << p.transpose();
      double best = -1e300;
      for (const Vec<D>& x : in) best = std::max(best, u.dot(x));
      EXPECT_LE(best, u.dot(p) + 1e-12 * R);
      EXPECT_GE(best, u.dot(p) - 0.2 * R);  // and samples come close (sharp corners less so)
    }
  }
}

TYPED_TEST(ShapeProperties, HullBallsCoverTheShapeAndStayClose) {
  constexpr int D = TypeParam::value;
  for (const auto& c : catalogue<D>()) {
    SCOPED_TRACE(c.name);
    const auto s = test::prototype<D>(c.family, c.parameters).shape->scaled(2.0);
    const double R = s->bounding_radius();
    const auto balls = s->hull_balls();
    const auto in = inside_samples<D>(*s, 20000, 11);
    for (const Vec<D>& u : directions<D>(D == 2 ? 1000 : 5000)) {
      const double h = u.dot(s->support(u));
      const double hb = ball_support<D>(balls, u);
      EXPECT_GE(hb, h - 1e-12 * R);
      EXPECT_LE(hb, h + hull_slack<D>(c.family) * R + 1e-12 * R);
    }
    for (const Vec<D>& u : directions<D>(64)) {  // every inside point is in the hull of the balls
      const double hb = ball_support<D>(balls, u) + 1e-12 * R;
      for (const Vec<D>& x : in) ASSERT_LE(u.dot(x), hb);
    }
  }
}

TYPED_TEST(ShapeProperties, MeasureAgreesWithMonteCarloOfContains) {
  constexpr int D = TypeParam::value;
  for (const auto& c : catalogue<D>()) {
    SCOPED_TRACE(c.name);
    const auto s = test::prototype<D>(c.family, c.parameters).shape;
    const int n = 400000;
    const double box = std::pow(2 * s->bounding_radius(), D);
    const double hits = static_cast<double>(inside_samples<D>(*s, n, 3).size());
    const double p = hits / n;
    const double sigma = box * std::sqrt(p * (1 - p) / n);
    EXPECT_NEAR(box * p, s->measure(), 5 * sigma);
  }
}

TYPED_TEST(ShapeProperties, InscribedBallIsInside) {
  constexpr int D = TypeParam::value;
  for (const auto& c : catalogue<D>()) {
    SCOPED_TRACE(c.name);
    const auto s = test::prototype<D>(c.family, c.parameters).shape;
    const double r = s->inscribed_radius();
    EXPECT_GE(r, 0.0);
    EXPECT_LE(r, s->bounding_radius());
    if (c.name == "cluster apart") {
      EXPECT_EQ(r, 0.0);  // the reference point lies between the members
    } else {
      EXPECT_GT(r, 0.0);
    }
    for (const Vec<D>& u : directions<D>(r > 0 ? 2000 : 0)) EXPECT_TRUE(s->contains(u * r * (1 - 1e-9)));
  }
}

TYPED_TEST(ShapeProperties, ScaledScalesEverything) {
  constexpr int D = TypeParam::value;
  const double k = 2.5;
  for (const auto& c : catalogue<D>()) {
    SCOPED_TRACE(c.name);
    const auto s = test::prototype<D>(c.family, c.parameters).shape;
    const auto t = s->scaled(k);
    EXPECT_STREQ(t->kind(), s->kind());
    EXPECT_NEAR(t->measure(), std::pow(k, D) * s->measure(), 1e-12 * t->measure());
    EXPECT_NEAR(t->bounding_radius(), k * s->bounding_radius(), 1e-12 * k);
    EXPECT_NEAR(t->inscribed_radius(), k * s->inscribed_radius(), 1e-12 * k);
    for (const Vec<D>& u : directions<D>(200)) EXPECT_LE((t->support(u) - k * s->support(u)).norm(), 1e-12 * k);
    const auto bs = s->hull_balls(), bt = t->hull_balls();
    ASSERT_EQ(bs.size(), bt.size());
    for (std::size_t i = 0; i < bs.size(); ++i) {
      EXPECT_LE((bt[i].center - k * bs[i].center).norm(), 1e-12 * k);
      EXPECT_NEAR(bt[i].radius, k * bs[i].radius, 1e-12 * k);
    }
    std::mt19937_64 rng(5);
    for (int i = 0; i < 2000; ++i) {
      const Vec<D> x = test::uniform_box<D>(rng, 1.0);
      EXPECT_EQ(t->contains(k * x), s->contains(x)) << x.transpose();
    }
    EXPECT_NE(t->definition_json(), s->definition_json());
  }
}

TYPED_TEST(ShapeProperties, SurfaceIsOnTheShapeAndOrientedOutwards) {
  constexpr int D = TypeParam::value;
  for (const auto& c : catalogue<D>()) {
    SCOPED_TRACE(c.name);
    const auto s = test::prototype<D>(c.family, c.parameters).shape;
    const SurfaceMesh<D> m = s->surface(512);
    ASSERT_FALSE(m.facets.empty());
    for (const Vec<D>& v : m.vertices) EXPECT_TRUE(s->contains(v) || s->contains(v * (1 - 1e-12))) << v.transpose();
    // Divergence theorem: sum over facets of (origin, facet) simplex measures = enclosed measure,
    // positive when facets face outwards. 3D clusters are drawn as overlapping spheres: skip.
    if (D == 3 && c.family == "cluster") continue;
    double enclosed = 0.0;
    for (const auto& f : m.facets) {
      for (int i : f) ASSERT_TRUE(i >= 0 && i < static_cast<int>(m.vertices.size()));
      if constexpr (D == 2) {
        const Vec2 &a = m.vertices[f[0]], &b = m.vertices[f[1]];
        enclosed += 0.5 * (a.x() * b.y() - a.y() * b.x());
      } else {
        enclosed += m.vertices[f[0]].dot(m.vertices[f[1]].cross(m.vertices[f[2]])) / 6;
      }
    }
    const bool flat = c.family == "polygon" || c.family == "polyhedron";
    EXPECT_NEAR(enclosed, s->measure(), (flat ? 1e-12 : 2e-3) * s->measure());
  }
}

TYPED_TEST(ShapeProperties, FclPartsAndDefinitionArePresent) {
  constexpr int D = TypeParam::value;
  for (const auto& c : catalogue<D>()) {
    SCOPED_TRACE(c.name);
    const auto s = test::prototype<D>(c.family, c.parameters).shape;
    const auto parts = s->fcl_parts();
    ASSERT_FALSE(parts.empty());
    for (const auto& p : parts) {
      EXPECT_TRUE(p.geometry);
      EXPECT_NEAR((p.rotation.transpose() * p.rotation - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);
    }
    EXPECT_EQ(s->definition_json().rfind(std::string(R"({"kind": ")") + s->kind() + "\"", 0), 0u)
        << s->definition_json();
  }
}

}  // namespace
}  // namespace fp
