#include "cli/sphere_pack.hpp"

#include <string>

#include "core/io/analysis_json.hpp"
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
  const PackingAnalysis a = analyze_packing<D>(res.packing, scene.container<D>(), scene.radii.get(), options);
  PackCheck c;
  c.validation = *a.validation;
  c.volume_fraction = a.vf_container.vf.value;
  c.timing_name = "metrics";
  const ContactStats& cs = a.coordination;
  const double n = static_cast<double>(res.packing.size());
  c.metrics = {{"volume_fraction_core", a.vf_core.vf.value},
               {"volume_fraction_reference_sphere", a.vf_reference},
               {"reference_sphere_radius", a.reference_radius},
               {"mean_coordination_with_walls", cs.mean_coordination_with_walls},
               {"rattler_fraction", n > 0 ? static_cast<double>(cs.rattlers) / n : 0.0},
               {"max_overlap_over_rmin", a.max_overlap_rel},
               {"radii_statistic", c.validation.radii().statistic},
               {"radii_pvalue", c.validation.radii().p}};
  const char* axis_names[] = {"x", "y", "z"};
  for (int k = 0; k < D; ++k)
    c.metrics.emplace_back(std::string("reference_sphere_center_") + axis_names[k], a.reference_center[static_cast<std::size_t>(k)]);
  c.counters = {{"rattlers", cs.rattlers}, {"grid_bytes", res.grid_bytes}};
  c.info = {{"radii_test", c.validation.radii().test}};
  c.analysis_json = analysis_json(a);
  std::string table = "  " + a.summary();
  for (std::size_t at = table.find('\n'); at != std::string::npos; at = table.find('\n', at + 3)) table.insert(at + 1, "  ");
  c.summary_lines = table + "\n";
  return c;
}

template struct SpherePack<2>;
template struct SpherePack<3>;

}  // namespace fp
