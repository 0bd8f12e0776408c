// EdgeChainTree against loops over every edge, on chains that need not be simple.
#include "core/geometry/edge_chain_tree.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "core/sampling/rng.hpp"

namespace fp {
namespace {

double loop_min_distance2(const std::vector<Vec2>& v, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < v.size(); ++i) best = std::min(best, segment_distance2(p, v[i], v[(i + 1) % v.size()]));
  return best;
}

/// Sunday's winding-number term of edge a->b for p (as the polygon container's loop computes it)
/// and whether the loop finds p on that edge.
std::pair<int, bool> sunday_term(const Vec2& a, const Vec2& b, const Vec2& p) {
  const double o = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
  if (a.y() <= p.y()) {
    if (b.y() > p.y()) return {o > 0 ? 1 : 0, o == 0};
    const bool on = b.y() == p.y() && o == 0 && std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
                    std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
    return {0, on};
  }
  if (b.y() <= p.y()) return {o < 0 ? -1 : 0, o == 0};
  return {0, false};
}

/// A random walk (self-crossing allowed) of n vertices around `centre`, steps of about `step`.
std::vector<Vec2> random_walk(Rng& rng, int n, const Vec2& centre, double step) {
  std::vector<Vec2> v{centre};
  while (static_cast<int>(v.size()) < n) {
    const Vec2 next = v.back() + step * Vec2(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
    if (next != v.back()) v.push_back(next);
  }
  return v;
}

/// A regular n-gon: nearly every edge ties for nearest at the centre.
std::vector<Vec2> regular(int n, double radius, const Vec2& centre) {
  std::vector<Vec2> v;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * kPi * k / n;
    v.push_back(centre + radius * Vec2(std::cos(a), std::sin(a)));
  }
  return v;
}

void check_chain(const std::vector<Vec2>& v, Rng& rng, int points) {
  const EdgeChainTree tree(v);
  const int n = static_cast<int>(v.size());
  ASSERT_EQ(tree.size(), n);
  const Aabb<2> b = tree.bounds();
  const Vec2 pad = 0.3 * b.size() + Vec2::Constant(1e-300);
  for (int k = 0; k < points; ++k) {
    Vec2 p(rng.uniform(b.lo.x() - pad.x(), b.hi.x() + pad.x()), rng.uniform(b.lo.y() - pad.y(), b.hi.y() + pad.y()));
    if (k % 4 == 1) {  // within 1e-12 of an edge, or on a vertex
      const int i = static_cast<int>(rng.uniform(0.0, n - 1e-9));
      const Vec2 a = v[i], c = v[(i + 1) % n];
      const Vec2 normal = Vec2(a.y() - c.y(), c.x() - a.x()).normalized();
      p = a + rng.uniform(0.0, 1.0) * (c - a) + rng.uniform(-1e-12, 1e-12) * b.size().norm() * normal;
      if (k % 8 == 1) p = a;
    }
    if (k % 4 == 2) p.y() = v[static_cast<std::size_t>(rng.uniform(0.0, n - 1e-9))].y();  // at a vertex's height
    const double want = loop_min_distance2(v, p);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(tree.min_distance2(p)), std::bit_cast<std::uint64_t>(want))
        << "n = " << n << ", p = " << p.transpose();
    const double d = std::sqrt(want);
    for (const double radius : {d, std::nextafter(d, 0.0), std::nextafter(d, 1e300), 2 * d, 0.5 * d, 0.0}) {
      bool any = false;
      std::set<int> near;
      for (int i = 0; i < n; ++i) {
        const double di = std::sqrt(segment_distance2(p, v[i], v[(i + 1) % n]));
        any = any || di < radius;
        if (di <= radius) near.insert(i);
      }
      EXPECT_EQ(tree.any_edge_closer_than(p, radius), any) << "radius " << radius;
      std::vector<int> got;
      tree.for_each_edge_near(p, radius, [&](int i) { got.push_back(i); });
      EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
      for (const int i : near) EXPECT_TRUE(std::binary_search(got.begin(), got.end(), i)) << "edge " << i;
    }
    // Sunday's loop: the edges the tree sums must add up to what the loop finds for them, and
    // none of them may hold p.
    int called_sum = 0, loop_sum = 0;
    std::set<int> called;
    const int beyond = tree.winding_beyond(p, [&](int i) {
      EXPECT_TRUE(called.insert(i).second);
      called_sum += sunday_term(v[i], v[(i + 1) % n], p).first;
    });
    for (int i = 0; i < n; ++i) {
      const auto [term, on_edge] = sunday_term(v[i], v[(i + 1) % n], p);
      loop_sum += term;
      if (on_edge) {
        EXPECT_TRUE(called.count(i)) << "edge " << i;
      }
      // An edge meeting p's height within 1e-9 (relative) of p: its term needs the loop's orient().
      const Vec2 a = v[i], c = v[(i + 1) % n];
      if (std::min(a.y(), c.y()) <= p.y() && p.y() <= std::max(a.y(), c.y()) && a.y() != c.y()) {
        const double xc = a.x() + (c.x() - a.x()) * (p.y() - a.y()) / (c.y() - a.y());
        if (std::abs(xc - p.x()) <= 1e-9 * b.size().norm()) {
          EXPECT_TRUE(called.count(i)) << "edge " << i;
        }
      }
    }
    EXPECT_EQ(beyond + called_sum, loop_sum) << "n = " << n << ", p = " << p.transpose();
  }
}

