// The broad phase: neighbour queries of the size the front makes (reach r0 + 2r), in a unit box
// holding as many random centres as a packing of VF 0.6 would (they overlap; the grid does not care).
#include <benchmark/benchmark.h>

#include <vector>

#include "core/geometry/neighbour_grid.hpp"
#include "core/sampling/rng.hpp"

namespace {

using namespace fp;

// range(0): r_max / r_min (r_max = 0.02); range(1): 0 = a small query (3 r_min, a small particle
// placed next to a small one), 1 = a big query (3 r_max, a big one next to a big one: the query
// that walks the fine levels through their top-level blocks).
void BM_GridQuery(benchmark::State& state) {
  const double ratio = static_cast<double>(state.range(0));
  const double r_max = 0.02, r_min = r_max / ratio;
  const double reach = state.range(1) ? 3 * r_max : 3 * r_min;
  // Uniform radii: E[r^3] = (r_max^4 - r_min^4) / (4 (r_max - r_min)).
  const double mean_r3 = (r_max * r_max * r_max * r_max - r_min * r_min * r_min * r_min) / (4 * (r_max - r_min));
  const int n = static_cast<int>(0.6 / (4.18879 * mean_r3));
  Rng rng(11);
  Aabb<3> box;
  box.lo = Vec3::Zero();
  box.hi = Vec3::Constant(1.0);
  NeighbourGrid<3> grid(box, r_min, r_max);
  std::vector<Vec3> c;
  for (int k = 0; k < n; ++k) {
    c.emplace_back(rng.uniform01(), rng.uniform01(), rng.uniform01());
    grid.insert(k, c.back(), rng.uniform(r_min, r_max));
  }
  std::size_t k = 0;
  long found = 0;
  for (auto _ : state) {
    grid.for_each_within(c[k++ % c.size()], reach, [&](int id, const Vec3&, double, double) { found += id; });
  }
  benchmark::DoNotOptimize(found);
  state.counters["levels"] = grid.levels();
  state.counters["particles"] = n;
}
BENCHMARK(BM_GridQuery)->Args({2, 0})->Args({2, 1})->Args({7, 0})->Args({7, 1})->Args({50, 0})->Args({50, 1});

}  // namespace
