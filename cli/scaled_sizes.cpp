#include "cli/scaled_sizes.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/io/scene_limits.hpp"
#include "core/sampling/scaled_radius.hpp"
#include "front/container_too_small.hpp"
#include "front/pack.hpp"

namespace fp {

bool SizeScaling::found() const {
  return full_count >= asked && static_cast<double>(full_count) <= (1 + kScaleSlack) * static_cast<double>(asked);
}

Scene with_radii_scaled(const Scene& scene, double s) {
  Scene scaled = scene;
  scaled.radii = std::make_shared<const ScaledRadius>(scene.radii, s);
  scaled.stop.scale_sizes = false;
  return scaled;
}

template <int D>
SizeScaling solve_size_scale(const Scene& scene, const ProgressFn& progress) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t N = *scene.stop.max_particles;
  const double n_asked = static_cast<double>(N);
  // The first guess: N balls of the law's mean measure at a solid fraction of random packings.
  const double phi = D == 3 ? 0.6 : 0.8;
  double s = std::pow(phi * scene.container<D>()->measure() / (n_asked * mean_ball_measure(*scene.radii, D)), 1.0 / D);
  SizeScaling best;
  best.asked = N;
  for (int trial = 0; trial < kMaxScaleTrials; ++trial) {
    Scene t = with_radii_scaled(scene, s);
    t.stop.max_particles = 2 * N;  // a first guess far too small stops here
    std::uint64_t n = 0;
    try {
      n = fp::pack<D>(t, progress, nullptr).packing.size();
    } catch (const ContainerTooSmall&) {  // the scaled law no longer fits: smaller
      n = 0;
    }
    ++best.trials;
    const SizeScaling now{N, s, n};
    // Keep the smallest count at or above N; below N, the largest.
    const bool better = trial == 0 || (n >= N ? best.full_count < N || n < best.full_count : best.full_count < N && n > best.full_count);
    if (better) best.scale = s, best.full_count = n;
    if (now.found()) break;
    // Aim at the middle of the band: the count goes as s^-D.
    s *= n == 0 ? 0.5 : std::pow(static_cast<double>(n) / (n_asked * (1 + kScaleSlack / 2)), 1.0 / D);
  }
  best.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return best;
}

void add_size_scaling_lines(PackCheck& c, const SizeScaling& s, std::size_t placed, double container_fraction,
                            double fitted) {
  char line[480];
  std::snprintf(line, sizeof line,
                "  scaled sizes   radii x %.6g (the law's shape kept) so that %llu fill the container: at that scale the "
                "front places %llu when it runs empty; %d trial packings, %.3f s; the size test's scale, fitted from the "
                "radii: %.6g\n",
                s.scale, static_cast<unsigned long long>(s.asked), static_cast<unsigned long long>(s.full_count), s.trials,
                s.seconds, fitted);
  c.summary_lines += line;
  c.metrics.insert(c.metrics.end(), {{"size_scale", s.scale}, {"size_scale_fitted", fitted}, {"size_scale_seconds", s.seconds}});
  c.counters.insert(c.counters.end(), {{"size_scale_trials", static_cast<std::uint64_t>(s.trials)}, {"size_scale_full_count", s.full_count}});
  if (s.found() && placed == s.asked) return;
  std::snprintf(line, sizeof line,
                "stop.scale_sizes found no scale at which %llu particles fill the container within %.0f %% in %d trial "
                "packings: at the best, radii x %.6g, the front places %llu when it runs empty; %zu placed (volume "
                "fraction %.4f of the container)",
                static_cast<unsigned long long>(s.asked), 100 * kScaleSlack, s.trials, s.scale,
                static_cast<unsigned long long>(s.full_count), placed, container_fraction);
  c.cut_short.push_back(line);
}

template SizeScaling solve_size_scale<2>(const Scene&, const ProgressFn&);
template SizeScaling solve_size_scale<3>(const Scene&, const ProgressFn&);

}  // namespace fp
