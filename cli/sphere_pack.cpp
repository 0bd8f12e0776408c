#include "cli/sphere_pack.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/metrics/packing_analysis.hpp"
#include "core/metrics/validate.hpp"
#include "core/system/parallel_parts.hpp"
#include "front/block_exchange.hpp"
#include "front/pack.hpp"

namespace fp {
namespace {

/// The scene's void filling on `run.packing`: what it adds is checked with the rest, with the
/// overlap it allows as the tolerance.
template <int D>
void fill(const Scene& scene, const DensifyOptions& options, SphereRun<D>& run) {
  run.densified = fill_voids<D>(run.packing, *scene.container<D>(), *scene.radii, options, scene.seed, run.contact_tolerance);
  run.seconds += run.densified->seconds;
  run.solid_measure = run.densified->solid_after;
  run.contact_tolerance = std::max(run.contact_tolerance, options.overlap);
}

/// Paper 000: steps 2-7a on the scene's tetrahedral mesh, then step 7b, the void filling with the
/// voids' own radii, the packer's epsilon and z_min, stopped by phi0 or N0 (unless the scene's
/// `densify:` says otherwise).
void fill_tet_mesh(const Scene& scene, SphereRun<3>& run) {
  const TetMeshOptions& t = scene.packer.tet_mesh;
  TetFillOptions o;
  o.overlap = t.overlap;
  o.z_min = t.z_min;
  o.loose = t.loose;
  o.target_volume_fraction = scene.stop.target_volume_fraction;
  o.max_particles = scene.stop.max_particles;
  run.contact_tolerance = scene.packer.contact_tolerance;
  run.tet_filled = fp::fill_tet_mesh(*scene.tet_mesh, *scene.container3, *scene.radii, o, scene.seed, run.contact_tolerance,
                                     run.packing);
  run.seconds = run.tet_filled->seconds;
  DensifyOptions step_7b;
  step_7b.radii = VoidRadii::Fit;
  step_7b.overlap = t.overlap;
  step_7b.z_min = t.z_min;
  step_7b.target_volume_fraction = o.target_volume_fraction;
  step_7b.max_particles = o.max_particles;
  fill<3>(scene, scene.densify.value_or(step_7b), run);
  if (run.densified->stop == VoidFillingStop::VolumeFraction) run.stop = StopReason::VolumeFraction;
  else if (run.densified->stop == VoidFillingStop::ParticleCount) run.stop = StopReason::ParticleCount;
}

}  // namespace

template <int D>
typename SpherePack<D>::Result SpherePack<D>::pack(const Scene& scene, const ProgressFn& progress, BlockExchange* exchange) {
  Result run;
  if constexpr (D == 3) {
    if (scene.packer.method == "tet_mesh") {
      fill_tet_mesh(scene, run);
      return run;
    }
  }
  static_cast<PackResult<D>&>(run) = fp::pack<D>(scene, progress, exchange);
  const bool root = !exchange || exchange->process() == 0;  // the others hold no packing
  if (scene.densify && root) fill<D>(scene, *scene.densify, run);
  return run;
}

template <int D>
typename SpherePack<D>::Result SpherePack<D>::densify(const Scene& scene, Packing<D> packing) {
  Result run;
  run.given = true;
  run.packing = std::move(packing);
  run.contact_tolerance = scene.packer.contact_tolerance;
  fill<D>(scene, scene.densify.value_or(DensifyOptions{}), run);
  return run;
}

template <int D>
std::string SpherePack<D>::stop_text(const Result& run) {
  std::string s = run.given ? "given" : run.tet_filled ? (run.tet_filled->reached_target ? to_string(run.stop) : "mesh filled")
                                                       : to_string(run.stop);
  if (run.densified) s += std::string("; void filling: ") + to_string(run.densified->stop);
  return s;
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
  // Radii the voids gave (paper 000) are asked to lie in the range only; their law is reported.
  const bool fitted = res.tet_filled || (res.densified && scene.densify && scene.densify->radii == VoidRadii::Fit);
  options.radii_alpha = fitted ? 0.0 : kRadiiAlpha;
  PackCheck c = depth == CheckDepth::Analysis
                    ? pack_check_of(analyze_packing<D>(res.packing, &container, scene.radii.get(), options))
                    : pack_check_of(validate_packing<D>(res.packing, container, scene.radii.get(), res.contact_tolerance,
                                                        options.radii_alpha, nullptr, options.threads),
                                    res.solid_measure / container.measure());
  c.counters.emplace_back("grid_bytes", res.grid_bytes);
  if (const auto& t = res.tet_filled) {
    char line[400];
    std::snprintf(line, sizeof line,
                  "  tet mesh       %llu tetrahedra, %llu nodes, %llu edges: steps 2-3 +%llu +%llu (%llu reduced below r_min), "
                  "4 +%llu, 5 +%llu, 6 +%llu, 7a -%llu; %.3f s\n",
                  static_cast<unsigned long long>(t->tets), static_cast<unsigned long long>(t->nodes),
                  static_cast<unsigned long long>(t->edges), static_cast<unsigned long long>(t->edge_spheres),
                  static_cast<unsigned long long>(t->node_spheres), static_cast<unsigned long long>(t->removed_reduced),
                  static_cast<unsigned long long>(t->face_spheres), static_cast<unsigned long long>(t->tet_spheres),
                  static_cast<unsigned long long>(t->midway_spheres), static_cast<unsigned long long>(t->removed_boundary),
                  t->seconds);
    c.summary_lines += line;
    c.metrics.emplace_back("tet_fill_seconds", t->seconds);
    c.counters.insert(c.counters.end(), {{"tet_tetrahedra", t->tets},
                                         {"tet_edge_spheres", t->edge_spheres},
                                         {"tet_node_spheres", t->node_spheres},
                                         {"tet_removed_reduced", t->removed_reduced},
                                         {"tet_face_spheres", t->face_spheres},
                                         {"tet_tet_spheres", t->tet_spheres},
                                         {"tet_midway_spheres", t->midway_spheres},
                                         {"tet_removed_boundary", t->removed_boundary},
                                         {"tet_procedures", t->procedures}});
  }
  if (const auto& v = res.densified) {
    const double measure = container.measure();
    char line[320];
    std::snprintf(line, sizeof line,
                  "  void filling   +%zu spheres in %d rounds (stop: %s): volume fraction %.4f -> %.4f; radii %s; %.3f s "
                  "(triangulations %.3f s)\n",
                  v->added, v->rounds, to_string(v->stop), v->solid_before / measure, v->solid_after / measure,
                  fitted ? "the voids' own" : (std::to_string(v->radii_unplaced) + " of " + std::to_string(v->radii_drawn) +
                                               " drawn left unplaced").c_str(),
                  v->seconds, v->triangulation_seconds);
    c.summary_lines += line;
    c.info.emplace_back("densify_stop", to_string(v->stop));
    c.info.emplace_back("densify_radii", fitted ? "fit" : "distribution");
    c.metrics.insert(c.metrics.end(), {{"densify_volume_fraction_before", v->solid_before / measure},
                                       {"densify_seconds", v->seconds},
                                       {"densify_triangulation_seconds", v->triangulation_seconds},
                                       {"densify_max_overlap_over_r_min", v->max_overlap_over_r_min}});
    c.counters.insert(c.counters.end(), {{"densify_given", res.given ? 1u : 0u},
                                         {"densify_before", v->before},
                                         {"densify_added", v->added},
                                         {"densify_rounds", static_cast<std::uint64_t>(v->rounds)},
                                         {"densify_voids", v->voids},
                                         {"densify_voids_open", v->voids_open},
                                         {"densify_mirrored", v->mirrored},
                                         {"densify_positions_tried", v->positions_tried},
                                         {"densify_rejected_overlap", v->rejected_overlap},
                                         {"densify_rejected_container", v->rejected_container},
                                         {"densify_rejected_contacts", v->rejected_contacts},
                                         {"densify_radii_drawn", v->radii_drawn},
                                         {"densify_radii_unplaced", v->radii_unplaced},
                                         {"densify_radii_reduced", v->radii_reduced},
                                         {"densify_radii_capped", v->radii_capped}});
  }
  return c;
}

template struct SpherePack<2>;
template struct SpherePack<3>;

}  // namespace fp
