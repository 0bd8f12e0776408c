// Convex polygon operations (core/geometry/convex_polygon.hpp) against brute force: the edge merge
// of the Minkowski difference against the hull of every difference, the one-pass reduction of a
// convex cycle against the monotone chain, the convexity test on polygons known to be (or not be)
// convex, and the distance and nearest points of apart polygons against the largest separation
// over directions.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/geometry/convex_polygon.hpp"

namespace fp {
namespace {

using namespace convex_polygon;

/// A random convex polygon (the hull of 3..12 random points in a disk of radius `size` about
/// `centre`), counter-clockwise without collinear points.
std::vector<Vec2> random_convex(std::mt19937_64& rng, double size, const Vec2& centre) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> n_points(3, 12);
  for (;;) {
    std::vector<Vec2> p;
    const int n = n_points(rng);
    while (static_cast<int>(p.size()) < n) {
      const Vec2 x(u(rng), u(rng));
      if (x.squaredNorm() <= 1) p.push_back(centre + size * x);
    }
    std::vector<Vec2> h = hull(p);
    if (h.size() >= 3) return h;
  }
}

std::vector<Vec2> turned(const std::vector<Vec2>& p, double angle, const Vec2& about) {
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<Vec2> q;
  for (const Vec2& x : p) {
    const Vec2 d = x - about;
    q.push_back(about + Vec2(c * d.x() - s * d.y(), s * d.x() + c * d.y()));
  }
  return q;
}

/// The hull of every difference f_i - m_j: the Minkowski difference by definition.
std::vector<Vec2> brute_difference(const std::vector<Vec2>& f, const std::vector<Vec2>& m) {
  std::vector<Vec2> all;
  for (const Vec2& a : f)
    for (const Vec2& b : m) all.push_back(a - b);
  return hull(all);
}

std::vector<Vec2> merged_difference(const std::vector<Vec2>& f, const std::vector<Vec2>& m) {
  std::vector<Vec2> sum, out;
  append_minkowski_difference(f, m, sum, out);
  return out;
}

TEST(ConvexPolygon, MinkowskiDifferenceByEdgeMergeIsTheHullOfEveryDifference) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int identical = 0, trials = 0;
  for (int t = 0; t < 3000; ++t) {
    // Sizes 1:100, centres up to 1e6 away, and every tenth mobile the fixed polygon itself turned
    // by 1e-9 rad (near-parallel edges) or not at all (parallel edges, taken at once).
    const double offset = t % 3 == 0 ? 1e6 : 0;
    const Vec2 centre(offset + u(rng), offset - u(rng));
    const std::vector<Vec2> f = random_convex(rng, 0.01 + u(rng), centre);
    std::vector<Vec2> m = random_convex(rng, 0.01 + u(rng), Vec2(u(rng), u(rng)));
    if (t % 10 == 0) m = turned(f, t % 20 == 0 ? 0.0 : 1e-9, centre);
    const std::vector<Vec2> merged = merged_difference(f, m), brute = brute_difference(f, m);
    ++trials;
    if (merged == brute) {
      ++identical;
      continue;
    }
    // Where rounding decides a near-collinear point differently, both are the same polygon to
    // rounding: every difference inside the merged one, within 1e-12 of the sizes.
    ASSERT_TRUE(t % 10 == 0) << "a generic pair gave another polygon than the brute-force hull, trial " << t;
    std::vector<Vec2> normals;
    for (std::size_t i = 0; i < merged.size(); ++i) normals.push_back(outward(merged[(i + 1) % merged.size()] - merged[i]));
    for (const Vec2& a : f)
      for (const Vec2& b : m) EXPECT_LE(signed_distance(merged, normals, a - b), 1e-12 * (1 + offset)) << t;
  }
  std::printf("  %d of %d merged differences identical to the brute-force hull\n", identical, trials);
  EXPECT_GE(identical, trials * 9 / 10);
}

TEST(ConvexPolygon, DifferencesWithPointsAndSegmentsFallBackToTheHull) {
  const std::vector<Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Vec2> point{{0.25, 0.5}}, segment{{0, 0}, {2, 1}};
  EXPECT_EQ(merged_difference(square, point), brute_difference(square, point));
  EXPECT_EQ(merged_difference(square, segment), brute_difference(square, segment));
  EXPECT_EQ(merged_difference(segment, segment), brute_difference(segment, segment));  // a segment twice as long
  EXPECT_EQ(merged_difference(point, segment), brute_difference(point, segment));
}

