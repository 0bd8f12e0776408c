// The metrics' own broad phase against brute force: dense and sparse cell tables, wide radius
// ratios (several levels), large coordinate offsets, excluded non-finite balls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "core/metrics/cell_list.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

// Candidate pairs of the cell list; fails on a duplicate or a pair not in i < j order.
template <int D>
PairSet candidates(const CellList<D>& cells) {
  PairSet seen;
  cells.for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
    EXPECT_LT(i, j);
    EXPECT_TRUE(seen.emplace(i, j).second) << "pair " << i << "-" << j << " visited twice";
  });
  return seen;
}

template <int D>
void expect_complete(const Packing<D>& p, double reach_rel, const CellList<D>& cells) {
  const PairSet seen = candidates(cells);
  for (const auto& pr : test::brute_force_pairs(p, reach_rel))
    EXPECT_TRUE(seen.count(pr)) << "missed pair " << pr.first << "-" << pr.second;
  // Candidates are box-overlap pairs: none is far away.
  for (const auto& [i, j] : seen)
    EXPECT_LE((p.centers[i] - p.centers[j]).cwiseAbs().maxCoeff(), (p.radii[i] + p.radii[j]) * (1.0 + reach_rel) * 1.000001);
}

template <int D>
Packing<D> random_balls(std::size_t n, double box, double r_lo, double r_hi, bool log_uniform, std::uint64_t seed,
                        double offset = 0.0) {
  Rng rng(seed);
  Packing<D> p;
  for (std::size_t k = 0; k < n; ++k) {
    Vec<D> c;
    for (int a = 0; a < D; ++a) c[a] = offset + rng.uniform(0.0, box);
    const double r = log_uniform ? r_lo * std::pow(r_hi / r_lo, rng.uniform01()) : rng.uniform(r_lo, r_hi);
    p.add(c, r);
  }
  return p;
}

TEST(CellList, FindsEveryClosePairOnce3D) {
  const auto p = random_balls<3>(3000, 20.0, 0.5, 1.0, false, 1);
  const CellList<3> cells(p.centers, p.radii, 0.0);
  EXPECT_EQ(cells.level_count(), 1);
  EXPECT_EQ(cells.sparse_levels(), 0);
  expect_complete(p, 0.0, cells);
}

TEST(CellList, FindsEveryClosePairOnce2D) {
  const auto p = random_balls<2>(3000, 60.0, 0.5, 1.0, false, 2);
  const CellList<2> cells(p.centers, p.radii, 0.0);
  expect_complete(p, 0.0, cells);
}

TEST(CellList, ReachWidensTheSearch) {
  const auto p = random_balls<3>(2000, 20.0, 0.5, 1.0, false, 3);
  const CellList<3> cells(p.centers, p.radii, 0.25);
  expect_complete(p, 0.25, cells);
  EXPECT_GT(test::brute_force_pairs(p, 0.25).size(), test::brute_force_pairs(p, 0.0).size());
}

TEST(CellList, WideRadiusRatioUsesLevelsAndStaysComplete) {
  for (const int seed : {4, 5}) {
    const auto p3 = random_balls<3>(3000, 30.0, 0.04, 2.0, true, seed);  // r_max / r_min = 50
    const CellList<3> c3(p3.centers, p3.radii, 0.0);
    EXPECT_GE(c3.level_count(), 3);
    expect_complete(p3, 0.0, c3);
    const auto p2 = random_balls<2>(3000, 80.0, 0.04, 2.0, true, seed);
    const CellList<2> c2(p2.centers, p2.radii, 0.0);
    EXPECT_GE(c2.level_count(), 3);
    expect_complete(p2, 0.0, c2);
  }
}

TEST(CellList, SparseTableForSpreadOutBalls) {
  // Clusters far apart: the bounding box is mostly empty, so the cell table is hashed.
  Packing<3> p;
  Rng rng(6);
  for (int cluster = 0; cluster < 20; ++cluster) {
    const Vec3 at(1e4 * rng.uniform01(), 1e4 * rng.uniform01(), 1e4 * rng.uniform01());
    for (int k = 0; k < 100; ++k)
      p.add(at + Vec3(rng.uniform(0, 8), rng.uniform(0, 8), rng.uniform(0, 8)), rng.uniform(0.3, 1.0));
  }
  const CellList<3> cells(p.centers, p.radii, 0.0);
  EXPECT_GE(cells.sparse_levels(), 1);
  expect_complete(p, 0.0, cells);
}

