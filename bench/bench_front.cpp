// End-to-end packer throughput on the paper's U[r, 2r] case, per lever setting
// (particles per second = items_per_second).
#include <benchmark/benchmark.h>

#include "core/geometry/box_container.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "front/advancing_front.hpp"

namespace {

using namespace fp;

template <int D>
void run_front(benchmark::State& state, PackerOptions opt, double side, double r_min, double r_max) {
  BoxContainer<D> box(Vec<D>::Zero(), Vec<D>::Constant(side));
  UniformRadius radii(r_min, r_max);
  std::size_t n = 0;
  for (auto _ : state) {
    AdvancingFront<D> front(box, radii, opt, StopCriteria{}, 1);
    n += front.run().packing.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(n));
}

void BM_Front3D_Defaults(benchmark::State& s) { run_front<3>(s, PackerOptions{}, 0.5, 0.01, 0.02); }
void BM_Front3D_PaperRandomFirst(benchmark::State& s) {
  PackerOptions o;
  o.front_pick = FrontPick::Random;
  o.candidate = CandidateChoice::First;
  o.radius_pool = 1;
  run_front<3>(s, o, 0.5, 0.01, 0.02);
}
void BM_Front3D_ClosestNoPool(benchmark::State& s) {
  PackerOptions o;
  o.radius_pool = 1;
  run_front<3>(s, o, 0.5, 0.01, 0.02);
}
void BM_Front3D_AllContactBodies(benchmark::State& s) {
  PackerOptions o;
  o.contact_bodies = ContactBodies::All;
  run_front<3>(s, o, 0.5, 0.01, 0.02);
}
// r_max / r_min = 50: the hierarchical grid's regime.
void BM_Front3D_Ratio50(benchmark::State& s) { run_front<3>(s, PackerOptions{}, 1.0, 0.002, 0.1); }
void BM_Front2D_Defaults(benchmark::State& s) { run_front<2>(s, PackerOptions{}, 0.5, 0.001, 0.002); }

BENCHMARK(BM_Front3D_Defaults)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Front3D_PaperRandomFirst)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Front3D_ClosestNoPool)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Front3D_AllContactBodies)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Front3D_Ratio50)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Front2D_Defaults)->Unit(benchmark::kMillisecond);

}  // namespace
