// The broad phase: neighbour queries of the size the front makes (reach r0 + 2r).
#include <benchmark/benchmark.h>

#include <vector>

#include "core/geometry/neighbour_grid.hpp"
#include "core/sampling/rng.hpp"

namespace {

using namespace fp;

void BM_GridQuery(benchmark::State& state) {
  const double ratio = static_cast<double>(state.range(0));
  const double r_min = 0.01, r_max = r_min * ratio;
  Rng rng(11);
  Aabb<3> box;
  box.lo = Vec3::Zero();
  box.hi = Vec3::Constant(1.0);
  NeighbourGrid<3> grid(box, r_min, r_max);
  std::vector<Vec3> c;
  for (int k = 0; k < 200000; ++k) {
    c.emplace_back(rng.uniform01(), rng.uniform01(), rng.uniform01());
    grid.insert(k, c.back(), rng.uniform(r_min, r_max));
  }
  std::size_t k = 0;
  long visited = 0;
  for (auto _ : state) {
    grid.for_each_near(c[k++ % c.size()], 3 * r_min, [&](int id) { visited += id; });
  }
  benchmark::DoNotOptimize(visited);
  state.counters["levels"] = grid.levels();
}
BENCHMARK(BM_GridQuery)->Arg(2)->Arg(7)->Arg(50);

}  // namespace
