// The analytic solver: one sphere tangent to three (general path and the front's batched Session).
#include <benchmark/benchmark.h>

#include <vector>

#include "contact/sphere_contact_solver.hpp"
#include "core/sampling/rng.hpp"

namespace {

using namespace fp;

/// Random solvable triples: three unit-ish spheres around a mobile one, all touching it.
std::vector<std::array<Body<3>, 3>> make_triples(int n, double r) {
  Rng rng(7);
  std::vector<std::array<Body<3>, 3>> out;
  for (int k = 0; k < n; ++k) {
    std::array<Body<3>, 3> t;
    for (auto& b : t) {
      const double z = 2 * rng.uniform01() - 1, phi = 2 * kPi * rng.uniform01(), s = std::sqrt(1 - z * z);
      const double rb = rng.uniform(1.0, 2.0);
      b = Body<3>::sphere(Vec3(s * std::cos(phi), s * std::sin(phi), z) * (rb + r), rb);
    }
    out.push_back(t);
  }
  return out;
}

void BM_SphereSolve(benchmark::State& state) {
  const double r = 1.5;
  const auto triples = make_triples(1024, r);
  SphereContactSolver<3> solver;
  std::array<Placement<3>, 4> out;
  std::size_t k = 0;
  for (auto _ : state) {
    const auto& t = triples[k++ & 1023];
    benchmark::DoNotOptimize(solver.solve(t, Mobile<3>{r}, out));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SphereSolve);

void BM_SphereSessionPair(benchmark::State& state) {
  // One front particle and 40 neighbours (a typical |V|), all pairs.
  Rng rng(3);
  const double r = 1.5;
  std::vector<Body<3>> bodies;
  for (int k = 0; k < 40; ++k) {
    const double z = 2 * rng.uniform01() - 1, phi = 2 * kPi * rng.uniform01(), s = std::sqrt(1 - z * z);
    const double rb = rng.uniform(1.0, 2.0);
    bodies.push_back(Body<3>::sphere(Vec3(s * std::cos(phi), s * std::sin(phi), z) * (1.5 + rb + rng.uniform(0, 2)), rb));
  }
  SphereContactSolver<3>::Session session;
  session.begin(Body<3>::sphere(Vec3::Zero(), 1.5), r, bodies);
  std::array<Placement<3>, 4> out;
  for (auto _ : state)
    for (int j = 1; j < 40; ++j)
      for (int i = 0; i < j; ++i) benchmark::DoNotOptimize(session.solve(i, j, out));
  state.SetItemsProcessed(state.iterations() * 40 * 39 / 2);
}
BENCHMARK(BM_SphereSessionPair);

}  // namespace
