#include "cli/pack_command.hpp"

#include "cli/failure_report.hpp"
#include "cli/pack_api.hpp"
#include "cli/packing_input.hpp"
#include "cli/pack_run_steps.hpp"
#include "cli/run_record_start.hpp"
#include "cli/shape_pack.hpp"
#include "cli/sphere_pack.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/io/atomic_file.hpp"
#include "core/io/output_format.hpp"
#include "core/io/output_paths.hpp"
#include "core/io/packing_writers.hpp"
#include "core/io/run_record.hpp"
#include "core/io/scene_yaml.hpp"
#include "front/block_exchange.hpp"
#include "front/container_too_small.hpp"
#include "shapes/io/shape_packing_writers.hpp"

namespace fp {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// A usage or input problem: reported as "frontpack: error: ..." with exit code 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Applies -o/--format to the scene and checks every file the run will write (outputs,
/// their side files, the record) before any work is done, so a bad path costs nothing and
/// creates nothing, and no output replaces another or an input.
void apply_output_options(Scene& scene, const PackCommandOptions& o) {
  if (!o.format.empty() && o.output_paths.size() != 1)
    throw InputError(o.output_paths.empty() ? "--format needs -o PATH"
                                            : "--format names the format of one -o; with several, each takes its format "
                                              "from its extension (.vtu, .txt/.yade, .data/.lammps, .csv, .json)");
  if (!o.output_paths.empty()) {
    scene.outputs.clear();
    for (const std::string& path : o.output_paths) {
      OutputSpec out;
      out.path = path;
      try {
        out.format = output_format_name(o.format.empty() ? format_from_extension(path) : parse_output_format(o.format));
      } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
      }
      scene.outputs.push_back(out);
    }
  }
  if (!o.surfaces.empty()) {
    if (scene.particle_templates.empty())
      throw InputError("--surfaces: spheres have no surfaces side file (it draws particles of other shapes)");
    for (OutputSpec& out : scene.outputs)
      if (out.format == "vtu") out.surfaces = parse_surface_detail(o.surfaces);
  }
  std::vector<NamedPath> writes;
  for (const OutputSpec& out : scene.outputs) {
    const std::string where = out.spot.file.empty() ? "option -o" : out.spot.describe();
    writes.push_back({out.path, where, "output"});
    for (const std::string& side : side_files(scene, out))
      writes.push_back({side, where, "the side file of output '" + out.path + "'"});
  }
  if (!o.record_path.empty()) writes.push_back({o.record_path, "option --record", "run record"});
  std::vector<NamedPath> reads = scene_reads(scene, o.input_path.empty() ? "argument SCENE" : "option --scene");
  if (!o.input_path.empty()) reads.push_back({o.input_path, "argument PACKING", "packing file"});
  check_output_paths(writes, reads);
}

/// One run for every kind of particle (`Kind`: SpherePack or ShapePack): pack (`make(progress)`,
/// Kind::pack by default), check (the one verdict), record, write every output or none,
/// summarise; exit 3 when the check fails.
template <int D, class Kind, class Make>
int run(const Scene& scene, const PackCommandOptions& o, Make&& make) {
  const Container<D>& container = *scene.container<D>();
  const bool root = !o.exchange || o.exchange->process() == 0;
  const typename Kind::Result res = pack_with_progress(o.progress && root, scene, make);
  if (!root) return 0;  // rank 0 holds the packing: it checks, writes and summarises
  const auto& P = res.packing;
  const double rate = particles_per_second(P.size(), res.seconds);

  // The full analysis where it is shown or stored; the validation always.
  bool stored = !o.record_path.empty();
  for (const OutputSpec& out : scene.outputs) stored |= parse_output_format(out.format) == OutputFormat::Json;
  const CheckDepth depth = !o.quiet || stored ? CheckDepth::Analysis : CheckDepth::Validation;
  const auto t_check = Clock::now();
  const PackCheck check = [&] {
    const Activity checking("checking the packing of '" + scene.source_path + "'");
    return Kind::check(scene, res, depth);
  }();
  const double check_seconds = since(t_check);
  const ValidationReport& v = check.validation;

  const std::string incomplete = check.incomplete_text();
  const RunRecord rec = pack_record<D, Kind>(scene, res, check, check_seconds);

  std::vector<std::string> spared;
  const double write_seconds = write_outputs(
      scene, o.record_path, rec, [&](const OutputSpec& out) {
        const OutputFormat format = parse_output_format(out.format);
        if constexpr (std::is_same_v<std::decay_t<decltype(P)>, ShapePacking<D>>) write_packing<D>(format, out.path, P, rec, out.surfaces);
        else write_packing<D>(format, out.path, P, rec);  // spheres: no surfaces
        if (format == OutputFormat::Vtu) write_container_vtu(container_vtu_path(out.path), container);
      },
      !check.valid() || !check.incomplete.empty(), &spared);  // a stop the scene asked for is written

  if (!o.quiet) {
    print_run_header<D>(scene, container);
    std::printf("  particles      %s\n", rec.distribution_description.c_str());
    std::printf("  placed         %zu   (stop: %s)\n", P.size(), Kind::stop_text(res).c_str());
    for (std::size_t r = 0; r < res.ranks.size(); ++r)
      std::printf("  rank %-9zu %s\n", r, rank_work_text(res.ranks[r]).c_str());
    std::printf("%s", check.summary_lines.c_str());
    std::printf("  validation     %s\n", v.one_line().c_str());
    if (check.valid())
      for (const auto* reasons : {&check.cut_short, &check.incomplete})
        for (const std::string& why : *reasons) std::printf("  INCOMPLETE     %s\n", why.c_str());
    std::printf("  time           pack %.3f s (%.1f particles/s), %s %.3f s, write %.3f s\n", res.seconds, rate,
                check.timing_name.c_str(), check_seconds, write_seconds);
    print_output_lines(scene, o.record_path, spared);
  }
  if (v.ok && incomplete.empty()) return 0;
  if (!check.valid()) std::fprintf(stderr, "frontpack: error: the packing failed validation:\n%s\n", v.summary().c_str());
  else std::fprintf(stderr, "frontpack: error: the packing is valid but incomplete: %s\n", incomplete.c_str());
  for (const std::string& path : spared)
    std::fprintf(stderr, "frontpack: '%s' is not written: it holds a file, which is kept\n", path.c_str());
  return check.valid() ? 4 : 3;
}

