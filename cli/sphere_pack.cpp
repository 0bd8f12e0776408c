#include "cli/sphere_pack.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/scene_regions.hpp"
#include "cli/target_thinning.hpp"
#include "core/metrics/contacts.hpp"
#include "core/metrics/packing_analysis.hpp"
#include "core/metrics/validate.hpp"
#include "core/sampling/scaled_radius.hpp"
#include "core/sampling/split_radius.hpp"
#include "core/system/parallel_parts.hpp"
#include "front/block_exchange.hpp"
#include "front/pack.hpp"

namespace fp {
namespace {

template <int D>
double solid_of(const Packing<D>& p) {
  double s = 0;
  for (const double r : p.radii) s += ball_measure<D>(r);
  return s;
}

/// The scene's void filling on `run.packing` with `law` (in `region` only, when given): what it
/// adds is checked with the rest, with the overlap it allows as the tolerance. A second call (the
/// next region) adds to the first's report.
template <int D>
void fill(const Scene& scene, const DensifyOptions& options, SphereRun<D>& run, const RadiusDistribution& law,
          const VoidRegion<D>* region = nullptr, std::uint64_t stream = 0) {
  const double before = solid_of(run.packing);
  VoidFillingReport r = fill_voids<D>(run.packing, *scene.container<D>(), law, options, scene.seed + stream,
                                      scene.packer.contact_tolerance, region);
  run.seconds += r.seconds;
  r.solid_before = before;  // of the whole packing, whatever the region
  r.solid_after = run.solid_measure = solid_of(run.packing);
  if (run.densified) {
    r.solid_before = run.densified->solid_before;
    *run.densified += r;
  } else {
    run.densified = r;
  }
  // Overlaps of epsilon r_min are allowed, to rounding (one placed at exactly epsilon r_min between
  // two spheres of r_min came out 0.050000000000000926 of it): overlap_tolerance().
  run.contact_tolerance = overlap_tolerance(scene);
}

/// The scene's void filling; with a split law, the part at or below r_s, up to the count that
/// keeps the law's proportions with what is there (the part above it).
template <int D>
void fill_scene_voids(const Scene& scene, SphereRun<D>& run) {
  DensifyOptions o = scene.densify.value_or(DensifyOptions{});
  if (!o.target_volume_fraction) o.target_volume_fraction = scene.target_solid_fraction;
  if (!o.split) return fill<D>(scene, o, run, *scene.radii);
  const SplitRadius below(scene.radii, *o.split, SplitRadius::Side::Below);
  const auto whole = static_cast<std::uint64_t>(std::ceil(static_cast<double>(run.packing.size()) / (1 - below.share_below())));
  o.max_particles = o.max_particles ? std::min(*o.max_particles, whole) : whole;
  fill<D>(scene, o, run, below);
}

/// The scene's least-squares densification (paper 001), when it asks for one; the law's range
/// bounds the radii.
template <int D>
void densify_by_least_squares(const Scene& scene, SphereRun<D>& run) {
  if (!scene.least_squares || run.packing.empty()) return;
  run.contact_tolerance = std::max(run.contact_tolerance, scene.least_squares->tolerance);
  run.squared = densify_least_squares<D>(run.packing, *scene.container<D>(), scene.radii->r_min(), scene.radii->r_max(),
                                         *scene.least_squares, run.contact_tolerance);
  run.seconds += run.squared->seconds;
  run.solid_measure = run.squared->solid_after;
}

/// The scene's `target:` (cli/target_thinning.hpp), contacts found at the run's tolerance.
template <int D>
void thin_to_target(const Scene& scene, SphereRun<D>& run) {
  if (!above_target<D>(scene, run.solid_measure)) return;
  const Container<D>& container = *scene.container<D>();
  const std::size_t n = run.packing.size();
  std::vector<double> measure(n);
  for (std::size_t i = 0; i < n; ++i) measure[i] = ball_measure<D>(run.packing.radii[i]);
  const std::vector<char> keep =
      particles_to_keep<D>(scene, container, measure, run.packing.radii, run.packing.centers, run.solid_measure,
                           find_pair_contacts(run.packing, run.contact_tolerance),
                           find_wall_contacts(run.packing, container, run.contact_tolerance), run.thinned);
  Packing<D> kept;
  kept.origin = run.packing.origin;
  kept.reserve(n - run.thinned->report.removed);
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) kept.add(run.packing.centers[i], run.packing.radii[i]);
  run.packing = std::move(kept);
  run.solid_measure = solid_of(run.packing);
  run.seconds += run.thinned->seconds;
}

/// Paper 000: steps 2-7a on the scene's tetrahedral mesh, then step 7b, the void filling with the
/// voids' own radii, the packer's epsilon and z_min, stopped by phi0 or N0 (unless the scene's
/// `densify:` says otherwise); region by region when the scene has regions (index 0: the
/// tetrahedra of no region, with the scene's law and stop).
void fill_tet_mesh(const Scene& scene, SphereRun<3>& run) {
  const TetMeshOptions& t = scene.packer.tet_mesh;
  const TetMesh& mesh = *scene.tet_mesh;
  TetFillOptions o;
  o.overlap = t.overlap;
  o.z_min = t.z_min;
  o.loose = t.loose;
  o.target_volume_fraction = scene.stop.target_volume_fraction ? scene.stop.target_volume_fraction
                                                                : scene.target_solid_fraction;
  o.max_particles = scene.stop.max_particles;
  std::optional<SceneRegions> regions;
  if (!scene.regions.empty()) {
    regions.emplace(scene);
    for (std::size_t g = 0; g < regions->count(); ++g) o.regions.push_back({regions->law(g), regions->target(g)});
    o.tet_region = regions->of_tet();
  }
  run.contact_tolerance = scene.packer.contact_tolerance;
  run.tet_filled = fp::fill_tet_mesh(mesh, *scene.container3, *scene.radii, o, scene.seed, run.contact_tolerance, run.packing);
  run.seconds = run.tet_filled->seconds;
  DensifyOptions step_7b;
  step_7b.radii = VoidRadii::Fit;
  step_7b.overlap = t.overlap;
  step_7b.z_min = t.z_min;
  step_7b.fallback_r_min = t.fallback_r_min;
  step_7b.target_volume_fraction = o.target_volume_fraction;
  step_7b.max_particles = o.max_particles;
  DensifyOptions base = scene.densify.value_or(step_7b);
  if (!base.target_volume_fraction) base.target_volume_fraction = o.target_volume_fraction;
  if (!regions) {
    fill<3>(scene, base, run, *scene.radii);
  } else {
    for (std::size_t g = 0; g < regions->count(); ++g) {
      if (!(regions->volume(g) > 0)) continue;
      const VoidRegion<3> where{[&, g](const Vec3& x) { return regions->at(x) == g; }, regions->volume(g)};
      DensifyOptions d = base;
      if (const auto phi0 = regions->target(g)) d.target_volume_fraction = phi0;
      fill<3>(scene, d, run, regions->law(g) ? *regions->law(g) : *scene.radii, &where, g);
    }
  }
  if (run.densified->stop == VoidFillingStop::VolumeFraction) run.stop = StopReason::VolumeFraction;
  else if (run.densified->stop == VoidFillingStop::ParticleCount) run.stop = StopReason::ParticleCount;
}

/// Paper 003: the list of the target (its solid phi V drawn from the law) or of stop.particles,
/// stacked largest first.
template <int D>
void stack(const Scene& scene, SphereRun<D>& run) {
  const Container<D>& container = *scene.container<D>();
  Rng rng(scene.seed);
  std::vector<double> radii;
  if (scene.target_solid_fraction) {
    radii = radii_for_measure<D>(*scene.radii, *scene.target_solid_fraction * container.measure(), rng);
  } else {
    for (std::uint64_t k = 0; k < *scene.stop.max_particles; ++k) radii.push_back(scene.radii->sample(rng));
  }
  const StackingParameters& p = scene.packer.stacking;
  const StackingOptions o{p.random_tries,      p.near_tries, p.two_contact_tries, p.nuclei,
                          p.pairs_per_nucleus, p.reshapes,   p.contacts_first,    p.random_share};
  run.contact_tolerance = scene.packer.contact_tolerance;
  run.stacked = stack_graded<D>(container, std::move(radii), o, scene.seed ^ 0x57AC'4ED0'0000'0003ull, run.contact_tolerance,
                                run.packing);
  StackingReport& s = *run.stacked;
  if (p.voids && !s.left_out.empty()) {  // (12): the Delaunay voids take what the steps could not place
    DensifyOptions into;
    into.list = s.left_out;
    const VoidFillingReport v = fill_voids<D>(run.packing, container, *scene.radii, into, scene.seed, run.contact_tolerance);
    s.by_voids = v.added;
    s.placed += v.added;
    s.unplaced -= v.added;
    s.solid_placed = solid_of(run.packing);
    s.seconds += v.seconds;
  }
  run.solid_measure = s.solid_placed;
  run.seconds = s.seconds;
}

/// Each region's solid fraction (its spheres by their centres) against its phi0.
void add_region_lines(const SceneRegions& regions, const Packing<3>& packing, PackCheck& c) {
  std::vector<double> solid(regions.count(), 0.0);
  std::vector<std::uint64_t> count(regions.count(), 0);
  for (std::size_t i = 0; i < packing.size(); ++i) {
    const std::size_t g = regions.at(packing.centers[i]);
    solid[g] += ball_measure<3>(packing.radii[i]);
    ++count[g];
  }
  for (std::size_t g = 0; g < regions.count(); ++g) {
    if (!(regions.volume(g) > 0)) continue;
    const auto target = regions.target(g);
    char line[240];
    std::snprintf(line, sizeof line, "  region         %s: volume fraction %.4f%s, %llu spheres (by their centres)\n",
                  regions.name(g).c_str(), solid[g] / regions.volume(g),
                  target ? (" (target " + std::to_string(*target).substr(0, 6) + ")").c_str() : "",
                  static_cast<unsigned long long>(count[g]));
    c.summary_lines += line;
    c.metrics.emplace_back("region_" + regions.name(g) + "_volume_fraction", solid[g] / regions.volume(g));
    if (count[g] == 0) c.incomplete.push_back("the region " + regions.name(g) + " holds no sphere (its law does not fit in it)");
  }
}

/// The least-squares densification's line and figures (VF before, at the optimum, after; how
/// far the radii and the centres moved; what the overlap removal did).
void add_least_squares_lines(const LeastSquaresReport& q, double measure, LeastSquaresRadii radii, PackCheck& c) {
  char line[600];
  std::snprintf(line, sizeof line,
                "  least squares  radii %s; %zu edges, %zu wall terms; Eq. 4 %.4g -> %.4g in %d evaluations; volume fraction "
                "%.4f -> %.4f (optimum %.4f, %zu overlaps there, up to %.3g); radii %zu grown, change mean %.4f max %.4f; "
                "centres moved mean %.4f max %.4f radii; overlap removal: %d relax rounds, %zu radii clipped (up to %.2g), "
                "%d sweeps, %zu grown into the room left, move kept %.4g%s; %.3f s\n",
                radii == LeastSquaresRadii::Range ? "in the law's range" : "fixed", q.edges, q.boundary_terms,
                q.objective_before, q.objective_after, q.evaluations, q.solid_before / measure, q.solid_after / measure,
                q.solid_solved / measure, q.overlaps_solved, q.max_overlap_solved, q.radii_grown, q.mean_radius_change,
                q.max_radius_change, q.mean_move, q.max_move, q.relax_rounds, q.radii_clipped, q.max_clip, q.sweeps,
                q.swelled, q.kept_share, q.less_dense ? " (the result was less dense: the packing given kept)" : "",
                q.seconds);
  c.summary_lines += line;
  c.info.emplace_back("least_squares_radii", radii == LeastSquaresRadii::Range ? "range" : "fixed");
  c.metrics.insert(c.metrics.end(), {{"least_squares_volume_fraction_before", q.solid_before / measure},
                                     {"least_squares_volume_fraction_optimum", q.solid_solved / measure},
                                     {"least_squares_volume_fraction_after", q.solid_after / measure},
                                     {"least_squares_objective_before", q.objective_before},
                                     {"least_squares_objective_after", q.objective_after},
                                     {"least_squares_max_overlap_optimum", q.max_overlap_solved},
                                     {"least_squares_mean_radius_change", q.mean_radius_change},
                                     {"least_squares_max_radius_change", q.max_radius_change},
                                     {"least_squares_mean_move", q.mean_move},
                                     {"least_squares_max_move", q.max_move},
                                     {"least_squares_max_clip", q.max_clip},
                                     {"least_squares_kept_share", q.kept_share},
                                     {"least_squares_seconds", q.seconds},
                                     {"least_squares_triangulation_seconds", q.triangulation_seconds},
                                     {"least_squares_solve_seconds", q.solve_seconds}});
  c.counters.insert(c.counters.end(), {{"least_squares_edges", q.edges},
                                       {"least_squares_wall_terms", q.boundary_terms},
                                       {"least_squares_evaluations", static_cast<std::uint64_t>(q.evaluations)},
                                       {"least_squares_overlaps_optimum", q.overlaps_solved},
                                       {"least_squares_relax_rounds", static_cast<std::uint64_t>(q.relax_rounds)},
                                       {"least_squares_relax_evaluations", static_cast<std::uint64_t>(q.relax_evaluations)},
                                       {"least_squares_sweeps", static_cast<std::uint64_t>(q.sweeps)},
                                       {"least_squares_radii_clipped", q.radii_clipped},
                                       {"least_squares_radii_grown", q.radii_grown},
                                       {"least_squares_swelled", q.swelled},
                                       {"least_squares_less_dense", q.less_dense ? 1u : 0u}});
}

}  // namespace

