#pragma once
// `stop: {particles: N, scale_sizes: true}`: N spheres (disks) that fill the container. The
// radius law is scaled by a factor s, its shape kept, and s is solved for by trial packings: each
// runs the front until it runs empty, and the next moves s by (n / N)^(1/D) (n: the particles it
// placed), until n lands in [N, (1 + kScaleSlack) N]. The packing is then the front at that scale,
// stopped at N: at most a share kScaleSlack of the full packing, the last the front would place, is
// left out. The size test then asks for the law's shape, its scale fitted from the radii
// (core/metrics/radius_scale_fit.hpp), so that `validate` needs the scene file alone.
#include <cstdint>

#include "cli/pack_check.hpp"
#include "core/io/scene.hpp"
#include "front/pack_result.hpp"

namespace fp {

/// The share of the full packing at the scale found that the count N may leave out (the
/// container's solid fraction then within kScaleSlack of the full packing's, relatively).
inline constexpr double kScaleSlack = 0.01;
/// Trial packings at most.
inline constexpr int kMaxScaleTrials = 10;

/// What `stop.scale_sizes` did.
struct SizeScaling {
  std::uint64_t asked = 0;         ///< N
  double scale = 1.0;              ///< the factor of the radius law the packing was made with
  std::uint64_t full_count = 0;    ///< the particles the front places at that scale when it runs empty
  int trials = 0;                  ///< trial packings run
  double seconds = 0.0;            ///< their wall time
  bool found() const;              ///< full_count in [N, (1 + kScaleSlack) N]
};

/// `scene` with its radius law scaled by `s` (and no scale_sizes).
Scene with_radii_scaled(const Scene& scene, double s);

/// The scale at which the front's full packing of `scene` (spheres, stop.particles = N,
/// scale_sizes) holds N particles or slightly more (the best of kMaxScaleTrials trials otherwise:
/// the smallest count at or above N, else the largest). Trials report to `progress`.
template <int D>
SizeScaling solve_size_scale(const Scene& scene, const ProgressFn& progress);

/// The summary line, figures and verdict of a packing made at the scale found: `placed`
/// particles at `container_fraction`; `fitted`: the scale the size test found from the radii.
/// Short of N, or a full packing beyond (1 + kScaleSlack) N, is incomplete (`cut_short`).
void add_size_scaling_lines(PackCheck& c, const SizeScaling& scaling, std::size_t placed, double container_fraction,
                            double fitted);

}  // namespace fp
