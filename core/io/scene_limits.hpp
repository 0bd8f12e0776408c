#pragma once
// What a scene asks of the machine, estimated and checked before any work ("limits
// checked up front"): how many particles the run may place, and the memory that takes. A scene
// that would not fit is refused with exit 2, naming the key to change, instead of running until
// the kernel kills it or a 32-bit particle id wraps.
//
// The rule, stated once (README "Limits"):
//   N   = min(stop.particles, stop.volume_fraction x container / v, phi_max x container / v)
//         v: the mean particle measure (volume in 3D, area in 2D) of the requested sizes;
//         phi_max: the densest packing of equal balls (pi/sqrt(18) in 3D, pi/sqrt(12) in 2D),
//         which no packing of the front was measured to exceed;
//   refused when N > 2^31 - 1 (particle ids), when N x bytes per particle + 300 MB > the memory
//   this process may use (core/system/available_memory.hpp), or when radius_pool is so large against
//   N that the radii left in the pool at the end would fail the radii test of the validation
//   (pool / (N + pool) > 1.95 / sqrt(N), the Kolmogorov-Smirnov critical distance at 0.001).
#include "core/io/scene.hpp"
#include "core/system/available_memory.hpp"

namespace fp {

/// Bytes per particle of a whole `frontpack pack` run (packer, analysis, validation, writers):
/// the growth of peak RSS per particle between a small and a large run (experiments/extremes/
/// RESULTS.md, "Limits": spheres 187, disks 147, 2D capsules 157, 3D capsules too few to
/// measure), rounded up; shapes with many vertices or members hold their own scaled copies, so
/// shapes get a wide margin.
inline constexpr double kBytesPerSphere = 200, kBytesPerDisk = 150, kBytesPerShape2 = 500, kBytesPerShape3 = 2000;
/// What a run needs whatever its size: the program (~25 MB) and the cache of display surfaces
/// that VTU outputs of non-spherical particles keep (at most 256 MB).
inline constexpr double kBytesPerRun = 300e6;

struct RunDemand {
  double container_measure = 0;      ///< volume (3D) or area (2D)
  double mean_particle_measure = 0;  ///< v
  double phi_max = 0;                ///< densest packing of equal balls in this dimension
  double full_particles = 0;         ///< phi_max x container / v
  double particles = 0;              ///< N: what the run may place
  std::string bound_by;              ///< the key of the scene that sets N ("container" when nothing stops earlier)
  double bytes_per_particle = 0;
  double bytes = 0;                  ///< N x bytes per particle + kBytesPerRun
};

/// The demand of `scene` whose particles have mean measure `mean_particle_measure`.
RunDemand estimate_run_demand(const Scene& scene, double mean_particle_measure);

/// Mean measure of balls of radii drawn from `radii` in dimension D (2 or 3).
double mean_ball_measure(const RadiusDistribution& radii, int dimension);

/// Throws SceneError at the key to change when `demand` breaks a limit of the rule above.
void check_run_limits(const Scene& scene, const RunDemand& demand, const MemoryBudget& memory);

}  // namespace fp
