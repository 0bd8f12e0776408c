// PolygonContainer queries on polygons of 10^5 vertices (radius 0.5, as in
// experiments/polygon-containers): a regular n-gon (convex) and a star whose 5 * 10^4 teeth are
// 0.05 deep (half the vertices reflex). Query points are uniform in the bounding box (most of
// them deep inside, where every edge of the n-gon is nearly as close as the nearest) or within
// 0.03 of the boundary (reach 0.06, as the front asks for walls around a particle of radius 0.02).
// Construction is timed too: the simplicity sweep, the edge tree and the deepest-point search.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "core/geometry/polygon_container.hpp"
#include "core/sampling/rng.hpp"

namespace {

using namespace fp;

std::vector<Vec2> polygon(bool star, int n) {
  std::vector<Vec2> v;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / n, r = star && k % 2 ? 0.45 : 0.5;
    v.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return v;
}

const PolygonContainer& container(bool star, int n) {
  static std::map<std::pair<bool, int>, std::unique_ptr<PolygonContainer>> made;
  auto& c = made[{star, n}];
  if (!c) c = std::make_unique<PolygonContainer>(polygon(star, n));
  return *c;
}

// 4096 points: anywhere in the box, or near the boundary (radius 0.47 .. 0.53).
std::vector<Vec2> points(bool near_boundary) {
  Rng rng(near_boundary ? 2 : 1);
  std::vector<Vec2> out;
  while (out.size() < 4096) {
    if (near_boundary) {
      const double a = rng.uniform(0, 2 * kPi), r = rng.uniform(0.47, 0.53);
      out.emplace_back(r * std::cos(a), r * std::sin(a));
    } else {
      out.emplace_back(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5));
    }
  }
  return out;
}

// Args: star (0/1), near boundary (0/1).
void BM_PolygonSignedDistance(benchmark::State& state) {
  const PolygonContainer& c = container(state.range(0) != 0, 100000);
  const std::vector<Vec2> p = points(state.range(1) != 0);
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.signed_distance(p[k]));
    k = (k + 1) % p.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PolygonSignedDistance)->ArgNames({"star", "near"})->ArgsProduct({{0, 1}, {0, 1}});

void BM_PolygonWallsNear(benchmark::State& state) {
  const PolygonContainer& c = container(state.range(0) != 0, 100000);
  const std::vector<Vec2> p = points(true);
  std::vector<Wall<2>> walls;
  std::size_t k = 0, found = 0;
  for (auto _ : state) {
    walls.clear();
    c.walls_near(p[k], 0.06, walls);
    found += walls.size();
    k = (k + 1) % p.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["walls"] = static_cast<double>(found) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_PolygonWallsNear)->ArgNames({"star"})->Arg(0)->Arg(1);

void BM_PolygonContainsBall(benchmark::State& state) {
  const PolygonContainer& c = container(state.range(0) != 0, 100000);
  const std::vector<Vec2> p = points(false);
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.contains_ball(p[k], 0.02));
    k = (k + 1) % p.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PolygonContainsBall)->ArgNames({"star"})->Arg(0)->Arg(1);

// Args: star (0/1), vertices.
void BM_PolygonConstruct(benchmark::State& state) {
  const std::vector<Vec2> v = polygon(state.range(0) != 0, static_cast<int>(state.range(1)));
  for (auto _ : state) {
    PolygonContainer c(v);
    benchmark::DoNotOptimize(c.interior_point());
  }
  state.SetItemsProcessed(state.iterations() * state.range(1));
}
BENCHMARK(BM_PolygonConstruct)
    ->ArgNames({"star", "n"})
    ->ArgsProduct({{0, 1}, {10000, 100000}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
