#pragma once
// The measure of a ball (disk in 2D) inside an axis-aligned box: what a cell of the per-cell
// solid fraction (cell_volume_fraction.hpp) holds of each ball it cuts.
//  * 2D, exact: the area is the integral over x of the chord inside [y0, y1]; between the
//    abscissae where the circle crosses y = y0 or y = y1 each bound of the chord is either the
//    circle or the line, integrated in closed form (int sqrt(r^2 - x^2) dx).
//  * 3D: the integral over z of that exact area of the section (radius sqrt(r^2 - z^2)), by
//    Gauss-Legendre on the pieces between the heights where the section's circle meets an edge
//    line or a corner of the box (where the area has a kink, smoothed by a change of variable); a ball cut by one face plane alone
//    (most cut balls) is a cap, in closed form. Relative error below 1e-9 of the ball measured in
//    tests/metrics/ball_box_test.cpp against the sum over a partition, which is exact.
#include <algorithm>
#include <cmath>

#include "core/geometry/vec.hpp"

namespace fp {

/// Measure of the part of a ball of radius r on the inner side of a plane at signed distance t
/// from its centre (t > 0: the centre is on the inner side), |t| < r. The cut-off cap has height
/// h = r - t: volume pi h^2 (3r - h) / 3 in 3D, segment area r^2 acos(1 - h/r) - (r - h) sqrt(h (2r - h))
/// in 2D. Subtracting from the whole ball keeps the absolute error at rounding level.
template <int D>
double ball_inside_plane(double r, double t) {
  const double h = r - t;
  double cap;
  if constexpr (D == 3) cap = kPi * h * h * (3.0 * r - h) / 3.0;
  else
    cap = r * r * std::acos(std::clamp(1.0 - h / r, -1.0, 1.0)) - (r - h) * std::sqrt(std::max(0.0, h * (2.0 * r - h)));
  return ball_measure<D>(r) - cap;
}

/// |ball(c, r) ∩ [lo, hi]|, for r >= 0 and lo <= hi componentwise.
template <int D>
double ball_box_measure(const Vec<D>& c, double r, const Vec<D>& lo, const Vec<D>& hi);

}  // namespace fp
