// BoxContainer against closed forms: clamping for distances, face patches for walls.
#include "core/geometry/box_container.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "core/sampling/rng.hpp"
#include "tests/geometry/reference_geometry.hpp"

namespace fp {
namespace {

template <int D>
Vec<D> random_point(Rng& rng, const Vec<D>& lo, const Vec<D>& hi) {
  Vec<D> p;
  for (int a = 0; a < D; ++a) p[a] = rng.uniform(lo[a], hi[a]);
  return p;
}

template <int D>
struct BoxCase {
  static Vec<D> lo() {
    Vec<D> v;
    for (int a = 0; a < D; ++a) v[a] = -0.3 + 0.2 * a;
    return v;
  }
  static Vec<D> hi() {
    Vec<D> v;
    for (int a = 0; a < D; ++a) v[a] = 0.9 + 0.5 * a;
    return v;
  }
};

template <class T>
class BoxTest : public ::testing::Test {};
using Dims = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(BoxTest, Dims);

/// Signed distance by clamping: outside, the distance to the clamped point; inside, minus the
/// smallest distance to a face.
template <int D>
double reference_sd(const Vec<D>& lo, const Vec<D>& hi, const Vec<D>& p) {
  const Vec<D> q = p.cwiseMax(lo).cwiseMin(hi);
  if (q != p) return (p - q).norm();
  double m = std::numeric_limits<double>::infinity();
  for (int a = 0; a < D; ++a) m = std::min({m, p[a] - lo[a], hi[a] - p[a]});
  return -m;
}

/// Distance from p to face (axis a, side s): clamp p into the face rectangle.
template <int D>
double face_distance(const Vec<D>& lo, const Vec<D>& hi, int a, int s, const Vec<D>& p) {
  Vec<D> q = p.cwiseMax(lo).cwiseMin(hi);
  q[a] = s == 0 ? lo[a] : hi[a];
  return (p - q).norm();
}

TYPED_TEST(BoxTest, InsideAndSignedDistanceMatchClosedForm) {
  constexpr int D = TypeParam::value;
  const Vec<D> lo = BoxCase<D>::lo(), hi = BoxCase<D>::hi();
  const BoxContainer<D> box(lo, hi);
  Rng rng(11);
  const Vec<D> pad = Vec<D>::Constant(0.5);
  int inside = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec<D> p = random_point<D>(rng, lo - pad, hi + pad);
    const double ref = reference_sd<D>(lo, hi, p);
    EXPECT_NEAR(box.signed_distance(p), ref, 1e-14);
    EXPECT_EQ(box.inside(p), ref <= 0.0);
    inside += box.inside(p);
  }
  EXPECT_GT(inside, 500);
  EXPECT_TRUE(box.inside(lo));  // closed
  EXPECT_TRUE(box.inside(hi));
  EXPECT_DOUBLE_EQ(box.signed_distance(lo), 0.0);
}

TYPED_TEST(BoxTest, MeasureBoundsInteriorDescribe) {
  constexpr int D = TypeParam::value;
  const Vec<D> lo = BoxCase<D>::lo(), hi = BoxCase<D>::hi();
  const BoxContainer<D> box(lo, hi);
  double vol = 1.0;
  for (int a = 0; a < D; ++a) vol *= hi[a] - lo[a];
  EXPECT_NEAR(box.measure(), vol, 1e-15 * vol);
  EXPECT_EQ(box.bounds().lo, lo);
  EXPECT_EQ(box.bounds().hi, hi);
  EXPECT_LT(box.signed_distance(box.interior_point()), -0.1);
  const std::string d = box.describe();
  EXPECT_EQ(d.rfind(D == 3 ? "box [" : "rectangle [", 0), 0u) << d;
}

TEST(BoxDescribe, ShortNumbers) {
  EXPECT_EQ(BoxContainer<3>(Vec3::Zero(), Vec3::Constant(0.9)).describe(), "box [0,0,0]-[0.9,0.9,0.9]");
}

TYPED_TEST(BoxTest, WallsNearAreExactlyTheFacesWithinReach) {
  constexpr int D = TypeParam::value;
  const Vec<D> lo = BoxCase<D>::lo(), hi = BoxCase<D>::hi();
  const BoxContainer<D> box(lo, hi);
  Rng rng(12);
  std::vector<Wall<D>> walls;
  const Vec<D> pad = Vec<D>::Constant(0.4);
  for (int i = 0; i < 3000; ++i) {
    const Vec<D> p = random_point<D>(rng, lo - pad, hi + pad);
    const double reach = rng.uniform(0.0, 0.8);
    walls.clear();
    box.walls_near(p, reach, walls);
    std::set<int> got;
    for (const auto& w : walls) {
      ASSERT_EQ(w.kind, WallKind::Plane);
      got.insert(w.id);
      const int a = w.id / 2, s = w.id % 2;
      EXPECT_DOUBLE_EQ(w.normal.norm(), 1.0);
      EXPECT_DOUBLE_EQ(w.normal[a], s == 0 ? 1.0 : -1.0);  // inward
      EXPECT_DOUBLE_EQ(w.point[a], s == 0 ? lo[a] : hi[a]);
    }
    EXPECT_EQ(got.size(), walls.size());
    for (int a = 0; a < D; ++a)
      for (int s = 0; s < 2; ++s) {
        const double d = face_distance<D>(lo, hi, a, s, p);
        if (d <= reach * (1 - 1e-12)) { EXPECT_TRUE(got.count(2 * a + s)) << "face " << 2 * a + s << " at " << d; }
        if (d > reach * (1 + 1e-12)) { EXPECT_FALSE(got.count(2 * a + s)) << "face " << 2 * a + s << " at " << d; }
      }
  }
}

TYPED_TEST(BoxTest, WallGapsReproduceSignedDistanceInside) {
  // Convex container: the nearest wall within reach |sd| gives the exact clearance.
  constexpr int D = TypeParam::value;
  const Vec<D> lo = BoxCase<D>::lo(), hi = BoxCase<D>::hi();
  const BoxContainer<D> box(lo, hi);
  Rng rng(13);
  std::vector<Wall<D>> walls;
  for (int i = 0; i < 2000; ++i) {
    const Vec<D> c = random_point<D>(rng, lo, hi);
    const double sd = box.signed_distance(c);
    const double r = rng.uniform(0.0, -sd);
    walls.clear();
    box.walls_near(c, -sd * (1 + 1e-12), walls);
    ASSERT_FALSE(walls.empty());
    double gap = std::numeric_limits<double>::infinity();
    for (const auto& w : walls) gap = std::min(gap, w.gap(c, r));
    EXPECT_NEAR(gap, -sd - r, 1e-14);
  }
}

TYPED_TEST(BoxTest, ContainsBallAgreesWithSignedDistance) {
  constexpr int D = TypeParam::value;
  const Vec<D> lo = BoxCase<D>::lo(), hi = BoxCase<D>::hi();
  const BoxContainer<D> box(lo, hi);
  Rng rng(14);
  int accepted = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec<D> c = random_point<D>(rng, lo, hi);
    const double r = rng.uniform(0.0, 0.5);
    const bool expected = box.signed_distance(c) <= -r + 1e-9 * r;
    EXPECT_EQ(box.contains_ball(c, r), expected);
    accepted += expected;
  }
  EXPECT_GT(accepted, 100);
  // A ball tangent to a face is accepted, one a hair bigger is not.
  Vec<D> c = box.interior_point();
  c[0] = lo[0] + 0.1;
  EXPECT_TRUE(box.contains_ball(c, 0.1));
  EXPECT_FALSE(box.contains_ball(c, 0.1 * (1 + 1e-6)));
}

TYPED_TEST(BoxTest, ImpossibleParametersNameTheParameter) {
  constexpr int D = TypeParam::value;
  const Vec<D> lo = Vec<D>::Zero(), hi = Vec<D>::Ones();
  Vec<D> flat = hi;
  flat[D - 1] = 0.0;
  testref::expect_invalid([&] { BoxContainer<D>(lo, flat); }, {"lo", "hi", "axis " + std::to_string(D - 1)});
  testref::expect_invalid([&] { BoxContainer<D>(hi, lo); }, {"lo must be < hi"});
  Vec<D> bad = lo;
  bad[0] = std::numeric_limits<double>::quiet_NaN();
  testref::expect_invalid([&] { BoxContainer<D>(bad, hi); }, {"lo", "finite"});
  bad = hi;
  bad[0] = std::numeric_limits<double>::infinity();
  testref::expect_invalid([&] { BoxContainer<D>(lo, bad); }, {"hi", "finite"});
}

}  // namespace
}  // namespace fp
