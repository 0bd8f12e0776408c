// lens_volume / lens_area (paper 002 Eq. 2): limiting cases, closed forms, and seeded random
// cases against quadrature of the cross-sections along the line of centres.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/metrics/lens.hpp"
#include "core/sampling/rng.hpp"

namespace fp {
namespace {

// Midpoint rule of f on [a, b]: knows nothing about where the integrand has kinks.
double midpoint(const std::function<double(double)>& f, double a, double b, int n) {
  const double h = (b - a) / n;
  double s = 0.0;
  for (int k = 0; k < n; ++k) s += f(a + (k + 0.5) * h);
  return s * h;
}

// Ball 1 at x = 0, ball 2 at x = d: the slice at x of the intersection is a disk (3D) or a
// segment (2D) of half-width min(sqrt(r1^2 - x^2), sqrt(r2^2 - (x - d)^2)).
double half_width(double r1, double r2, double d, double x) {
  const double a = r1 * r1 - x * x, b = r2 * r2 - (x - d) * (x - d);
  return (a <= 0.0 || b <= 0.0) ? 0.0 : std::sqrt(std::min(a, b));
}
double quadrature_volume(double r1, double r2, double d) {
  return midpoint([&](double x) { const double w = half_width(r1, r2, d, x); return kPi * w * w; }, -r1, r1, 400000);
}
double quadrature_area(double r1, double r2, double d) {
  return midpoint([&](double x) { return 2.0 * half_width(r1, r2, d, x); }, -r1, r1, 400000);
}

TEST(LensVolume, DisjointAndTouchingAreZero) {
  EXPECT_EQ(lens_volume(1.0, 2.0, 3.5), 0.0);
  EXPECT_EQ(lens_volume(1.0, 2.0, 3.0), 0.0);
  EXPECT_EQ(lens_area(1.0, 2.0, 3.5), 0.0);
  EXPECT_EQ(lens_area(1.0, 2.0, 3.0), 0.0);
}

TEST(LensVolume, ContainedIsTheSmallerBall) {
  EXPECT_DOUBLE_EQ(lens_volume(1.0, 3.0, 1.5), ball_measure<3>(1.0));
  EXPECT_DOUBLE_EQ(lens_volume(3.0, 1.0, 2.0), ball_measure<3>(1.0));  // internally tangent
  EXPECT_DOUBLE_EQ(lens_volume(2.0, 2.0, 0.0), ball_measure<3>(2.0));  // d = 0, equal radii
  EXPECT_DOUBLE_EQ(lens_volume(0.5, 2.0, 0.0), ball_measure<3>(0.5));
  EXPECT_DOUBLE_EQ(lens_area(1.0, 3.0, 1.5), ball_measure<2>(1.0));
  EXPECT_DOUBLE_EQ(lens_area(2.0, 2.0, 0.0), ball_measure<2>(2.0));
  EXPECT_EQ(lens_volume(0.0, 1.0, 0.5), 0.0);
}

TEST(LensVolume, EqualSpheresAtDistanceREqualsClosedForm) {
  for (const double r : {0.01, 1.0, 37.0}) {
    EXPECT_NEAR(lens_volume(r, r, r), 5.0 * kPi * r * r * r / 12.0, 1e-14 * r * r * r);
    // Two circular segments of angle 2 pi / 3.
    EXPECT_NEAR(lens_area(r, r, r), r * r * (2.0 * kPi / 3.0 - std::sqrt(3.0) / 2.0), 1e-14 * r * r);
  }
}

TEST(LensVolume, ContinuousAtBothTransitions) {
  const double r1 = 1.0, r2 = 2.5;
  for (const double eps : {1e-6, 1e-9}) {
    EXPECT_NEAR(lens_volume(r1, r2, r1 + r2 - eps), 0.0, 1e-5 * eps);  // ~ pi r1 r2 eps^2 / (r1 + r2)
    EXPECT_NEAR(lens_volume(r1, r2, r2 - r1 + eps), ball_measure<3>(r1), 10 * eps);
    EXPECT_NEAR(lens_area(r1, r2, r2 - r1 + eps), ball_measure<2>(r1), 10 * std::sqrt(eps));
  }
  // Nearly concentric equal spheres: no cancellation through the 1/d of Eq. 2.
  EXPECT_NEAR(lens_volume(1.0, 1.0, 1e-12), ball_measure<3>(1.0), 1e-11);
}

TEST(LensVolume, NearTangencyKeepsRelativePrecision) {
  // Overlap s -> 0: the lens is ~ pi s^2 r1 r2 / (r1 + r2) (3D) and ~ (4/3) sum sqrt(2 r_i) h_i^1.5
  // (2D, cap heights h_i = s r_j / (r1 + r2)); both are computed to better than 1e-5 relative.
  const double r1 = 1.0, r2 = 2.5;
  for (const double s : {1e-5, 1e-7, 1e-9}) {
    const double v = kPi * s * s * r1 * r2 / (r1 + r2);
    EXPECT_NEAR(lens_volume(r1, r2, r1 + r2 - s), v, 1e-4 * v);
    const double h1 = s * r2 / (r1 + r2), h2 = s * r1 / (r1 + r2);
    const double a = 4.0 / 3.0 * (std::sqrt(2.0 * r1) * std::pow(h1, 1.5) + std::sqrt(2.0 * r2) * std::pow(h2, 1.5));
    EXPECT_NEAR(lens_area(r1, r2, r1 + r2 - s), a, 1e-4 * a) << "s " << s;
  }
}

TEST(LensVolume, SymmetricInTheRadii) {
  Rng rng(11);
  for (int k = 0; k < 200; ++k) {
    const double r1 = rng.uniform(0.1, 2.0), r2 = rng.uniform(0.1, 2.0), d = rng.uniform(0.0, 4.0);
    EXPECT_NEAR(lens_volume(r1, r2, d), lens_volume(r2, r1, d), 1e-14 * ball_measure<3>(2.0));
    EXPECT_NEAR(lens_area(r1, r2, d), lens_area(r2, r1, d), 1e-14 * ball_measure<2>(2.0));
  }
}

TEST(LensVolume, MatchesQuadratureOnRandomCases) {
  Rng rng(2024);
  for (int k = 0; k < 25; ++k) {
    const double r1 = rng.uniform(0.2, 3.0), r2 = rng.uniform(0.2, 3.0);
    const double d = rng.uniform(0.0, r1 + r2);
    const double scale3 = ball_measure<3>(std::min(r1, r2)), scale2 = ball_measure<2>(std::min(r1, r2));
    EXPECT_NEAR(lens_volume(r1, r2, d), quadrature_volume(r1, r2, d), 1e-7 * scale3)
        << "r1 " << r1 << " r2 " << r2 << " d " << d;
    EXPECT_NEAR(lens_area(r1, r2, d), quadrature_area(r1, r2, d), 1e-6 * scale2)
        << "r1 " << r1 << " r2 " << r2 << " d " << d;
  }
}

TEST(LensVolume, MatchesMonteCarlo) {
  // Independent of the slice picture: count uniform points of ball 1 that fall in ball 2.
  Rng rng(7);
  const double r1 = 1.0, r2 = 1.4, d = 1.7;
  const int n = 400000;
  int hits = 0, in_ball1 = 0;
  for (int k = 0; k < n; ++k) {
    const Vec3 p(rng.uniform(-r1, r1), rng.uniform(-r1, r1), rng.uniform(-r1, r1));
    if (p.squaredNorm() > r1 * r1) continue;
    ++in_ball1;
    hits += (p - Vec3(d, 0, 0)).squaredNorm() <= r2 * r2 ? 1 : 0;
  }
  const double estimate = ball_measure<3>(r1) * hits / in_ball1;
  EXPECT_NEAR(lens_volume(r1, r2, d), estimate, 0.01 * ball_measure<3>(r1));
}

}  // namespace
}  // namespace fp
