#include "cli/sphere_pack.hpp"

#include <string>

#include "core/metrics/packing_analysis.hpp"
#include "front/pack.hpp"

namespace fp {

template <int D>
typename SpherePack<D>::Result SpherePack<D>::pack(const Scene& scene, const ProgressFn& progress) {
  return fp::pack<D>(scene, progress);
}

template <int D>
PackCheck SpherePack<D>::check(const Scene& scene, const Result& res) {
  // Every figure of `frontpack analyze`, from the same code, the validation included.
  AnalysisOptions options;
  options.contact_tolerance = res.contact_tolerance;
  PackCheck c = pack_check_of(analyze_packing<D>(res.packing, scene.container<D>(), scene.radii.get(), options));
  c.counters.emplace_back("grid_bytes", res.grid_bytes);
  return c;
}

template struct SpherePack<2>;
template struct SpherePack<3>;

}  // namespace fp
