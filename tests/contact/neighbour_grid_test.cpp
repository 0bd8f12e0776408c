// NeighbourGrid (core/geometry/neighbour_grid.hpp) against brute force: for random particles with
// uniform radii and wide ranges (r_max / r_min = 1, 7, 50, 1000, so the hierarchy of grids is
// exercised), for_each_near(c, reach, f) visits a superset of {k : |c - c_k| <= reach + r_k},
// each particle at most once, only inserted ids, and stays local (it does not simply visit
// everything). Query points outside the domain and reaches bigger than the domain included.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include "core/geometry/neighbour_grid.hpp"
#include "core/sampling/rng.hpp"

namespace fp {
namespace {

template <int D>
Vec<D> uniform_in(Rng& rng, const Vec<D>& lo, const Vec<D>& hi) {
  Vec<D> v;
  for (int a = 0; a < D; ++a) v[a] = rng.uniform(lo[a], hi[a]);
  return v;
}

struct GridCase {
  double ratio;
  int particles;
  int queries;
  double domain;                 ///< side of the cubic domain, in units of r_max
  std::size_t max_cells = std::size_t(1) << 26;
};

struct GridTally {
  long visits = 0, required = 0, queries = 0;
};

template <int D>
void run_grid_case(const GridCase& gc, std::uint64_t seed, GridTally& t) {
  Rng rng(seed);
  const double r_max = 1.0, r_min = r_max / gc.ratio;
  Aabb<D> domain;
  domain.lo = Vec<D>::Constant(-0.5 * gc.domain);
  domain.hi = Vec<D>::Constant(0.5 * gc.domain);
  const NeighbourGrid<D> empty(domain, r_min, r_max, 2.0, 4.0, gc.max_cells);
  NeighbourGrid<D> grid(domain, r_min, r_max, 2.0, 4.0, gc.max_cells);
  double max_cell = 0;
  for (int l = 0; l < grid.levels(); ++l) max_cell = std::max(max_cell, grid.cell_size(l));

  // Particles: radii log-uniform, plus the exact ends and octave boundaries; ids sparse (3k + 1)
  // so that never-inserted ids exist; a few centres slightly outside the domain (clamped cells).
  std::vector<Vec<D>> c;
  std::vector<double> r;
  std::vector<int> id;
  for (int k = 0; k < gc.particles; ++k) {
    double rk = r_min * std::pow(gc.ratio, rng.uniform01());
    if (k % 50 == 0) rk = r_min;
    if (k % 50 == 1) rk = r_max;
    if (k % 50 == 2) rk = std::max(r_min, std::ldexp(r_max, -static_cast<int>(rng.below(12))));
    Vec<D> ck = uniform_in<D>(rng, domain.lo, domain.hi);
    if (k % 97 == 0) ck += 0.1 * gc.domain * Vec<D>::Ones();
    c.push_back(ck);
    r.push_back(rk);
    id.push_back(3 * k + 1);
    grid.insert(3 * k + 1, ck, rk);
  }
  const int n_ids = 3 * gc.particles + 3;
  std::vector<int> seen(n_ids, -1), count(n_ids, 0);

  for (int q = 0; q < gc.queries; ++q) {
    // Query points: mostly inside, some far outside; reaches from tiny to beyond the domain.
    Vec<D> cq = uniform_in<D>(rng, domain.lo, domain.hi);
    const int kind = q % 10;
    if (kind == 7) cq = uniform_in<D>(rng, domain.lo, domain.hi) * 3.0;      // around the domain
    if (kind == 8) cq = Vec<D>::Constant(rng.uniform(-1e7, 1e7));            // far away
    double reach = r_min * std::pow(3 * gc.ratio, rng.uniform01());         // [r_min, 3 r_max]
    if (q % 50 == 9) reach = gc.domain * (q % 100 == 9 ? 2.0 : 1e3);         // bigger than the domain
    if (q % 100 == 3) reach = 0.0;
    for (int& k : count) k = 0;
    long visited = 0;
    bool local = true;
    grid.for_each_near(cq, reach, [&](int i) {
      ++visited;
      if (i < 0 || i >= n_ids) { local = false; return; }
      ++count[i];
      seen[i] = q;
    });
    empty.for_each_near(cq, reach, [&](int) { ADD_FAILURE() << "an empty grid reported a particle"; });
    ++t.queries;
    t.visits += visited;
    ASSERT_TRUE(local) << "id out of range";
    for (int k = 0; k < gc.particles; ++k) {
      const int i = id[k];
      ASSERT_LE(count[i], 1) << "particle " << i << " visited twice";
      const double d = (cq - c[k]).norm();
      if (d <= reach + r[k]) {
        ++t.required;
        ASSERT_EQ(count[i], 1) << "missed particle " << i << " at distance " << d << " for reach " << reach
                               << " + r " << r[k] << " (ratio " << gc.ratio << ", query " << q << ")";
      }
      // Locality: for centres and queries inside the domain, nothing beyond the query box of
      // its level (reach + r_top + one cell, r_top <= r_max) is visited.
      if (count[i] && domain.contains(cq) && domain.contains(c[k])) {
        ASSERT_LE((cq - c[k]).cwiseAbs().maxCoeff(), reach + r_max + max_cell) << "non-local visit";
      }
    }
    for (int i = 0; i < n_ids; ++i) {
      if (i % 3 != 1) {
        ASSERT_EQ(count[i], 0) << "visited an id that was never inserted";
      }
    }
  }
}

template <int D>
void run_ratio(const GridCase& gc, std::uint64_t seed) {
  GridTally t;
  const auto t0 = std::chrono::steady_clock::now();
  run_grid_case<D>(gc, seed, t);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "[ stats    ] " << D << "D ratio " << gc.ratio << ": " << t.queries << " queries, " << t.required
            << " required visits, " << t.visits << " visits, " << ms << " ms\n";
  EXPECT_GT(t.required, t.queries);  // the superset check had work to do
}

TEST(NeighbourGrid, VisitsASupersetOfTheBruteForceSetUniformRadii) {
  run_ratio<3>({1, 4000, 1500, 30}, 900);
  run_ratio<2>({1, 4000, 1500, 60}, 901);
}

TEST(NeighbourGrid, VisitsASupersetOfTheBruteForceSetRatio7) {
  run_ratio<3>({7, 4000, 1500, 30}, 902);
  run_ratio<2>({7, 4000, 1500, 60}, 903);
}

TEST(NeighbourGrid, VisitsASupersetOfTheBruteForceSetRatio50) {
  run_ratio<3>({50, 4000, 1500, 12}, 904);
  run_ratio<2>({50, 4000, 1500, 40}, 905);
}

TEST(NeighbourGrid, VisitsASupersetOfTheBruteForceSetRatio1000) {
  // 3D with a cell budget (the default would allocate ~2^26 cells on each fine level).
  run_ratio<3>({1000, 4000, 300, 8, std::size_t(1) << 20}, 906);
  run_ratio<2>({1000, 4000, 500, 16}, 907);
}

TEST(NeighbourGrid, CoarsenedLevelsStillVisitASuperset) {
  // A tight cell budget forces every level to coarsen (cells larger than factor * r_top).
  run_ratio<3>({50, 3000, 800, 20, 512}, 908);
  run_ratio<2>({50, 3000, 800, 40, 64}, 909);
}

TEST(NeighbourGrid, HugeReachesAndFarQueriesVisitEverythingInReach) {
  // Reaches far beyond the domain (up to infinity) and query points far outside it. The cell
  // range of such a query does not fit in an integer before clamping.
  for (const double ratio : {1.0, 50.0}) {
    Aabb<3> domain;
    domain.lo = Vec3::Constant(0);
    domain.hi = Vec3::Constant(10);
    NeighbourGrid<3> grid(domain, 1.0 / ratio, 1.0);
    Rng rng(910);
    const int n = 500;
    std::vector<Vec3> c;
    std::vector<double> r;
    for (int k = 0; k < n; ++k) {
      c.push_back(uniform_in<3>(rng, domain.lo, domain.hi));
      r.push_back(1.0 / ratio * std::pow(ratio, rng.uniform01()));
      grid.insert(k, c.back(), r.back());
    }
    int all = 0;
    for (const double reach : {1e3, 1e12, 1e19, 1e30, 1e300, std::numeric_limits<double>::infinity()}) {
      for (const Vec3& q : {Vec3(5, 5, 5), Vec3(-1e6, 3, 1e6), Vec3(-1e25, 1e25, 5), Vec3(1e300, 5, 5)}) {
        std::vector<int> count(n, 0);
        grid.for_each_near(q, reach, [&](int i) { ++count[i]; });
        int in_reach = 0;
        for (int k = 0; k < n; ++k) {
          ASSERT_LE(count[k], 1);
          if ((q - c[k]).norm() <= reach + r[k]) {
            ++in_reach;
            ASSERT_EQ(count[k], 1) << "particle " << k << ", reach " << reach << ", query (" << q.transpose()
                                   << "), ratio " << ratio;
          }
        }
        all += in_reach == n;
      }
    }
    EXPECT_GE(all, 15);  // most of these queries have every particle in reach
  }
}

TEST(NeighbourGrid, LevelsFollowTheRadiusOctaves) {
  Aabb<3> domain;
  domain.lo = Vec3::Constant(0);
  domain.hi = Vec3::Constant(40);
  auto levels = [&](double ratio) { return NeighbourGrid<3>(domain, 1.0, ratio).levels(); };
  EXPECT_EQ(levels(1), 1);
  EXPECT_EQ(levels(4), 1);  // at the default hierarchy threshold: one grid
  EXPECT_GT(levels(50), 1);
  // One level per octave of [r_min, r_max]: (r_max/2, r_max], (r_max/4, r_max/2], ...; the
  // finest one takes the rest. ceil(log2(ratio)) of them cover [r_min, r_max].
  EXPECT_EQ(levels(7), 3);     // 7, 3.5, 1.75 (holds [1, 1.75])
  EXPECT_EQ(levels(8), 3);     // 8, 4, 2 (holds [1, 2])
  EXPECT_EQ(levels(50), 6);    // 50 ... 1.5625
  EXPECT_EQ(levels(1000), 10); // 1000 ... 1.953125
  // Cells are cell_factor * r_top of their level, so each level holds radii it can see; in
  // particular the finest level is not finer than r_min needs: a level finer than that never
  // receives a particle but is scanned by every query, at the highest cost of all levels.
  // A fine level has at most 64 cells per top-level cell (4x finer per axis in 3D): finer ones
  // are coarsened in 1.26x steps (memory; big queries walk the top-level blocks anyway).
  Aabb<3> big;
  big.lo = Vec3::Constant(0);
  big.hi = Vec3::Constant(1000);
  const NeighbourGrid<3> g(big, 1.0, 50.0, 2.0);
  for (int l = 0; l < g.levels(); ++l) {
    const double natural = 2.0 * 50.0 / std::ldexp(1.0, l);
    if (l <= 2) EXPECT_DOUBLE_EQ(g.cell_size(l), natural) << "level " << l;
    EXPECT_GE(g.cell_size(l), natural) << "level " << l;
    EXPECT_LE(g.cell_size(l), std::max(natural, 1.26 * g.cell_size(0) / 4)) << "level " << l;
  }
  EXPECT_GE(g.cell_size(g.levels() - 1), 2.0 * 1.0);
}

TEST(NeighbourGrid, RejectsInvalidParameters) {
  Aabb<2> domain;
  domain.lo = Vec2::Constant(0);
  domain.hi = Vec2::Constant(1);
  EXPECT_THROW(NeighbourGrid<2>(domain, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(NeighbourGrid<2>(domain, 2.0, 1.0), std::invalid_argument);
  EXPECT_THROW(NeighbourGrid<2>(domain, 0.1, 1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(NeighbourGrid<2>(domain, std::nan(""), 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace fp

namespace fp {
namespace {

// erase + insert (a particle moved, graded stacking's reshape): queries then see the particle at
// its new centre only, for every level of a wide hierarchy, and the other particles unchanged.
TEST(NeighbourGrid, ErasedAndMovedParticlesAreFoundWhereTheyAre) {
  Rng rng(11);
  const Aabb<3> box{Vec3::Zero(), Vec3::Constant(10.0)};
  NeighbourGrid<3> grid(box, 0.01, 0.5, 2.0, 4.0);
  std::vector<Vec3> c;
  std::vector<double> r;
  for (int i = 0; i < 3000; ++i) {
    c.push_back(uniform_in<3>(rng, box.lo, box.hi));
    r.push_back(0.01 * std::pow(50.0, rng.uniform01()));
    grid.insert(i, c.back(), r.back());
  }
  for (int i = 0; i < 3000; i += 3) {  // move a third, erase a third for good
    grid.erase(i);
    c[i] = uniform_in<3>(rng, box.lo, box.hi);
    grid.insert(i, c[i], r[i]);
    if (i + 1 < 3000) grid.erase(i + 1);
  }
  for (int q = 0; q < 300; ++q) {
    const Vec3 x = uniform_in<3>(rng, box.lo, box.hi);
    const double reach = rng.uniform(0.0, 1.0);
    std::vector<int> seen;
    grid.for_each_within(x, reach, [&](int id, const Vec3& ck, double rk, double) {
      EXPECT_EQ(ck, c[id]);
      EXPECT_EQ(rk, r[id]);
      seen.push_back(id);
    });
    std::sort(seen.begin(), seen.end());
    std::vector<int> expected;
    for (int i = 0; i < 3000; ++i)
      if ((i % 3 != 1) && (c[i] - x).norm() <= reach + r[i]) expected.push_back(i);
    EXPECT_EQ(seen, expected) << "query " << q;
  }
}

}  // namespace
}  // namespace fp
