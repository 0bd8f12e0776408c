// The measure of a ball inside an axis-aligned box (core/metrics/ball_box.hpp): closed forms
// (whole, disjoint, one plane, a quadrant / octant) and partitions, whose pieces must sum to the
// whole ball.
#include "core/metrics/ball_box.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/sampling/rng.hpp"

namespace fp {
namespace {

constexpr double kBig = 1e3;

TEST(BallBox, WholeDisjointAndOnePlane) {
  const Vec3 c(0.3, -0.2, 0.1);
  EXPECT_EQ(ball_box_measure<3>(c, 0.5, Vec3::Constant(-1), Vec3::Constant(1)), ball_measure<3>(0.5));
  EXPECT_EQ(ball_box_measure<3>(c, 0.5, Vec3(0.8, -1, -1), Vec3(2, 1, 1)), 0.0);  // tangent from outside
  EXPECT_EQ(ball_box_measure<3>(c, 0.0, Vec3::Constant(-1), Vec3::Constant(1)), 0.0);
  for (const double t : {-0.49, -0.2, 0.0, 0.1, 0.45}) {  // the plane x = c.x + t cuts it
    const double inside = ball_box_measure<3>(c, 0.5, Vec3(-kBig, -kBig, -kBig), Vec3(c.x() + t, kBig, kBig));
    EXPECT_NEAR(inside, ball_inside_plane<3>(0.5, t), 1e-15);
    const Vec2 c2(0.3, -0.2);
    EXPECT_NEAR(ball_box_measure<2>(c2, 0.5, Vec2(-kBig, c2.y() + t), Vec2(kBig, kBig)), ball_inside_plane<2>(0.5, -t),
                1e-15);
  }
}

TEST(BallBox, QuadrantAndOctant) {
  for (const double r : {1.0, 0x1p-60, 0x1p60}) {
    EXPECT_NEAR(ball_box_measure<2>(Vec2(0, 0), r, Vec2(0, 0), Vec2(kBig * r, kBig * r)), kPi * r * r / 4, 1e-14 * r * r);
    const double eighth = ball_measure<3>(r) / 8;
    EXPECT_NEAR(ball_box_measure<3>(Vec3(0, 0, 0), r, Vec3(0, 0, 0), Vec3::Constant(kBig * r)), eighth, 1e-13 * eighth);
    // A quarter (two planes through the centre): 1/4 of the ball.
    EXPECT_NEAR(ball_box_measure<3>(Vec3(0, 0, 0), r, Vec3(0, 0, -kBig * r), Vec3::Constant(kBig * r)), 2 * eighth,
                1e-13 * eighth);
  }
}

// Random grids of planes through a ball: the measures of the cells sum to the ball.
template <int D>
void check_partitions(double tol) {
  Rng rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const double r = 0.1 + rng.uniform01();
    Vec<D> c;
    for (int k = 0; k < D; ++k) c[k] = 4 * rng.uniform01() - 2;
    std::vector<std::vector<double>> planes(D);
    for (int k = 0; k < D; ++k) {
      planes[k] = {c[k] - 2 * r};
      const int cuts = 1 + static_cast<int>(rng.below(4));
      for (int q = 0; q < cuts; ++q) planes[k].push_back(c[k] - r + 2 * r * rng.uniform01());
      planes[k].push_back(c[k] + 2 * r);
      std::sort(planes[k].begin(), planes[k].end());
    }
    double sum = 0.0;
    std::array<std::size_t, D> at{};
    for (;;) {
      Vec<D> lo, hi;
      for (int k = 0; k < D; ++k) lo[k] = planes[k][at[k]], hi[k] = planes[k][at[k] + 1];
      const double m = ball_box_measure<D>(c, r, lo, hi);
      EXPECT_GE(m, 0.0);
      sum += m;
      int k = 0;
      while (k < D && at[k] + 2 == planes[k].size()) at[k] = 0, ++k;
      if (k == D) break;
      ++at[k];
    }
    EXPECT_NEAR(sum, ball_measure<D>(r), tol * ball_measure<D>(r)) << "trial " << trial;
  }
}

TEST(BallBox, PartitionsSumToTheBall) {
  check_partitions<2>(1e-12);
  check_partitions<3>(1e-9);
}

}  // namespace
}  // namespace fp
