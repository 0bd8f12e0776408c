#include "cli/shape_pack.hpp"

#include <algorithm>
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
  Result run;
  static_cast<ShapePackResult<D>&>(run) = pack_shape_scene<D>(scene, progress);
  if (!above_target<D>(scene, run.solid_measure)) return run;
  // The contacts as the validation finds them (narrow phase); the size classes by template,
  // then size (a rank), so each template keeps its share too.
  const Container<D>& container = *scene.container<D>();
  ContactNetwork<D> network;
  validate_shapes<D>(run.packing, container, run.contact_tolerance, {}, kRadiiAlpha, &network);
  const std::size_t n = run.packing.size();
  std::vector<double> measure(n), rank(n);
  std::vector<Vec<D>> centres(n);
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) {
    measure[i] = run.packing.particles[i].shape->measure();
    centres[i] = run.packing.particles[i].position();
    order[i] = i;
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Particle<D>&pa = run.packing.particles[a], &pb = run.packing.particles[b];
    return pa.template_id != pb.template_id ? pa.template_id < pb.template_id : pa.size < pb.size;
  });
  for (std::size_t q = 0; q < n; ++q) rank[order[q]] = static_cast<double>(q);
  const std::vector<char> keep = particles_to_keep<D>(scene, container, measure, rank, centres, run.solid_measure,
                                                      network.pairs, network.walls, run.thinned);
  ShapePacking<D> kept;
  kept.template_names = run.packing.template_names;
  kept.origin = run.packing.origin;
  run.solid_measure = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) {
      kept.particles.push_back(run.packing.particles[i]);
      run.solid_measure += measure[i];
    }
  run.packing = std::move(kept);
  run.seconds += run.thinned->seconds;
  return run;
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
                "  solver         %llu solves: %llu in closed form or by Newton (wrappers, spheres, gap Newton), the others by minimisation (%s): "
                "%llu minimisations, %llu gap evaluations; %llu FCL queries\n",
                static_cast<unsigned long long>(res.counters.solves), static_cast<unsigned long long>(s.analytic_solves),
                scene.packer.minimisation.algorithm.c_str(), static_cast<unsigned long long>(s.minimisations),
                static_cast<unsigned long long>(s.gap_evaluations), static_cast<unsigned long long>(s.fcl_queries));
  c.summary_lines += buf;
  add_cut_short_reason(c, scene.stop, res.stop, res.packing.size(), res.solid_measure / container.measure());
  add_target_lines(c, scene, res.thinned, res.solid_measure, container.measure(), stop_text(res));
  add_never_fit_lines(c, res.never_fit_radii, {}, nullptr);  // a line only: the size tests are per template
  return c;
}

template struct ShapePack<2>;
template struct ShapePack<3>;

}  // namespace fp
