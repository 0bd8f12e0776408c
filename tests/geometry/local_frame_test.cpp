// The local frame rule (core/geometry/local_frame.hpp) and the containers built in it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/local_frame.hpp"
#include "core/geometry/polygon_container.hpp"

namespace fp {
namespace {

template <int D>
Aabb<D> box_of(const Vec<D>& lo, const Vec<D>& hi) {
  Aabb<D> b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

TEST(LocalFrame, ContainersNearTheOriginKeepOriginZero) {
  EXPECT_TRUE(frame_origin<3>(box_of<3>(Vec3::Zero(), Vec3::Constant(0.9))).isZero());
  EXPECT_TRUE(frame_origin<3>(box_of<3>(Vec3::Constant(-5), Vec3::Constant(5))).isZero());
  EXPECT_TRUE(frame_origin<2>(box_of<2>(Vec2::Zero(), Vec2::Constant(1))).isZero());
  // Scaling does not move the frame: a box [0, 0.9 * 2^k] stays at origin 0.
  for (int k : {-60, -30, 30, 60})
    EXPECT_TRUE(frame_origin<3>(box_of<3>(Vec3::Zero(), Vec3::Constant(std::ldexp(0.9, k)))).isZero()) << k;
}

TEST(LocalFrame, RoundOffsetsMapToTheUnshiftedCoordinates) {
  for (const double t : {1e3, 1e6, 1e9, -1e9, 1048576.0}) {
    const Vec3 lo = Vec3::Constant(t), hi = Vec3::Constant(t + 0.5);
    const Vec3 o = frame_origin<3>(box_of<3>(lo, hi));
    EXPECT_EQ(o, lo) << t;
    const BoxContainer<3> box(lo, hi, o);
    EXPECT_EQ(box.lo(), Vec3::Zero());
    EXPECT_EQ(box.hi(), Vec3::Constant(0.5));
    EXPECT_EQ(box.origin(), lo);
    const BallContainer<2> disk(Vec2(t, -t), 0.75, frame_origin<2>(box_of<2>(Vec2(t - 0.75, -t - 0.75), Vec2(t + 0.75, -t + 0.75))));
    EXPECT_EQ(disk.center(), Vec2::Zero()) << t;
  }
}

TEST(LocalFrame, SubtractingTheOriginIsExactForEveryPointOfTheContainer) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const double t : {123456.789, 1e9 + 0.3, -7.77e12, 3.3e-3}) {
    for (const double e : {1e-6, 1e-3, 1.0, 100.0}) {
      const Vec2 lo(t, 2 * t), hi(t + e, 2 * t + 0.5 * e);
      const Vec2 o = frame_origin<2>(box_of<2>(lo, hi));
      for (int k = 0; k < 200; ++k) {
        const Vec2 x = lo + (hi - lo).cwiseProduct(Vec2(u(rng), u(rng)));
        for (int a = 0; a < 2; ++a) {
          const double local = x[a] - o[a];
          EXPECT_EQ(local + o[a], x[a]) << "t " << t << " e " << e;  // no rounding in either direction
        }
      }
    }
  }
}

TEST(LocalFrame, ContainersDescribeThemselvesInAbsoluteCoordinates) {
  const Vec3 lo = Vec3::Constant(1e9), hi = Vec3::Constant(1e9 + 0.5);
  const BoxContainer<3> box(lo, hi, frame_origin<3>(box_of<3>(lo, hi)));
  EXPECT_EQ(box.describe(), "box [1e+09,1e+09,1e+09]-[1000000000.5,1000000000.5,1000000000.5]");
  const PolygonContainer tri({Vec2(1e6, 1e6), Vec2(1e6 + 1, 1e6), Vec2(1e6, 1e6 + 1)}, Vec2(1e6, 1e6));
  EXPECT_EQ(tri.vertices()[0], Vec2::Zero());
  EXPECT_DOUBLE_EQ(tri.measure(), 0.5);
}

}  // namespace
}  // namespace fp
