#include "cli/pack_api.hpp"

#include <array>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "cli/run_record_start.hpp"
#include "cli/shape_pack.hpp"
#include "cli/sphere_pack.hpp"
#include "contact/shape_analysis.hpp"
#include "contact/shape_validation.hpp"
#include "core/io/exact_decimal.hpp"
#include "core/io/scene_limits.hpp"
#include "core/io/scene_yaml.hpp"
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
  out.valid = check.valid();
  out.validation = check.validation.one_line();
  out.incomplete = check.incomplete_text();
  out.summary = check.summary_lines;
  out.packed.scene = scene;
  out.packed.dimension = D;
  store(out.packed, std::move(res.packing));
  return out;
}

template <int D>
PackingAnalysis analyze_as(const PackingInput& in, const Packing<D>& P, double tolerance, int threads) {
  const Container<D>* container = nullptr;
  RadiusDistributionPtr law;  // the law pack and validate test against (scaled to fill: fitted)
  AnalysisOptions opt;
  if (in.scene) {
    container = in.scene->container<D>();
    law = radii_to_check(*in.scene, P.radii);
    opt.contact_tolerance = in.scene->packer.contact_tolerance;
  }
  if (tolerance >= 0) opt.contact_tolerance = tolerance;
  opt.threads = thread_count(threads);
  return analyze_packing<D>(P, container, law.get(), opt);
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
  return validate_packing<D>(P, *scene.container<D>(), radii_to_check(scene, P.radii).get(), tol,
                             alpha >= 0 ? alpha : radii_alpha_of(scene), nullptr, thread_count(threads));
}

template <int D>
ValidationReport validate_as(const Scene& scene, const ShapePacking<D>& P, double tolerance, double alpha, int) {
  const double tol = tolerance >= 0 ? tolerance : scene.packer.minimisation.gap_tolerance;
  return validate_shapes<D>(P, *scene.container<D>(), tol, requested_templates(scene), alpha >= 0 ? alpha : kRadiiAlpha);
}

/// The particles' coordinates moved from the frame of `from` to that of `to` through their
/// absolute text, as a file written in one frame and read in the other gives them.
template <int D>
struct Reframe {
  std::array<OffsetAxis, 3> from, to;
  Reframe(const Vec<D>& a, const Vec<D>& b) : from(offset_axes(a.data(), D)), to(offset_axes(b.data(), D)) {}
  Vec<D> operator()(const Vec<D>& local) const {
    Vec<D> out;
    std::string text;
    for (int k = 0; k < D; ++k) {
      text.clear();
      from[k].append_absolute(text, local[k]);
      const std::optional<double> moved = to[k].local_from_text(text);
      out[k] = moved ? *moved : local[k];  // not a number stays so (the validation reports it)
    }
    return out;
  }
};

template <int D>
void move_to(Packing<D>& P, const Vec<D>& origin) {
  if (P.origin == origin) return;
  const Reframe<D> reframe(P.origin, origin);
  for (Vec<D>& c : P.centers) c = reframe(c);
  P.origin = origin;
}

template <int D>
void move_to(ShapePacking<D>& P, const Vec<D>& origin, const std::size_t templates) {
  for (std::size_t i = 0; i < P.particles.size(); ++i)
    if (static_cast<std::size_t>(P.particles[i].template_id) >= templates)
      throw std::invalid_argument("particle " + std::to_string(i) + " is of template " +
                                  std::to_string(P.particles[i].template_id) + " but the scene has " +
                                  std::to_string(templates) + " particle templates");
  if (P.origin == origin) return;
  const Reframe<D> reframe(P.origin, origin);
  for (Particle<D>& p : P.particles) p.pose.position = reframe(p.pose.position);
  P.origin = origin;
}

}  // namespace

void check_threads(long long requested, const std::string& name) {
  if (requested < 0 || requested > static_cast<long long>(kMaxThreads))
    throw std::invalid_argument(name + " must be an integer from 0 (every hardware thread) to " + std::to_string(kMaxThreads) +
                                " (got " + std::to_string(requested) + ")");
}

PackingInput packing_in_scene(const PackingInput& in, Scene scene) {
  const std::string named = scene.source_path.empty() ? "the scene" : "the scene " + scene.source_path;
  if (in.dimension != scene.dimension)
    throw std::invalid_argument("the packing is " + std::to_string(in.dimension) + "D, " + named + " " +
                                std::to_string(scene.dimension) + "D");
  const bool shapes = !scene.particle_templates.empty();
  if (in.shapes != shapes)
    throw std::invalid_argument(std::string("the packing is of ") + (in.shapes ? "shapes" : "spheres") + ", " + named +
                                (shapes ? " of shapes" : " of spheres"));
  PackingInput out = in;
  out.scene = std::move(scene);
  const Scene& s = *out.scene;
  if (out.dimension == 2) {
    const Vec<2>& origin = s.container<2>()->origin();
    out.shapes ? move_to<2>(out.shapes2, origin, s.particle_templates.size()) : move_to<2>(out.packing2, origin);
  } else {
    const Vec<3>& origin = s.container<3>()->origin();
    out.shapes ? move_to<3>(out.shapes3, origin, s.particle_templates.size()) : move_to<3>(out.packing3, origin);
  }
  return out;
}

void prepare_scene(Scene& scene, std::optional<std::uint64_t> seed, std::optional<int> threads) {
  if (seed) scene.seed = *seed;
  if (threads) {
    check_threads(*threads, "threads");
    scene.packer.threads = *threads;
  }
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
