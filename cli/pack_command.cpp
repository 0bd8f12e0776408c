#include "cli/pack_command.hpp"

#include "cli/failure_report.hpp"
#include "cli/packing_input.hpp"
#include "cli/pack_run_steps.hpp"
#include "cli/run_record_start.hpp"
#include "cli/shape_pack_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/atomic_file.hpp"
#include "core/io/output_format.hpp"
#include "core/io/output_paths.hpp"
#include "core/io/packing_writers.hpp"
#include "core/io/run_record.hpp"
#include "core/io/scene_limits.hpp"
#include "core/io/scene_yaml.hpp"
#include "core/io/analysis_json.hpp"
#include "core/metrics/packing_analysis.hpp"
#include "front/pack.hpp"
#include "shapes/io/shape_packing_writers.hpp"
#include "frontpack/version.hpp"

namespace fp {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// A usage or input problem: reported as "frontpack: error: ..." with exit code 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Applies -o/--format/--seed to the scene and checks every file the run will write (outputs,
/// their side files, the record) before any work is done, so a bad path costs nothing and
/// creates nothing, and no output replaces another or an input.
void apply_overrides(Scene& scene, const PackCommandOptions& o) {
  if (o.seed) scene.seed = *o.seed;
  if (!o.format.empty() && o.output_path.empty()) throw InputError("--format needs -o PATH");
  if (!o.output_path.empty()) {
    OutputSpec out;
    out.path = o.output_path;
    try {
      out.format = output_format_name(o.format.empty() ? format_from_extension(o.output_path)
                                                       : parse_output_format(o.format));
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    }
    scene.outputs = {out};
  }
  std::vector<NamedPath> writes;
  for (const OutputSpec& out : scene.outputs) {
    const std::string where = out.spot.file.empty() ? "option -o" : out.spot.describe();
    writes.push_back({out.path, where, "output"});
    if (!scene.particle_templates.empty())  // shape packings write a side file for vtu and lammps
      for (const std::string& side : companion_paths(parse_output_format(out.format), out.path))
        writes.push_back({side, where, "the side file of output '" + out.path + "'"});
  }
  if (!o.record_path.empty()) writes.push_back({o.record_path, "option --record", "run record"});
  check_output_paths(writes, scene_reads(scene, "argument SCENE"));
}

template <int D>
int run(const Scene& scene, const PackCommandOptions& o) {
  const Container<D>& container = *scene.container<D>();
  const PackResult<D> res = pack_with_progress(o.progress, [&](const ProgressFn& progress) { return pack<D>(scene, progress); });
  const Packing<D>& P = res.packing;

  // Every figure of `frontpack analyze`, from the same code, the independent validation included.
  const Activity analysing("analysing the packing of '" + scene.source_path + "'");
  const auto t_metrics = Clock::now();
  AnalysisOptions analysis_options;
  analysis_options.contact_tolerance = scene.packer.contact_tolerance;
  const PackingAnalysis a = analyze_packing<D>(P, &container, scene.radii.get(), analysis_options);
  const ValidationReport& vr = *a.validation;
  const ContactStats& cs = a.coordination;
  const double metrics_seconds = since(t_metrics);

  RunRecord rec = start_run_record<D>(scene, container, P.size());
  rec.distribution_description = scene.radii->describe();
  rec.timings = {{"pack", res.seconds}, {"metrics", metrics_seconds}};
  rec.metrics = {{"volume_fraction_container", a.vf_container.vf.value},
                 {"volume_fraction_core", a.vf_core.vf.value},
                 {"volume_fraction_reference_sphere", a.vf_reference},
                 {"reference_sphere_radius", a.reference_radius},
                 {"contact_tolerance", a.contact_tolerance},
                 {"mean_coordination", cs.mean_coordination},
                 {"mean_coordination_with_walls", cs.mean_coordination_with_walls},
                 {"rattler_fraction", P.empty() ? 0.0 : static_cast<double>(cs.rattlers) / P.size()},
                 {"max_overlap_over_rmin", a.max_overlap_rel},
                 {"max_overlap_over_smaller_radius", vr.max_overlap_rel},
                 {"max_outside_over_r", vr.max_outside_rel},
                 {"radii_statistic", vr.radii.statistic},
                 {"radii_pvalue", vr.radii.p},
                 {"particles_per_second", res.seconds > 0 ? P.size() / res.seconds : 0.0}};
  const char* axis_names[] = {"x", "y", "z"};
  for (int a_ = 0; a_ < D; ++a_)
    rec.metrics.emplace_back(std::string("reference_sphere_center_") + axis_names[a_], a.reference_center[a_]);
  rec.analysis_json = analysis_json(a);
  rec.counters = front_counter_entries(res.counters);
  const std::vector<std::pair<std::string, std::uint64_t>> extra = {
      {"contacts", cs.contacts}, {"wall_contacts", cs.wall_contacts}, {"rattlers", cs.rattlers}, {"grid_bytes", res.grid_bytes}};
  rec.counters.insert(rec.counters.end(), extra.begin(), extra.end());
  rec.info = {{"stop_reason", to_string(res.stop)}, {"validation", vr.ok ? "ok" : "FAILED"}, {"radii_test", vr.radii.test}};

  const double write_seconds = write_outputs(scene, o.record_path, rec, [&](OutputFormat format, const std::string& path) {
    write_packing<D>(format, path, P, rec);
  });

  if (!o.quiet) {
    print_run_header<D>(scene, container);
    std::printf("  radii          %s\n", scene.radii->describe().c_str());
    std::printf("  particles      %zu   (stop: %s)\n", P.size(), to_string(res.stop));
    std::string table = "  " + a.summary();
    for (std::size_t at = table.find('\n'); at != std::string::npos; at = table.find('\n', at + 3)) table.insert(at + 1, "  ");
    std::printf("%s\n", table.c_str());
    std::printf("  validation     %s\n", vr.ok ? "ok (every pair, every particle against the container, radii range and test)"
                                                : "FAILED (see above)");
    std::printf("  time           pack %.3f s (%.0f particles/s), metrics %.3f s, write %.3f s\n", res.seconds,
                res.seconds > 0 ? P.size() / res.seconds : 0.0, metrics_seconds, write_seconds);
    print_output_lines(scene, o.record_path);
  }
  if (!vr.ok) {
    std::fprintf(stderr, "frontpack: error: the packing failed validation:\n%s\n", vr.summary().c_str());
    return 3;
  }
  return 0;
}

}  // namespace

int run_pack_command(const PackCommandOptions& o) {
  Scene scene;
  try {  // reading and checking what was given: any failure is bad input
    const Activity doing("reading scene '" + o.scene_path + "'");
    scene = load_scene(o.scene_path);
    apply_overrides(scene, o);
    // Every shape-specific input problem (family, parameters, output formats) and what the run
    // asks of the machine, before any work.
    if (!scene.particle_templates.empty()) check_shape_scene(scene);
    else check_run_limits(scene, estimate_run_demand(scene, mean_ball_measure(*scene.radii, scene.dimension)), available_memory());
  } catch (...) {
    return report_failure(2);
  }
  try {
    const Activity doing("packing scene '" + o.scene_path + "'");
    if (!scene.particle_templates.empty())  // non-spherical particles: the general front
      return scene.dimension == 2 ? run_shape_pack<2>(scene, o) : run_shape_pack<3>(scene, o);
    return scene.dimension == 2 ? run<2>(scene, o) : run<3>(scene, o);
  } catch (...) {
    return report_failure(1);
  }
}

}  // namespace fp
