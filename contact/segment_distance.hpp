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

/// Two segments of fixed directions d1, d2 (a point: zero), prepared for many closest-point
/// queries as they translate (a contact solver moving one particle against fixed ones): what
/// depends on the directions alone is computed once.
template <int D>
class SegmentPair {
 public:
  SegmentPair(const Vec<D>& d1, const Vec<D>& d2)
      : d1_(d1), d2_(d2), a_(d1.squaredNorm()), e_(d2.squaredNorm()), b_(d1.dot(d2)), denom_(a_ * e_ - b_ * b_) {}

  /// Closest points of [p1, p1 + d1] and [p2, p2 + d2]; degenerate segments (points) are handled.
  SegmentClosest<D> closest(const Vec<D>& p1, const Vec<D>& p2) const {
    const Vec<D> r = p1 - p2;
    const double f = d2_.dot(r);
    // Relative to the segments' own lengths, so huge coordinates and tiny particles keep their digits.
    const double eps = 1e-300;
    double s = 0, t = 0;
    if (a_ <= eps && e_ <= eps) return {p1, p2};
    if (a_ <= eps) {
      t = std::clamp(f / e_, 0.0, 1.0);
    } else {
      const double c = d1_.dot(r);
      if (e_ <= eps) {
        s = std::clamp(-c / a_, 0.0, 1.0);
      } else {
        s = denom_ > 1e-14 * a_ * e_ ? std::clamp((b_ * f - c * e_) / denom_, 0.0, 1.0) : 0.0;  // parallel: any s
        t = (b_ * s + f) / e_;
        if (t < 0) {
          t = 0;
          s = std::clamp(-c / a_, 0.0, 1.0);
        } else if (t > 1) {
          t = 1;
          s = std::clamp((b_ - c) / a_, 0.0, 1.0);
        }
      }
    }
    return {p1 + s * d1_, p2 + t * d2_};
  }

 private:
  Vec<D> d1_, d2_;
  double a_, e_, b_, denom_;
};

/// Closest points of [p1, q1] and [p2, q2].
template <int D>
SegmentClosest<D> closest_points_on_segments(const Vec<D>& p1, const Vec<D>& q1, const Vec<D>& p2, const Vec<D>& q2) {
  return SegmentPair<D>(q1 - p1, q2 - p2).closest(p1, p2);
}

}  // namespace fp