template <int D>
typename SpherePack<D>::Result SpherePack<D>::pack(const Scene& scene, const ProgressFn& progress, BlockExchange* exchange) {
  if (scene.stop.scale_sizes) {  // N spheres that fill the container: the law's scale is solved for first
    if (exchange && exchange->processes() > 1)
      throw std::runtime_error("stop.scale_sizes packs on one process: run this scene without mpirun, with threads (-j N)");
    const SizeScaling scaling = solve_size_scale<D>(scene, progress);
    Result run = pack(with_radii_scaled(scene, scaling.scale), progress, nullptr);
    run.sizes_scaled = scaling;
    run.seconds += scaling.seconds;
    return run;
  }
  Result run;
  if constexpr (D == 3) {
    if (scene.packer.method == "tet_mesh") {
      fill_tet_mesh(scene, run);
      densify_by_least_squares<3>(scene, run);
      thin_to_target<3>(scene, run);
      return run;
    }
  }
  if (scene.packer.method == "stacking") {
    stack<D>(scene, run);
    if (scene.densify) fill_scene_voids<D>(scene, run);
    densify_by_least_squares<D>(scene, run);
    return run;
  }
  if (scene.densify && scene.densify->split) {  // the front packs the law's part above the split
    Scene above = scene;
    above.radii = std::make_shared<const SplitRadius>(scene.radii, *scene.densify->split, SplitRadius::Side::Above);
    static_cast<PackResult<D>&>(run) = fp::pack<D>(above, progress, exchange);
  } else {
    static_cast<PackResult<D>&>(run) = fp::pack<D>(scene, progress, exchange);
  }
  const bool root = !exchange || exchange->process() == 0;  // the others hold no packing
  if (scene.densify && root) fill_scene_voids<D>(scene, run);
  if (root) densify_by_least_squares<D>(scene, run);
  if (root) thin_to_target<D>(scene, run);
  return run;
}

