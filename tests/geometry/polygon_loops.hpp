#pragma once
// The polygon container's queries as loops over every edge: the code PolygonContainer ran
// before its edges were indexed (O(n) per query, O(n^2) simplicity check). The indexed
// container must give the same doubles, so these are copied, not rederived.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/geometry/vec.hpp"
#include "core/geometry/wall.hpp"

namespace fp::loops {

inline double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

inline bool on_collinear_segment(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= c.y() &&
         c.y() <= std::max(a.y(), b.y());
}

inline bool segments_meet(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2) {
  const double o1 = orient(p1, p2, q1), o2 = orient(p1, p2, q2);
  const double o3 = orient(q1, q2, p1), o4 = orient(q1, q2, p2);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  return (o1 == 0 && on_collinear_segment(p1, p2, q1)) || (o2 == 0 && on_collinear_segment(p1, p2, q2)) ||
         (o3 == 0 && on_collinear_segment(q1, q2, p1)) || (o4 == 0 && on_collinear_segment(q1, q2, p2));
}

inline double segment_distance2(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double t = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (p - a - t * e).squaredNorm();
}

/// No fold-back at a vertex and no two non-adjacent edges meeting (every pair tested).
inline bool is_simple(const std::vector<Vec2>& v) {
  const int n = static_cast<int>(v.size());
  for (int i = 0; i < n; ++i) {
    const Vec2 &a = v[(i + n - 1) % n], &b = v[i], &c = v[(i + 1) % n];
    if (orient(a, b, c) == 0.0 && (b - a).dot(c - b) < 0.0) return false;
  }
  for (int e = 0; e < n; ++e)
    for (int f = e + 2; f < n; ++f) {
      if (e == 0 && f == n - 1) continue;
      if (segments_meet(v[e], v[(e + 1) % n], v[f], v[(f + 1) % n])) return false;
    }
  return true;
}

/// Sunday's winding number (boundary counts as inside) and the squared distance to the boundary.
inline bool locate(const std::vector<Vec2>& v, const Vec2& p, double* dist2) {
  const int n = static_cast<int>(v.size());
  int winding = 0;
  bool on_boundary = false;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const Vec2& a = v[i];
    const Vec2& b = v[i + 1 == n ? 0 : i + 1];
    if (dist2) best = std::min(best, segment_distance2(p, a, b));
    if (a.y() <= p.y()) {
      if (b.y() > p.y()) {
        const double o = orient(a, b, p);
        if (o > 0) ++winding;
        else if (o == 0) on_boundary = true;
      } else if (b.y() == p.y() && orient(a, b, p) == 0 && on_collinear_segment(a, b, p)) {
        on_boundary = true;
      }
    } else if (b.y() <= p.y()) {
      const double o = orient(a, b, p);
      if (o < 0) --winding;
      else if (o == 0) on_boundary = true;
    }
  }
  if (dist2) *dist2 = on_boundary ? 0.0 : best;
  return on_boundary || winding != 0;
}

inline double signed_distance(const std::vector<Vec2>& v, const Vec2& p) {
  double d2;
  const bool in = locate(v, p, &d2);
  const double d = std::sqrt(d2);
  return in ? -d : d;
}

/// `v` counter-clockwise; inward normals as the container computes them.
inline std::vector<Wall<2>> walls_near(const std::vector<Vec2>& v, const Vec2& p, double reach) {
  const int n = static_cast<int>(v.size());
  std::vector<Wall<2>> out;
  const double reach2 = reach * reach;
  for (int i = 0; i < n; ++i) {
    const Vec2& a = v[i];
    const Vec2& b = v[i + 1 == n ? 0 : i + 1];
    const Vec2 e = (b - a).normalized();
    if (segment_distance2(p, a, b) <= reach2) out.push_back(Wall<2>::plane(a, Vec2(-e.y(), e.x()), i));
  }
  for (int i = 0; i < n; ++i)
    if (orient(v[(i + n - 1) % n], v[i], v[(i + 1) % n]) < 0.0 && (p - v[i]).squaredNorm() <= reach2)
      out.push_back(Wall<2>::vertex(v[i], n + i));
  return out;
}

}  // namespace fp::loops
