// sort_doubles against std::sort: random values of every sign and magnitude, ties, infinities,
// signed zeros, subnormals, both sides of the radix threshold, and digits all keys share.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "core/sampling/rng.hpp"
#include "core/sampling/sort_doubles.hpp"

namespace fp {
namespace {

std::vector<double> random_values(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> v;
  v.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = rng.uniform01();
    switch (i % 5) {
      case 0: v.push_back(u); break;                                     // [0, 1)
      case 1: v.push_back(-1e6 * u); break;                              // negatives
      case 2: v.push_back(std::ldexp(u, static_cast<int>(i % 600) - 300)); break;  // magnitudes 2^-300..2^300
      case 3: v.push_back(static_cast<double>(i % 7)); break;            // ties
      default: v.push_back((u - 0.5) * 1e-310); break;                   // subnormals, both signs
    }
  }
  return v;
}

void expect_sorted_like_std(std::vector<double> v) {
  std::vector<double> expected = v;
  std::sort(expected.begin(), expected.end());
  sort_doubles(v);
  ASSERT_EQ(v.size(), expected.size());
  EXPECT_TRUE(std::is_sorted(v.begin(), v.end()));
  for (std::size_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], expected[i]) << "at " << i;  // -0.0 == 0.0
}

TEST(SortDoubles, MatchesStdSortBelowAndAboveTheRadixThreshold) {
  for (const std::size_t n : {0u, 1u, 2u, 1000u, 16383u, 16384u, 100000u, 300001u})
    expect_sorted_like_std(random_values(n, 7 + n));
}

TEST(SortDoubles, InfinitiesSignedZerosAndSharedDigits) {
  std::vector<double> v = random_values(50000, 3);
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < v.size(); i += 97) v[i] = (i % 2) ? inf : -inf;
  for (std::size_t i = 5; i < v.size(); i += 89) v[i] = (i % 2) ? 0.0 : -0.0;
  expect_sorted_like_std(v);
  sort_doubles(v);
  EXPECT_EQ(v.front(), -inf);
  EXPECT_EQ(v.back(), inf);
  // Radii of one binade: sign and exponent shared by every key (passes skipped).
  std::vector<double> radii;
  Rng rng(11);
  for (int i = 0; i < 40000; ++i) radii.push_back(0.01 + 0.005 * rng.uniform01());
  expect_sorted_like_std(radii);
  // All equal: every pass skipped.
  expect_sorted_like_std(std::vector<double>(30000, 0.25));
}

TEST(SortDoubles, NegativeZeroBeforePositiveZero) {
  std::vector<double> v(20000, 0.0);
  for (std::size_t i = 0; i < v.size(); i += 2) v[i] = -0.0;
  sort_doubles(v);
  EXPECT_TRUE(std::signbit(v[9999]));
  EXPECT_FALSE(std::signbit(v[10000]));
}

}  // namespace
}  // namespace fp