template <int D>
typename SpherePack<D>::Result SpherePack<D>::densify(const Scene& scene, Packing<D> packing) {
  Result run;
  run.given = true;
  run.packing = std::move(packing);
  run.contact_tolerance = scene.packer.contact_tolerance;
  run.solid_measure = solid_of(run.packing);
  if (scene.densify || !scene.least_squares) fill_scene_voids<D>(scene, run);
  densify_by_least_squares<D>(scene, run);
  thin_to_target<D>(scene, run);
  return run;
}

template <int D>
std::string SpherePack<D>::stop_text(const Result& run) {
  std::string s = run.given ? "given" : run.tet_filled ? (run.tet_filled->reached_target ? to_string(run.stop) : "mesh filled")
                                                       : to_string(run.stop);
  if (run.densified) s += std::string("; void filling: ") + to_string(run.densified->stop);
  if (run.squared) s += "; least squares";
  if (run.thinned) s += "; thinned to the target";
  if (run.stacked) s = run.stacked->unplaced ? "stacking: " + std::to_string(run.stacked->unplaced) + " found no place"
                                             : std::string("stacking: every particle placed");
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
  const bool fitted = radii_alpha_of(scene) == 0.0;
  options.radii_alpha = radii_alpha_of(scene);
  const RadiusDistributionPtr law = radii_to_check(scene, res.packing.radii);
  PackCheck c = depth == CheckDepth::Analysis
                    ? pack_check_of(analyze_packing<D>(res.packing, &container, law.get(), options))
                    : pack_check_of(validate_packing<D>(res.packing, container, law.get(), res.contact_tolerance,
                                                        options.radii_alpha, nullptr, options.threads),
                                    res.solid_measure / container.measure());
  c.counters.emplace_back("grid_bytes", res.grid_bytes);
  if (res.sizes_scaled) {
    const auto* scaled_law = dynamic_cast<const ScaledRadius*>(law.get());
    add_size_scaling_lines(c, *res.sizes_scaled, res.packing.size(), res.solid_measure / container.measure(),
                           scaled_law ? scaled_law->scale() : std::nan(""));
  }
  else if (!res.given && !res.tet_filled && !res.stacked)  // the front's own stop (the others fill the whole container)
    add_cut_short_reason(c, scene.stop, res.stop, res.packing.size(), res.solid_measure / container.measure());
  add_never_fit_lines(c, res.never_fit_radii, res.packing.radii, law.get());
  // A target solid fraction above what the packer reached is said, with why it stopped.
  std::optional<double> phi0 = scene.stop.target_volume_fraction;
  if (res.densified && scene.densify && scene.densify->target_volume_fraction) phi0 = scene.densify->target_volume_fraction;
  if (phi0 && !scene.target_solid_fraction && scene.regions.empty() && res.solid_measure / container.measure() < *phi0)
    add_not_reached_line(c, *phi0, res.solid_measure / container.measure(), stop_text(res));
  add_target_lines(c, scene, res.thinned, res.solid_measure, container.measure(), stop_text(res),
                   res.stacked && res.stacked->unplaced == 0 && !res.densified);
  if (const auto& s = res.stacked) {
    char line[400];
    std::snprintf(line, sizeof line,
                  "  stacking       %llu asked (volume fraction %.4f), %llu placed: %llu random, %llu near, %llu two-contact, "
                  "%llu three-contact, %llu into voids; %llu reshape passes (%llu moved); %llu without a place; %.3f s\n",
                  static_cast<unsigned long long>(s->asked), s->solid_asked / container.measure(),
                  static_cast<unsigned long long>(s->placed), static_cast<unsigned long long>(s->by_random),
                  static_cast<unsigned long long>(s->by_near), static_cast<unsigned long long>(s->by_two_contact),
                  static_cast<unsigned long long>(s->by_three_contact), static_cast<unsigned long long>(s->by_voids),
                  static_cast<unsigned long long>(s->reshape_passes),
                  static_cast<unsigned long long>(s->reshape_moves), static_cast<unsigned long long>(s->unplaced), s->seconds);
    c.summary_lines += line;
    if (2 * s->placed < s->asked)
      c.incomplete.push_back("the graded stacking placed " + std::to_string(s->placed) + " of the " + std::to_string(s->asked) +
                             " particles of its list");
    c.metrics.emplace_back("stacking_volume_fraction_asked", s->solid_asked / container.measure());
    c.counters.insert(c.counters.end(), {{"stacking_asked", s->asked},
                                         {"stacking_random", s->by_random},
                                         {"stacking_near", s->by_near},
                                         {"stacking_two_contact", s->by_two_contact},
                                         {"stacking_three_contact", s->by_three_contact},
                                         {"stacking_voids", s->by_voids},
                                         {"stacking_reshape_passes", s->reshape_passes},
                                         {"stacking_reshape_moves", s->reshape_moves},
                                         {"stacking_unplaced", s->unplaced}});
  }
  if constexpr (D == 3) {
    if (!scene.regions.empty()) add_region_lines(SceneRegions(scene), res.packing, c);
  }
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
  if (const auto& q = res.squared) add_least_squares_lines(*q, container.measure(), scene.least_squares->radii, c);
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
