#include "cli/pack_api.hpp"

#include <chrono>
#include <utility>

#include "cli/run_record_start.hpp"
#include "cli/shape_pack.hpp"
#include "cli/sphere_pack.hpp"
#include "contact/shape_analysis.hpp"
#include "contact/shape_validation.hpp"
#include "core/io/scene_limits.hpp"
#include "core/system/parallel_parts.hpp"

namespace fp {
namespace {

void store(PackingInput& in, Packing<2>&& p) { in.packing2 = std::move(p); }
void store(PackingInput& in, Packing<3>&& p) { in.packing3 = std::move(p); }
void store(PackingInput& in, ShapePacking<2>&& p) { in.shapes2 = std::move(p), in.shapes = true; }
void store(PackingInput& in, ShapePacking<3>&& p) { in.shapes3 = std::move(p), in.shapes = true; }

template <int D, class Kind>
PackOutcome pack_as(const Scene& scene, const ProgressFn& progress) {
  typename Kind::Result res = Kind::pack(scene, progress, nullptr);
  const auto t = std::chrono::steady_clock::now();
  const PackCheck check = Kind::check(scene, res, CheckDepth::Analysis);
  const double check_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  PackOutcome out;
  out.record = pack_record<D, Kind>(scene, res, check, check_seconds);
  out.valid = check.validation.ok;
  out.validation = check.validation.one_line();
  out.summary = check.summary_lines;
  out.packed.scene = scene;
  out.packed.dimension = D;
  store(out.packed, std::move(res.packing));
  return out;
}

template <int D>
PackingAnalysis analyze_as(const PackingInput& in, const Packing<D>& P, double tolerance, int threads) {
  const Container<D>* container = nullptr;
  const RadiusDistribution* law = nullptr;
  AnalysisOptions opt;
  if (in.scene) {
    container = in.scene->container<D>();
    law = in.scene->radii.get();
    opt.contact_tolerance = in.scene->packer.contact_tolerance;
  }
  if (tolerance >= 0) opt.contact_tolerance = tolerance;
  opt.threads = thread_count(threads);
  return analyze_packing<D>(P, container, law, opt);
}

template <int D>
PackingAnalysis analyze_as(const PackingInput& in, const ShapePacking<D>& P, double tolerance, int threads) {
  if (!in.scene) throw std::invalid_argument("a packing of shapes is analysed with its scene");
  AnalysisOptions opt;
  opt.contact_tolerance = tolerance >= 0 ? tolerance : in.scene->packer.minimisation.gap_tolerance;
  opt.threads = thread_count(threads);
  return analyze_shape_packing<D>(P, *in.scene, opt);
}

template <int D>
ValidationReport validate_as(const Scene& scene, const Packing<D>& P, double tolerance, double alpha, int threads) {
  const double tol = tolerance >= 0 ? tolerance : overlap_tolerance(scene);
  return validate_packing<D>(P, *scene.container<D>(), radii_to_check(scene).get(), tol,
                             alpha >= 0 ? alpha : radii_alpha_of(scene), nullptr, thread_count(threads));
}

template <int D>
ValidationReport validate_as(const Scene& scene, const ShapePacking<D>& P, double tolerance, double alpha, int) {
  const double tol = tolerance >= 0 ? tolerance : scene.packer.minimisation.gap_tolerance;
  return validate_shapes<D>(P, *scene.container<D>(), tol, requested_templates(scene), alpha >= 0 ? alpha : kRadiiAlpha);
}

}  // namespace

void prepare_scene(Scene& scene, std::optional<std::uint64_t> seed, std::optional<int> threads) {
  if (seed) scene.seed = *seed;
  if (threads) scene.packer.threads = *threads;
  if (!scene.particle_templates.empty()) check_shape_scene(scene);
  else check_run_limits(scene, estimate_run_demand(scene, mean_ball_measure(*scene.radii, scene.dimension)), available_memory());
}

PackOutcome pack_scene(const Scene& scene, const ProgressFn& progress) {
  if (!scene.particle_templates.empty())
    return scene.dimension == 2 ? pack_as<2, ShapePack<2>>(scene, progress) : pack_as<3, ShapePack<3>>(scene, progress);
  return scene.dimension == 2 ? pack_as<2, SpherePack<2>>(scene, progress) : pack_as<3, SpherePack<3>>(scene, progress);
}

PackingAnalysis analyze_input(const PackingInput& in, double tolerance, int threads) {
  if (in.shapes)
    return in.dimension == 2 ? analyze_as<2>(in, in.shapes2, tolerance, threads) : analyze_as<3>(in, in.shapes3, tolerance, threads);
  return in.dimension == 2 ? analyze_as<2>(in, in.packing2, tolerance, threads) : analyze_as<3>(in, in.packing3, tolerance, threads);
}

ValidationReport validate_input(const PackingInput& in, double tolerance, double alpha, int threads) {
  if (!in.scene) throw std::invalid_argument("a packing is validated against its scene");
  const Scene& s = *in.scene;
  if (in.shapes)
    return in.dimension == 2 ? validate_as<2>(s, in.shapes2, tolerance, alpha, threads) : validate_as<3>(s, in.shapes3, tolerance, alpha, threads);
  return in.dimension == 2 ? validate_as<2>(s, in.packing2, tolerance, alpha, threads) : validate_as<3>(s, in.packing3, tolerance, alpha, threads);
}

}  // namespace fp