TEST(ConvexPolygon, OnePassReductionOfAConvexCycleEqualsTheMonotoneChain) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int t = 0; t < 2000; ++t) {
    const std::vector<Vec2> p = random_convex(rng, 1, Vec2(u(rng), u(rng)));
    // The cycle from any vertex, with repeated points and midpoints of edges (collinear) inserted.
    std::vector<Vec2> cycle;
    const std::size_t start = static_cast<std::size_t>(t) % p.size();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2& a = p[(start + i) % p.size()];
      const Vec2& b = p[(start + i + 1) % p.size()];
      cycle.push_back(a);
      if (t % 3 == 0) cycle.push_back(a);
      if (t % 5 == 0) cycle.push_back(0.5 * (a + b));
    }
    std::vector<Vec2> one_pass, scratch = cycle;
    ASSERT_TRUE(append_convex_cycle(cycle, one_pass));
    std::vector<Vec2> chain;
    append_hull(scratch, chain);
    EXPECT_EQ(one_pass, chain) << t;
  }
  // Fewer than three distinct points: declined, nothing appended.
  std::vector<Vec2> out{{5, 5}};
  EXPECT_FALSE(append_convex_cycle(std::vector<Vec2>{{0, 0}, {1, 1}, {2, 2}, {1, 1}}, out));
  EXPECT_FALSE(append_convex_cycle(std::vector<Vec2>{{3, 3}, {3, 3}, {3, 3}}, out));
  EXPECT_EQ(out.size(), 1u);
}

TEST(ConvexPolygon, StrictConvexityNeedsLeftTurnsAndOneWinding) {
  for (int n : {3, 4, 6, 17}) {
    std::vector<Vec2> regular;
    for (int i = 0; i < n; ++i) regular.push_back(Vec2(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)));
    for (const double angle : {0.0, 0.3, 2.0, -1.0}) {
      const std::vector<Vec2> p = turned(regular, angle, Vec2(1e6, -3));
      EXPECT_TRUE(strictly_convex_ccw(p)) << n << " " << angle;
      EXPECT_FALSE(strictly_convex_ccw(std::vector<Vec2>(p.rbegin(), p.rend()))) << "clockwise " << n;
    }
    std::vector<Vec2> with_midpoint = regular;
    with_midpoint.insert(with_midpoint.begin() + 1, 0.5 * (regular[0] + regular[1]));
    EXPECT_FALSE(strictly_convex_ccw(with_midpoint)) << "collinear " << n;
  }
  std::vector<Vec2> pentagram;  // every turn to the left, winding twice
  for (int i = 0; i < 5; ++i) pentagram.push_back(Vec2(std::cos(4 * kPi * i / 5), std::sin(4 * kPi * i / 5)));
  EXPECT_FALSE(strictly_convex_ccw(pentagram));
}

/// The distance of two apart convex sets is the largest separation over directions u:
/// min_b u.b - max_a u.a (sampled, then refined by golden sections around the best sample).
double separation_reference(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  const auto separation = [&](double angle) {
    const Vec2 u(std::cos(angle), std::sin(angle));
    double max_a = -1e300, min_b = 1e300;
    for (const Vec2& p : a) max_a = std::max(max_a, u.dot(p));
    for (const Vec2& p : b) min_b = std::min(min_b, u.dot(p));
    return min_b - max_a;
  };
  const int samples = 4096;
  double best = -1e300, best_angle = 0;
  for (int i = 0; i < samples; ++i) {
    const double angle = 2 * kPi * i / samples;
    if (const double s = separation(angle); s > best) best = s, best_angle = angle;
  }
  double lo = best_angle - 2 * kPi / samples, hi = best_angle + 2 * kPi / samples;
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  for (int it = 0; it < 200; ++it) {
    const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    if (separation(x1) < separation(x2)) lo = x1;
    else hi = x2;
  }
  return std::max(best, separation(0.5 * (lo + hi)));
}

TEST(ConvexPolygon, DistanceOfApartPolygonsIsTheLargestSeparation) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  int apart = 0;
  for (int t = 0; t < 400; ++t) {
    const std::vector<Vec2> a = random_convex(rng, 0.5 + u(rng), Vec2::Zero());
    const double angle = 2 * kPi * u(rng);
    const std::vector<Vec2> b = random_convex(rng, 0.5 + u(rng), (2.2 + 2 * u(rng)) * Vec2(std::cos(angle), std::sin(angle)));
    const double reference = separation_reference(a, b);
    if (!(reference > 1e-9)) continue;
    ++apart;
    EXPECT_NEAR(apart_distance(a, b), reference, 1e-12) << t;
    EXPECT_NEAR(apart_distance(b, a), reference, 1e-12) << t;
    // The nearest points lie on the boundaries, as far apart as the distance.
    Vec2 on_a, on_b;
    const double d = apart_nearest(a, b, on_a, on_b);
    EXPECT_NEAR((on_b - on_a).norm(), d, 1e-14 * (1 + d)) << t;
    const auto normals_of = [](const std::vector<Vec2>& p) {
      std::vector<Vec2> n;
      for (std::size_t i = 0; i < p.size(); ++i) n.push_back(outward(p[(i + 1) % p.size()] - p[i]));
      return n;
    };
    EXPECT_NEAR(signed_distance(a, normals_of(a), on_a), 0, 1e-14) << t;
    EXPECT_NEAR(signed_distance(b, normals_of(b), on_b), 0, 1e-14) << t;
  }
  EXPECT_GT(apart, 100);
}

}  // namespace
}  // namespace fp
