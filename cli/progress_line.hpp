#pragma once
// The progress line of `frontpack pack --progress` (stderr, rewritten in place): the count, the
// rate, the container's solid fraction, the time, and an estimate of the share done and the time
// left. The share is the largest of: the count against stop.particles, the time against stop.time,
// the solid fraction against stop.volume_fraction or else against a full container's usual one
// (0.6 in 3D, 0.8 in 2D: an estimate, so shown with "~" and never above 99 % until the end).
#include <algorithm>
#include <cstdint>
#include <cstdio>

#include "core/io/scene.hpp"

namespace fp {

class ProgressLine {
 public:
  ProgressLine(bool on, const Scene& scene)
      : on_(on),
        particles_(scene.stop.max_particles ? static_cast<double>(*scene.stop.max_particles) : 0.0),
        seconds_(scene.stop.time_limit_seconds.value_or(0.0)),
        fraction_(scene.stop.target_volume_fraction.value_or(scene.dimension == 3 ? 0.6 : 0.8)) {}
  void operator()(std::uint64_t n, double t, double vf) {
    double done = vf / fraction_;
    if (particles_ > 0) done = std::max(done, static_cast<double>(n) / particles_);
    if (seconds_ > 0) done = std::max(done, t / seconds_);
    done = std::clamp(done, 0.0, 0.99);
    std::fprintf(stderr, "\r  packed %12llu   %10.0f /s   VF %.4f   %6.1f s   ~%2.0f %%, ~%.0f s left ",
                 static_cast<unsigned long long>(n), t > 0 ? static_cast<double>(n) / t : 0.0, vf, t, 100 * done,
                 done > 0 ? t * (1 / done - 1) : 0.0);
    std::fflush(stderr);
    shown_ = true;
  }
  void finish() {
    if (shown_) std::fprintf(stderr, "\n");
  }
  bool on() const { return on_; }

 private:
  bool on_;
  double particles_, seconds_, fraction_;
  bool shown_ = false;
};

}  // namespace fp
