#pragma once
// Closest points of two segments (Ericson, Real-Time Collision Detection, 5.1.9), the distance
// d1(s1, s2) of paper 004 Eq. 6 from which the spherocylinder gap follows.
#include <algorithm>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D>
struct SegmentClosest {
  Vec<D> on_first;
  Vec<D> on_second;
};

/// Closest points of [p1, q1] and [p2, q2]; degenerate segments (points) are handled.
template <int D>
SegmentClosest<D> closest_points_on_segments(const Vec<D>& p1, const Vec<D>& q1, const Vec<D>& p2, const Vec<D>& q2) {
  const Vec<D> d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  // Relative to the segments' own lengths, so huge coordinates and tiny particles keep their digits.
  const double eps = 1e-300;
  double s = 0, t = 0;
  if (a <= eps && e <= eps) return {p1, p2};
  if (a <= eps) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= eps) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;  // parallel: any s
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {p1 + s * d1, p2 + t * d2};
}

}  // namespace fp
