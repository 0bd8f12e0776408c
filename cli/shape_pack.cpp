#include "cli/shape_pack.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/shape_analysis.hpp"
#include "contact/shape_validation.hpp"
#include "core/system/parallel_parts.hpp"
#include "front/block_exchange.hpp"
#include "core/io/output_format.hpp"
#include "core/io/scene_limits.hpp"
#include "front/pack_shapes_scene.hpp"
#include "shapes/io/shape_packing_writers.hpp"

namespace fp {
namespace {

template <int D>
void check_in(const Scene& scene) {
  const std::vector<ShapeTemplate<D>> templates = resolve_templates<D>(scene);
  std::vector<std::string> families;
  for (const ShapeTemplate<D>& t : templates) families.push_back(t.prototype.shape->kind());
  for (const OutputSpec& out : scene.outputs) check_shape_format<D>(parse_output_format(out.format), families);
  check_run_limits(scene, estimate_run_demand(scene, mean_measure<D>(templates)), available_memory());
}

}  // namespace

void check_shape_scene(const Scene& scene) {
  if (scene.dimension == 2) check_in<2>(scene);
  else check_in<3>(scene);
}

template <int D>
typename ShapePack<D>::Result ShapePack<D>::pack(const Scene& scene, const ProgressFn& progress, BlockExchange* exchange) {
  if (exchange && exchange->processes() > 1)
    throw std::runtime_error("several MPI processes pack scenes of spheres (disks) only; run this scene without mpirun, with "
                             "threads (-j N)");
  return pack_shape_scene<D>(scene, progress);
}

template <int D>
PackCheck ShapePack<D>::check(const Scene& scene, const Result& res, CheckDepth depth) {
  const Container<D>& container = *scene.container<D>();
  AnalysisOptions options;
  options.contact_tolerance = res.contact_tolerance;
  options.threads = thread_count(scene.packer.threads);
  PackCheck c = depth == CheckDepth::Analysis
                    ? pack_check_of(analyze_shape_packing<D>(res.packing, scene, options))
                    : pack_check_of(validate_shapes<D>(res.packing, container, res.contact_tolerance, requested_templates(scene)),
                                    res.solid_measure / container.measure());
  const SolverCounters& s = res.solver;
  const std::vector<std::pair<std::string, std::uint64_t>> solver = {
      {"analytic_solves", s.analytic_solves}, {"minimisations", s.minimisations}, {"gap_evaluations", s.gap_evaluations},
      {"minima_rejected", s.minima_rejected}, {"fcl_queries", s.fcl_queries}};
  c.counters.insert(c.counters.end(), solver.begin(), solver.end());
  c.info.emplace_back("minimisation_algorithm", scene.packer.minimisation.algorithm);
  c.info.emplace_back("contact_solver", scene.packer.contact_solver == ContactSolverChoice::Auto ? "auto" : "minimisation");
  char buf[480];
  std::snprintf(buf, sizeof buf,
                "  solver         %llu solves: %llu in closed form (wrappers, spheres), the others by minimisation (%s): "
                "%llu minimisations, %llu gap evaluations; %llu FCL queries\n",
                static_cast<unsigned long long>(res.counters.solves), static_cast<unsigned long long>(s.analytic_solves),
                scene.packer.minimisation.algorithm.c_str(), static_cast<unsigned long long>(s.minimisations),
                static_cast<unsigned long long>(s.gap_evaluations), static_cast<unsigned long long>(s.fcl_queries));
  c.summary_lines += buf;
  return c;
}

template struct ShapePack<2>;
template struct ShapePack<3>;

}  // namespace fp
