#include "cli/shape_pack_command.hpp"

#include <chrono>
#include <stdexcept>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/failure_report.hpp"
#include "cli/pack_run_steps.hpp"
#include "cli/run_record_start.hpp"
#include "contact/shape_validation.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/output_format.hpp"
#include "core/io/run_record.hpp"
#include "core/io/scene_limits.hpp"
#include "front/pack_shapes_scene.hpp"
#include "shapes/io/shape_packing_writers.hpp"

namespace fp {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

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
int run_shape_pack(const Scene& scene, const PackCommandOptions& o) {
  const Container<D>& container = *scene.container<D>();
  const ShapePackResult<D> res =
      pack_with_progress(o.progress, [&](const ProgressFn& progress) { return pack_shape_scene<D>(scene, progress); });
  const ShapePacking<D>& P = res.packing;

  const Activity checking("validating the packing of '" + scene.source_path + "'");
  const auto t_check = Clock::now();
  const ShapeValidation v = validate_shapes<D>(P, container, res.gap_tolerance, requested_templates(scene));
  const double check_seconds = since(t_check);
  const double vf = res.solid_measure / container.measure();
  const double n = static_cast<double>(P.size());

  RunRecord rec = start_run_record<D>(scene, container, P.size());
  for (const ParticleTemplateSpec& t : scene.particle_templates)
    rec.distribution_description += (rec.distribution_description.empty() ? "" : "; ") + t.family + " " + t.size->describe();
  const MinimisationStats& ms = res.minimisation;
  rec.timings = {{"pack", res.seconds}, {"validation", check_seconds}};
  rec.metrics = {{"volume_fraction_container", vf},
                 {"gap_tolerance", res.gap_tolerance},
                 {"mean_coordination", v.mean_coordination},
                 {"max_overlap_over_rmin", v.max_overlap_rel},
                 {"max_contact_gap_over_rmin", v.max_contact_gap_rel},
                 {"max_outside_over_r", v.max_outside_rel},
                 {"particles_per_second", res.seconds > 0 ? n / res.seconds : 0.0}};
  const FrontCounters& c = res.counters;
  rec.counters = front_counter_entries(c);
  const std::vector<std::pair<std::string, std::uint64_t>> extra = {
      {"analytic_solves", res.analytic_solves}, {"minimisations", ms.minimisations},
      {"gap_evaluations", ms.evaluations},      {"minima_rejected", ms.rejected_gap},
      {"fcl_queries", res.fcl_queries},         {"contacts", v.contacts},
      {"wall_contacts", v.wall_contacts},       {"pairs_checked", v.pairs_checked}};
  rec.counters.insert(rec.counters.end(), extra.begin(), extra.end());
  rec.info = {{"stop_reason", to_string(res.stop)},
              {"validation", v.ok ? "ok" : "FAILED"},
              {"minimisation_algorithm", scene.packer.minimisation.algorithm},
              {"contact_solver", scene.packer.contact_solver == ContactSolverChoice::Auto ? "auto" : "minimisation"}};

  const double write_seconds = write_outputs(scene, o.record_path, rec, [&](OutputFormat format, const std::string& path) {
    write_shape_packing<D>(format, path, P, rec);
  });

  if (!o.quiet) {
    print_run_header<D>(scene, container);
    std::printf("  particles      %s\n", rec.distribution_description.c_str());
    std::printf("  placed         %zu   (stop: %s)\n", P.size(), to_string(res.stop));
    std::printf("  %s     %.4f of the container\n", D == 3 ? "volume fraction" : "area fraction  ", vf);
    std::printf("  coordination   %.3f   (contacts: |gap| <= %.3g x smaller circumscribed radius; the largest: %.2g)\n",
                v.mean_coordination, res.gap_tolerance, v.max_contact_gap_rel);
    std::printf("  solver         %llu solves: %llu in closed form (wrappers, spheres), the others by minimisation (%s): %llu "
                "minimisations, %llu gap evaluations; %llu FCL queries\n",
                static_cast<unsigned long long>(c.solves), static_cast<unsigned long long>(res.analytic_solves),
                scene.packer.minimisation.algorithm.c_str(), static_cast<unsigned long long>(ms.minimisations),
                static_cast<unsigned long long>(ms.evaluations), static_cast<unsigned long long>(res.fcl_queries));
    std::printf("  validation     %s\n", v.summary().c_str());
    std::printf("  time           pack %.3f s (%.1f particles/s), validation %.3f s, write %.3f s\n", res.seconds,
                res.seconds > 0 ? n / res.seconds : 0.0, check_seconds, write_seconds);
    print_output_lines(scene, o.record_path);
  }
  if (!v.ok) {
    std::fprintf(stderr, "frontpack: error: the packing failed validation: %s\n", v.summary().c_str());
    return 3;
  }
  return 0;
}

template int run_shape_pack<2>(const Scene&, const PackCommandOptions&);
template int run_shape_pack<3>(const Scene&, const PackCommandOptions&);

}  // namespace fp
