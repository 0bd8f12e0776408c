// Least-squares densification (paper 001) of a front packing, per particle: the whole stage
// (triangulation, Eq. 4, overlap removal), 3D U[r, 2r] and 2D; and its L-BFGS alone on a chain of
// springs (vector work per evaluation). items_per_second = particles (unknowns) per second.
#include <benchmark/benchmark.h>

#include "core/geometry/box_container.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "densify/lbfgs.hpp"
#include "densify/least_squares.hpp"
#include "front/advancing_front.hpp"

namespace {

using namespace fp;

template <int D>
void run_least_squares(benchmark::State& state, double side, LeastSquaresRadii radii_mode) {
  BoxContainer<D> box(Vec<D>::Zero(), Vec<D>::Constant(side));
  UniformRadius radii(0.01, 0.02);
  AdvancingFront<D> front(box, radii, PackerOptions{}, StopCriteria{}, 1);
  const Packing<D> given = front.run().packing;
  LeastSquaresOptions o;
  o.radii = radii_mode;
  std::size_t n = 0;
  for (auto _ : state) {
    Packing<D> p = given;
    benchmark::DoNotOptimize(densify_least_squares<D>(p, box, 0.01, 0.02, o, o.tolerance).solid_after);
    n += p.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(n));
}

void BM_LeastSquares3D_Range(benchmark::State& s) { run_least_squares<3>(s, 0.5, LeastSquaresRadii::Range); }
void BM_LeastSquares3D_Fixed(benchmark::State& s) { run_least_squares<3>(s, 0.5, LeastSquaresRadii::Fixed); }
void BM_LeastSquares2D_Range(benchmark::State& s) { run_least_squares<2>(s, 1.0, LeastSquaresRadii::Range); }

void BM_Lbfgs_SpringChain(benchmark::State& s) {
  const int n = static_cast<int>(s.range(0));
  const auto f = [&](const Eigen::VectorXd& v, Eigen::VectorXd& g) {
    g.setZero();
    double sum = 0;
    for (int k = 0; k <= n; ++k) {
      const double left = k == 0 ? 0.0 : v[k - 1], right = k == n ? n + 1.0 : v[k], d = right - left - 1;
      sum += d * d;
      if (k > 0) g[k - 1] -= 2 * d;
      if (k < n) g[k] += 2 * d;
    }
    return sum;
  };
  LbfgsOptions o;
  o.evaluations = 50;
  o.memory = 4;
  for (auto _ : s) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    benchmark::DoNotOptimize(minimise_lbfgs(x, f, o).value);
  }
  s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()) * n);
}

BENCHMARK(BM_LeastSquares3D_Range)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LeastSquares3D_Fixed)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LeastSquares2D_Range)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Lbfgs_SpringChain)->Arg(1 << 16)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

}  // namespace