TEST(CellList, LargeCoordinateOffsetKeepsTouchingPairs) {
  // Touching simple cubic lattice at 1e6: every lattice contact is at exactly the reach.
  const auto lat = test::simple_cubic(8, 0.75, Vec3(1e6, -1e6, 1e6));
  const CellList<3> cells(lat.packing.centers, lat.packing.radii, 0.0);
  const PairSet seen = candidates(cells);
  std::size_t touching = 0;
  for (const auto& [i, j] : seen)
    touching += (lat.packing.centers[i] - lat.packing.centers[j]).norm() <= 0.75 * (1 + 1e-9) ? 1 : 0;
  EXPECT_EQ(touching, 3u * 8 * 8 * 7);
  const auto p = random_balls<3>(2000, 20.0, 0.5, 1.0, false, 7, 1e6);
  expect_complete(p, 0.0, CellList<3>(p.centers, p.radii, 0.0));
}

TEST(CellList, LeavesOutNonFiniteAndNegativeBalls) {
  auto p = random_balls<3>(500, 10.0, 0.5, 1.0, false, 8);
  p.centers[3][1] = std::numeric_limits<double>::quiet_NaN();
  p.radii[5] = std::numeric_limits<double>::infinity();
  p.radii[9] = -1.0;
  const CellList<3> cells(p.centers, p.radii, 0.0);
  EXPECT_EQ(cells.indexed(), 497u);
  const PairSet seen = candidates(cells);
  for (const auto& [i, j] : seen)
    for (const std::uint32_t bad : {3u, 5u, 9u}) EXPECT_TRUE(i != bad && j != bad);
}

// The parts threads share: every pair in exactly one part, for any number of parts, on dense,
// sparse and multi-level tables.
TEST(CellList, PartsCoverEveryPairOnce) {
  Packing<3> sparse;
  Rng rng(12);
  for (int cluster = 0; cluster < 10; ++cluster) {
    const Vec3 at(1e4 * rng.uniform01(), 1e4 * rng.uniform01(), 1e4 * rng.uniform01());
    for (int k = 0; k < 100; ++k)
      sparse.add(at + Vec3(rng.uniform(0, 8), rng.uniform(0, 8), rng.uniform(0, 8)), rng.uniform(0.3, 1.0));
  }
  for (const Packing<3>& p : {random_balls<3>(2000, 20.0, 0.5, 1.0, false, 13),
                              random_balls<3>(2000, 30.0, 0.04, 2.0, true, 14), sparse}) {
    const CellList<3> cells(p.centers, p.radii, 1e-9);
    const PairSet whole = candidates(cells);
    for (const std::size_t parts : {1u, 2u, 3u, 7u, 64u, 5000u}) {
      PairSet seen;
      for (std::size_t part = 0; part < parts; ++part)
        cells.for_each_candidate_pair(part, parts, [&](std::uint32_t i, std::uint32_t j) {
          EXPECT_TRUE(seen.emplace(i, j).second) << "pair " << i << "-" << j << " in two parts of " << parts;
        });
      EXPECT_EQ(seen, whole) << parts << " parts";
    }
  }
}

TEST(CellList, DegenerateInputs) {
  Packing<3> empty;
  EXPECT_TRUE(candidates(CellList<3>(empty.centers, empty.radii)).empty());
  Packing<2> points;  // zero radii at one point: every pair is at distance 0 <= 0
  for (int k = 0; k < 4; ++k) points.add(Vec2(0, 0), 0.0);
  EXPECT_EQ(candidates(CellList<2>(points.centers, points.radii)).size(), 6u);
  Packing<3> p;
  p.add(Vec3(0, 0, 0), 1.0);
  EXPECT_THROW(CellList<3>(p.centers, p.radii, -0.1), std::invalid_argument);
  p.radii.push_back(1.0);
  EXPECT_THROW(CellList<3>(p.centers, p.radii), std::invalid_argument);
}

}  // namespace
}  // namespace fp
