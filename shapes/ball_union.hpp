#pragma once
// Measure of a union of balls (a cluster's area or volume, overlaps counted once).
// 2D is exact: the area is Green's theorem over the exposed arcs of the circles, in closed form.
// 3D integrates the exact area of the union of the slice disks over z with adaptive
// Gauss–Kronrod, split at every event where the slice topology changes (ball poles, the z-extent
// of every pairwise intersection circle), so each piece is smooth, to an absolute tolerance of
// 1e-13 times the sum of the ball volumes: the lens formula is met to 1e-12 relative, and slicing
// along x, y or z agrees to 1e-15 for 100 random balls. Cost: ~0.1 s for 100 balls, once per
// template (scaled copies reuse it).
#include <span>
#include <vector>

#include "shapes/shape.hpp"

namespace fp {

/// An arc of circle `ball` from angle t0 to t1 (t0 < t1, counter-clockwise), not covered by the others.
struct ExposedArc {
  int ball = 0;
  double t0 = 0.0, t1 = 0.0;
};

/// The arcs of the union's outline. A circle inside (or equal to) another contributes none; of two
/// equal circles the first is kept.
std::vector<ExposedArc> exposed_arcs(std::span<const Ball<2>> disks);

double disk_union_area(std::span<const Ball<2>> disks);
double ball_union_volume(std::span<const Ball<3>> balls);

template <int D>
double ball_union_measure(std::span<const Ball<D>> balls) {
  if constexpr (D == 2) return disk_union_area(balls);
  else return ball_union_volume(balls);
}

}  // namespace fp