TEST(EdgeChainTree, QueriesEqualTheLoopsOnRandomChains) {
  Rng rng(7);
  for (const int n : {2, 3, 7, 8, 9, 16, 17, 65, 1000})
    check_chain(random_walk(rng, n, Vec2(0.3, -0.2), 0.1), rng, 200);
}

TEST(EdgeChainTree, QueriesEqualTheLoopsFarFromTheOriginAndAtTinyScales) {
  Rng rng(8);
  check_chain(random_walk(rng, 300, Vec2(1e6, -3e6), 0.01), rng, 300);
  check_chain(random_walk(rng, 300, Vec2(1e-7, 2e-7), 1e-9), rng, 300);
}

TEST(EdgeChainTree, NearestEdgeNearTheCentreOfAFineRegularPolygon) {
  Rng rng(9);
  const std::vector<Vec2> v = regular(20000, 0.5, Vec2(0.1, 0.2));
  const EdgeChainTree tree(v);
  for (int k = 0; k < 100; ++k) {
    const Vec2 p = Vec2(0.1, 0.2) + Vec2(rng.uniform(-1e-4, 1e-4), rng.uniform(-1e-4, 1e-4)) * (k % 10);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(tree.min_distance2(p)), std::bit_cast<std::uint64_t>(loop_min_distance2(v, p)));
  }
}

TEST(EdgeChainTree, NonFinitePointsGiveWhatTheLoopsGive) {
  Rng rng(10);
  const std::vector<Vec2> v = random_walk(rng, 50, Vec2::Zero(), 1.0);
  const EdgeChainTree tree(v);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const Vec2& p : {Vec2(nan, 0), Vec2(0, nan), Vec2(inf, 0), Vec2(-inf, inf)}) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(tree.min_distance2(p)), std::bit_cast<std::uint64_t>(loop_min_distance2(v, p)));
    EXPECT_FALSE(tree.any_edge_closer_than(p, 1.0));
  }
}

TEST(EdgeChainTree, OverlappingPairsCoverEveryNonAdjacentPairWithMeetingBoxes) {
  Rng rng(11);
  for (const int n : {4, 9, 40, 300}) {
    const std::vector<Vec2> v = random_walk(rng, n, Vec2::Zero(), 1.0);
    const EdgeChainTree tree(v);
    std::set<std::pair<int, int>> got;
    int last_i = -1;
    tree.any_overlapping_pair([&](int i, int j) {
      EXPECT_LT(i + 1, j);
      EXPECT_FALSE(i == 0 && j == n - 1);
      EXPECT_GE(i, last_i);
      last_i = i;
      EXPECT_TRUE(got.insert({i, j}).second);
      return false;
    });
    for (int i = 0; i < n; ++i)
      for (int j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;
        const Vec2 lo1 = v[i].cwiseMin(v[(i + 1) % n]), hi1 = v[i].cwiseMax(v[(i + 1) % n]);
        const Vec2 lo2 = v[j].cwiseMin(v[(j + 1) % n]), hi2 = v[j].cwiseMax(v[(j + 1) % n]);
        if ((lo1.array() <= hi2.array()).all() && (lo2.array() <= hi1.array()).all()) {
          EXPECT_TRUE(got.count({i, j})) << i << " " << j;
        }
      }
    int calls = 0;  // stops at the first true
    EXPECT_EQ(tree.any_overlapping_pair([&](int, int) { return ++calls == 3; }), got.size() >= 3);
    EXPECT_EQ(calls, std::min<int>(3, static_cast<int>(got.size())));
  }
}

}  // namespace
}  // namespace fp
