#include "cli/sphere_pack.hpp"

#include <string>

#include "core/metrics/packing_analysis.hpp"
#include "core/metrics/validate.hpp"
#include "core/system/parallel_parts.hpp"
#include "front/pack.hpp"

namespace fp {

template <int D>
typename SpherePack<D>::Result SpherePack<D>::pack(const Scene& scene, const ProgressFn& progress, BlockExchange* exchange) {
  return fp::pack<D>(scene, progress, exchange);
}

template <int D>
PackCheck SpherePack<D>::check(const Scene& scene, const Result& res, CheckDepth depth) {
  // Every figure of `frontpack analyze`, from the same code, the validation included; or the
  // validation alone.
  const Container<D>& container = *scene.container<D>();
  // On the pack's threads (the figures do not depend on their number).
  AnalysisOptions options;
  options.contact_tolerance = res.contact_tolerance;
  options.threads = thread_count(scene.packer.threads);
  PackCheck c = depth == CheckDepth::Analysis
                    ? pack_check_of(analyze_packing<D>(res.packing, &container, scene.radii.get(), options))
                    : pack_check_of(validate_packing<D>(res.packing, container, scene.radii.get(), res.contact_tolerance,
                                                        kRadiiAlpha, nullptr, options.threads),
                                    res.solid_measure / container.measure());
  c.counters.emplace_back("grid_bytes", res.grid_bytes);
  return c;
}

template struct SpherePack<2>;
template struct SpherePack<3>;

}  // namespace fp
