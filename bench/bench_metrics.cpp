// The whole packing analysis (core/metrics/packing_analysis.hpp) on front-packed boxes of
// 10^4, 10^5 and 10^6 spheres with radii U[0.01, 0.02] (the paper's case), box sized to be
// filled. Counters: spheres per second, contacts, and peak_rss_MB, the resident-memory high-water
// mark during the analysis (reset just before it; it includes the packing itself, 32 bytes a sphere).
// The packings are made once per process (the 10^6 one takes ~20 s).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "core/geometry/box_container.hpp"
#include "core/metrics/packing_analysis.hpp"
#include "core/metrics/validate.hpp"
#include "core/sampling/rng.hpp"
#include "core/sampling/sort_doubles.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "front/advancing_front.hpp"

namespace {

using namespace fp;

struct Scenario {
  BoxContainer<3> box;
  Packing<3> packing;
};

// Mean sphere volume of U[0.01, 0.02] radii is 4/3 pi E[r^3] = 1.571e-5; the front fills ~0.6.
const Scenario& scenario(std::int64_t n) {
  static std::map<std::int64_t, Scenario> made;
  auto it = made.find(n);
  if (it == made.end()) {
    const double side = std::cbrt(static_cast<double>(n) * 1.571e-5 / 0.6);
    BoxContainer<3> box(Vec3::Zero(), Vec3::Constant(side));
    const UniformRadius radii(0.01, 0.02);
    StopCriteria stop;
    stop.max_particles = static_cast<std::uint64_t>(n);
    Packing<3> p = AdvancingFront<3>(box, radii, PackerOptions{}, stop, 1).run().packing;
    it = made.emplace(n, Scenario{box, std::move(p)}).first;
  }
  return it->second;
}

// Linux: writing 5 to clear_refs resets VmHWM, the peak resident set size.
void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }
double peak_rss_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  return 0.0;
}

// Args: spheres, threads (the figures are the same for every count).
void BM_AnalyzePacking3D(benchmark::State& state) {
  const Scenario& s = scenario(state.range(0));
  const UniformRadius radii(0.01, 0.02);
  AnalysisOptions options;
  options.threads = static_cast<int>(state.range(1));
  std::uint64_t contacts = 0;
  reset_peak_rss();
  for (auto _ : state) {
    const PackingAnalysis a = analyze_packing<3>(s.packing, &s.box, &radii, options);
    contacts = a.coordination.contacts;
    benchmark::DoNotOptimize(a.vf_core.vf.value);
  }
  state.counters["peak_rss_MB"] = peak_rss_mb();
  state.counters["spheres"] = static_cast<double>(s.packing.size());
  state.counters["contacts"] = static_cast<double>(contacts);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(s.packing.size()));
}

// The validation alone (what `pack -q` runs). Args: spheres, threads.
void BM_ValidatePacking3D(benchmark::State& state) {
  const Scenario& s = scenario(state.range(0));
  const UniformRadius radii(0.01, 0.02);
  const int threads = static_cast<int>(state.range(1));
  for (auto _ : state) {
    const ValidationReport r = validate_packing<3>(s.packing, s.box, &radii, 1e-9, kRadiiAlpha, nullptr, threads);
    benchmark::DoNotOptimize(r.contacts);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(s.packing.size()));
}

// The sort of the K-S tests (radix) against std::sort, on uniform doubles. Arg: values.
std::vector<double> uniform_values(std::int64_t n) {
  Rng rng(5);
  std::vector<double> v(static_cast<std::size_t>(n));
  for (double& x : v) x = rng.uniform(0.01, 0.02);
  return v;
}
void BM_SortDoubles(benchmark::State& state) {
  const std::vector<double> values = uniform_values(state.range(0));
  for (auto _ : state) {
    std::vector<double> v = values;
    sort_doubles(v);
    benchmark::DoNotOptimize(v.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
void BM_StdSortDoubles(benchmark::State& state) {
  const std::vector<double> values = uniform_values(state.range(0));
  for (auto _ : state) {
    std::vector<double> v = values;
    std::sort(v.begin(), v.end());
    benchmark::DoNotOptimize(v.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

BENCHMARK(BM_AnalyzePacking3D)->Args({10000, 1})->Args({100000, 1})->Args({100000, 2})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AnalyzePacking3D)->Args({1000000, 1})->Args({1000000, 2})->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ValidatePacking3D)->Args({100000, 1})->Args({100000, 2})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SortDoubles)->Arg(100000)->Arg(3000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StdSortDoubles)->Arg(100000)->Arg(3000000)->Unit(benchmark::kMillisecond);

}  // namespace