template <int D, class Kind>
int run(const Scene& scene, const PackCommandOptions& o) {
  return run<D, Kind>(scene, o, [&](const ProgressFn& progress) { return Kind::pack(scene, progress, o.exchange); });
}

/// `frontpack densify`: the packing read, filled by the scene's void filling.
template <int D>
int run_densify(const Scene& scene, Packing<D>& given, const PackCommandOptions& o) {
  return run<D, SpherePack<D>>(scene, o, [&](const ProgressFn&) { return SpherePack<D>::densify(scene, std::move(given)); });
}

}  // namespace

int run_pack_command(const PackCommandOptions& o) {
  Scene scene;
  PackingInput given;  // densify: the packing to fill
  const bool densify = !o.input_path.empty();
  try {  // reading and checking what was given: any failure is bad input
    const Activity doing(densify ? "reading packing '" + o.input_path + "'" : "reading scene '" + o.scene_path + "'");
    if (densify) {
      given = read_packing_input(o.input_path, o.input_format, o.scene_path, false, o.scene_overrides);  // refuses a scene of shapes
      // The stages take the packing given as valid (least squares steps back towards it): it
      // gets validate's verdict first, and a packing that fails it is bad input.
      const ValidationReport v = validate_input(given, -1.0, -1.0, o.threads.value_or(0));
      if (!v.ok)
        throw InputError("'" + o.input_path + "' is not a valid packing of the scene '" + o.scene_path +
                         "', so it is not densified (frontpack validate gives this verdict):\n" + v.summary());
      scene = std::move(*given.scene);
      if (scene.stop.scale_sizes)  // the voids would take the law's own sizes, not the scale the packing was made at
        throw InputError("the scene '" + o.scene_path + "' scales its size law to fill the container with stop.particles "
                         "(stop.scale_sizes); frontpack densify fills voids with the law's own sizes: give it a scene with "
                         "the scaled law written out");
    } else {
      scene = load_scene(o.scene_path, o.scene_overrides);
    }
    apply_output_options(scene, o);
    // --seed, -j; every shape-specific input problem (family, parameters, output formats) and
    // what the run asks of the machine, before any work.
    prepare_scene(scene, o.seed, o.threads);
  } catch (...) {
    return report_failure(2);
  }
  try {
    const Activity doing(densify ? "filling the voids of '" + o.input_path + "'" : "packing scene '" + o.scene_path + "'");
    if (densify) return scene.dimension == 2 ? run_densify<2>(scene, given.packing2, o) : run_densify<3>(scene, given.packing3, o);
    if (!scene.particle_templates.empty())  // non-spherical particles: the general front
      return scene.dimension == 2 ? run<2, ShapePack<2>>(scene, o) : run<3, ShapePack<3>>(scene, o);
    return scene.dimension == 2 ? run<2, SpherePack<2>>(scene, o) : run<3, SpherePack<3>>(scene, o);
  } catch (const ContainerTooSmall& e) {  // the scene's mistake, found when the front starts: bad input
    const SourceSpot at = scene.spot("particles");
    try {
      throw SceneError(at.file, at.line, at.column, at.key, e.what());
    } catch (...) {
      return report_failure(2);
    }
  } catch (...) {
    return report_failure(1);
  }
}

}  // namespace fp
