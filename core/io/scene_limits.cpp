#include "core/io/scene_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/io/scene_error.hpp"
#include "core/sampling/radius_moment.hpp"

namespace fp {
namespace {

/// Kolmogorov's c(alpha) at alpha = 0.001, the validation's default level.
constexpr double kKsCritical = 1.949;

[[noreturn]] void fail_at(const Scene& scene, const std::string& key, const std::string& message) {
  const SourceSpot s = scene.spot(key);
  throw SceneError(s.file, s.line, s.column, key, message);
}

std::string num(double x) {
  std::ostringstream os;
  os.precision(3);
  os << x;
  return os.str();
}

std::string bytes_text(double b) {
  const char* units[] = {"bytes", "KB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (b >= 1000 && u < 6) b /= 1000, ++u;
  return num(b) + " " + units[u];
}

}  // namespace

double mean_ball_measure(const RadiusDistribution& radii, int dimension) {
  return dimension == 3 ? 4.0 / 3.0 * kPi * radius_moment(radii, 3) : kPi * radius_moment(radii, 2);
}

RunDemand estimate_run_demand(const Scene& scene, double mean_particle_measure) {
  const int D = scene.dimension;
  RunDemand d;
  d.container_measure = D == 3 ? scene.container3->measure() : scene.container2->measure();
  d.mean_particle_measure = mean_particle_measure;
  d.phi_max = D == 3 ? kPi / std::sqrt(18.0) : kPi / std::sqrt(12.0);
  d.full_particles = d.phi_max * d.container_measure / mean_particle_measure;
  d.particles = d.full_particles;
  d.bound_by = "container";
  if (scene.stop.target_volume_fraction) {
    const double n = *scene.stop.target_volume_fraction * d.container_measure / mean_particle_measure;
    if (n < d.particles) d.particles = n, d.bound_by = "stop.volume_fraction";
  }
  // stop.scale_sizes: the sizes are scaled to the count, and its trial packings place up to twice it.
  if (scene.stop.max_particles && scene.stop.scale_sizes)
    d.particles = 2.0 * static_cast<double>(*scene.stop.max_particles), d.bound_by = "stop.particles";
  else if (scene.stop.max_particles && static_cast<double>(*scene.stop.max_particles) < d.particles)
    d.particles = static_cast<double>(*scene.stop.max_particles), d.bound_by = "stop.particles";
  const bool shapes = !scene.particle_templates.empty();
  d.bytes_per_particle = shapes ? (D == 3 ? kBytesPerShape3 : kBytesPerShape2) : (D == 3 ? kBytesPerSphere : kBytesPerDisk);
  d.bytes = d.particles * d.bytes_per_particle + kBytesPerRun;
  return d;
}

void check_run_limits(const Scene& scene, const RunDemand& d, const MemoryBudget& memory) {
  const bool by_container = d.bound_by == "container";
  const std::string what = scene.dimension == 3 ? "volume" : "area";
  const std::string how =
      by_container ? num(d.phi_max) + " x container " + what + " " + num(d.container_measure) + " / mean particle " + what + " " +
                         num(d.mean_particle_measure) + ": the container filled as densely as equal balls can be"
                   : "its '" + d.bound_by + "'";
  const std::string remedy =
      by_container ? std::string("; add stop: {particles: N} or a stop.volume_fraction") +
                         (scene.stop.time_limit_seconds ? " (a time limit does not bound the count)" : "") +
                         ", or use larger particles or a smaller container"
                   : "; lower it, or use larger particles";
  constexpr double kMaxIds = std::numeric_limits<int>::max();
  if (!(d.particles <= kMaxIds))
    fail_at(scene, d.bound_by, "this run could place about " + num(d.particles) + " particles (" + how + "), more than the " +
                                   num(kMaxIds) + " a packing can number (32-bit ids)" + remedy);
  if (d.bytes > static_cast<double>(memory.bytes)) {
    const double fits = std::max(0.0, static_cast<double>(memory.bytes) - kBytesPerRun) / d.bytes_per_particle;
    fail_at(scene, d.bound_by, "this run could place about " + num(d.particles) + " particles (" + how + "), needing about " +
                                   bytes_text(d.bytes) + " at " + num(d.bytes_per_particle) + " bytes per particle and 300 MB for the run, more than the " +
                                   bytes_text(static_cast<double>(memory.bytes)) + " this process may use (" + memory.source +
                                   ")" + remedy + " (about " + num(fits) + " particles fit)");
  }
  // The graded stacking makes its whole list before it places any: a list beyond what the
  // container can hold ran for 22 s (10^5) or out of memory (3 x 10^9) before failing.
  if (scene.packer.method == "stacking" && scene.stop.max_particles &&
      static_cast<double>(*scene.stop.max_particles) > d.full_particles)
    fail_at(scene, "stop.particles",
            "the graded stacking places a list of " + num(static_cast<double>(*scene.stop.max_particles)) +
                " particles, more than the container can hold: about " + num(d.full_particles) + " (" + num(d.phi_max) +
                " x container " + what + " " + num(d.container_measure) + " / mean particle " + what + " " +
                num(d.mean_particle_measure) + ", the densest packing of equal balls); give fewer, or a target instead");
  // A target below one particle's solid thins every particle away (a packing of none).
  if (scene.target_solid_fraction && *scene.target_solid_fraction * d.container_measure < d.mean_particle_measure)
    fail_at(scene, "target",
            "a solid fraction of " + num(*scene.target_solid_fraction) + " is " + num(*scene.target_solid_fraction * d.container_measure) +
                " of the container's " + what + " " + num(d.container_measure) + ", less than one particle (mean " + what + " " +
                num(d.mean_particle_measure) + "): no particle would be kept; give a larger solid fraction (a smaller porosity or void ratio)");
  // The pool's last radii are never placed, and they are mostly large ones: against N particles
  // they shift the radii's distribution by up to pool / (N + pool).
  const double pool = scene.packer.radius_pool, n = std::max(d.particles, 1.0);
  if (pool / (n + pool) > kKsCritical / std::sqrt(n))
    fail_at(scene, "packer.radius_pool",
            "a pool of " + num(pool) + " radii is too large for the about " + num(d.particles) + " particles this run can place (" + how +
                "): the radii left in the pool at the end would bias the sizes beyond what the validation's radii test accepts "
                "(pool / (N + pool) must stay below 1.95 / sqrt(N)); use a smaller radius_pool");
}

}  // namespace fp
