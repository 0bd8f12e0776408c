// BallContainer (disk in 2D) against closed forms.
#include "core/geometry/ball_container.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/sampling/rng.hpp"
#include "tests/geometry/reference_geometry.hpp"

namespace fp {
namespace {

template <class T>
class BallTest : public ::testing::Test {};
using Dims = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(BallTest, Dims);

template <int D>
Vec<D> center() {
  Vec<D> c;
  for (int a = 0; a < D; ++a) c[a] = 0.25 * (a + 1);
  return c;
}

template <int D>
Vec<D> random_in_cube(Rng& rng, const Vec<D>& c, double half) {
  Vec<D> p;
  for (int a = 0; a < D; ++a) p[a] = c[a] + rng.uniform(-half, half);
  return p;
}

TYPED_TEST(BallTest, InsideSignedDistanceAndWallsMatchClosedForm) {
  constexpr int D = TypeParam::value;
  const double R = 0.7;
  const BallContainer<D> ball(center<D>(), R);
  Rng rng(21);
  std::vector<Wall<D>> walls;
  int inside = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec<D> p = random_in_cube<D>(rng, center<D>(), 1.2 * R);
    double dist2 = 0.0;
    for (int a = 0; a < D; ++a) dist2 += (p[a] - center<D>()[a]) * (p[a] - center<D>()[a]);
    const double ref = std::sqrt(dist2) - R;
    EXPECT_NEAR(ball.signed_distance(p), ref, 1e-15);
    EXPECT_EQ(ball.inside(p), dist2 <= R * R);
    inside += ball.inside(p);

    const double reach = rng.uniform(0.0, 0.5);
    walls.clear();
    ball.walls_near(p, reach, walls);
    if (std::abs(ref) < reach * (1 - 1e-12)) {
      ASSERT_EQ(walls.size(), 1u);
      EXPECT_EQ(walls[0].kind, WallKind::Sphere);
      EXPECT_EQ(walls[0].point, center<D>());
      EXPECT_EQ(walls[0].radius, R);
      if (ref < 0) {
        const double r = rng.uniform(0.0, -ref);
        EXPECT_NEAR(walls[0].gap(p, r), -ref - r, 1e-15);
      }
    } else if (std::abs(ref) > reach * (1 + 1e-12)) {
      EXPECT_TRUE(walls.empty());
    }
  }
  EXPECT_GT(inside, 1000);
}

TYPED_TEST(BallTest, MeasureBoundsDescribe) {
  constexpr int D = TypeParam::value;
  const double R = 0.7;
  const BallContainer<D> ball(center<D>(), R);
  EXPECT_NEAR(ball.measure(), D == 2 ? kPi * R * R : 4.0 / 3.0 * kPi * R * R * R, 1e-15);
  EXPECT_EQ(ball.interior_point(), center<D>());
  EXPECT_NEAR(ball.bounds().lo[0], center<D>()[0] - R, 1e-15);
  EXPECT_NEAR(ball.bounds().hi[D - 1], center<D>()[D - 1] + R, 1e-15);
  EXPECT_EQ(ball.describe().rfind(D == 2 ? "disk center [" : "ball center [", 0), 0u) << ball.describe();
}

TYPED_TEST(BallTest, ContainsBallAgreesWithSignedDistance) {
  constexpr int D = TypeParam::value;
  const BallContainer<D> ball(center<D>(), 0.7);
  Rng rng(22);
  for (int i = 0; i < 5000; ++i) {
    const Vec<D> c = random_in_cube<D>(rng, center<D>(), 0.7);
    const double r = rng.uniform(0.0, 0.4);
    EXPECT_EQ(ball.contains_ball(c, r), ball.signed_distance(c) <= -r + 1e-9 * r);
  }
}

TYPED_TEST(BallTest, ImpossibleParametersNameTheParameter) {
  constexpr int D = TypeParam::value;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  testref::expect_invalid([] { BallContainer<D>(Vec<D>::Zero(), 0.0); }, {"radius", "positive"});
  testref::expect_invalid([] { BallContainer<D>(Vec<D>::Zero(), -1.0); }, {"radius"});
  testref::expect_invalid([&] { BallContainer<D>(Vec<D>::Zero(), nan); }, {"radius"});
  testref::expect_invalid([] { BallContainer<D>(Vec<D>::Zero(), std::numeric_limits<double>::infinity()); }, {"radius"});
  testref::expect_invalid([&] { BallContainer<D>(Vec<D>::Constant(nan), 1.0); }, {"center", "finite"});
}

}  // namespace
}  // namespace fp
