#pragma once
// Convex polygons (2D), counter-clockwise point lists: hulls, the Minkowski difference by the
// O(n + m) edge merge, signed distances. What the 2D wrapper solver builds its wrappers from
// (paper 004, Sect. 3.1: "the wrapping polygon has as many edges as both together") and the
// narrow phase's exact distance of apart polygons. Every function is exact up to rounding and
// allocates nothing beyond its output (callers reuse scratch vectors).
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp::convex_polygon {

using V = Vec2;

inline double cross(const V& a, const V& b) { return a.x() * b.y() - a.y() * b.x(); }
/// Whether direction d has its angle in [0, pi).
inline bool upper(const V& d) { return d.y() > 0 || (d.y() == 0 && d.x() >= 0); }
/// Outward unit normal of the edge along d of a counter-clockwise polygon.
inline V outward(const V& d) { return V(d.y(), -d.x()).normalized(); }

/// Appends to `out` the counter-clockwise convex hull of p (Andrew's monotone chain) without
/// collinear points: 1 or 2 points when the points span no area. p is sorted and deduplicated in
/// place (callers pass scratch: a solve builds hundreds of hulls and allocates none).
inline void append_hull(std::vector<V>& p, std::vector<V>& out) {
  std::sort(p.begin(), p.end(), [](const V& a, const V& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() <= 2) {
    out.insert(out.end(), p.begin(), p.end());
    return;
  }
  const std::size_t start = out.size();
  out.resize(start + 2 * p.size());
  V* h = out.data() + start;
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  out.resize(start + k - 1);
}

/// Whether p (3 points or more) is a strictly convex polygon counter-clockwise: every turn to the
/// left, the edges winding once. Such a polygon (a polygon particle's vertices, turned and moved)
/// is its own hull.
inline bool strictly_convex_ccw(std::span<const V> p) {
  const std::size_t n = p.size();
  if (n < 3) return false;
  int windings = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const V& a = p[i];
    const V& b = p[(i + 1) % n];
    const V& c = p[(i + 2) % n];
    if (!(cross(b - a, c - a) > 0)) return false;
    if (!upper(b - a) && upper(c - b)) ++windings;
  }
  return windings == 1;
}

/// Appends to `out` what append_hull() gives for the points of `cycle`, a convex polygon
/// counter-clockwise from any vertex, possibly with repeated or collinear points (a Minkowski
/// sum's merge), in linear time: from the lowest (x, y), each point kept while it turns left
/// (the monotone chain's test on the same triples), the start closing the cycle. Returns false
/// (nothing appended) when fewer than 3 points remain: degenerate, for append_hull().
inline bool append_convex_cycle(std::span<const V> cycle, std::vector<V>& out) {
  const std::size_t n = cycle.size();
  std::size_t s = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (cycle[i].x() < cycle[s].x() || (cycle[i].x() == cycle[s].x() && cycle[i].y() < cycle[s].y())) s = i;
  const std::size_t start = out.size();
  out.resize(start + n + 1);
  V* h = out.data() + start;
  std::size_t k = 0;
  for (std::size_t t = 0; t <= n; ++t) {
    const V& p = cycle[(s + t) % n];
    if (k >= 1 && p == h[k - 1]) continue;
    while (k >= 2 && cross(h[k - 1] - h[k - 2], p - h[k - 2]) <= 0) --k;
    h[k++] = p;
  }
  if (k < 4 || h[k - 1] != h[0]) {  // the start must close the cycle, with 3 points or more before it
    out.resize(start);
    return false;
  }
  out.resize(start + k - 1);
  return true;
}

/// The hull of p as a new vector.
inline std::vector<V> hull(std::vector<V> p) {
  std::vector<V> h;
  append_hull(p, h);
  return h;
}

/// Appends to `out` the Minkowski sum f (+) (-m) of two convex polygons given counter-clockwise
/// without collinear points (append_hull() output: 1 or 2 points for a point or a segment), by the
/// O(n + m) merge of their edges by angle (paper 004: the wrapper has as many edges as both
/// together). Each vertex is computed as f_i - m_j, and the result is the one append_hull() would
/// give for every difference: the same points, collinear ones dropped, starting from the lowest
/// (x, y). `sum` is scratch.
inline void append_minkowski_difference(std::span<const V> f, std::span<const V> m, std::vector<V>& sum, std::vector<V>& out) {
  const std::size_t nf = f.size(), nm = m.size();
  // -m is counter-clockwise too (a point reflection is a rotation by 180 degrees).
  auto lowest = [](std::span<const V> p, double sign) {
    std::size_t k = 0;
    for (std::size_t i = 1; i < p.size(); ++i) {
      const V a = sign * p[i], b = sign * p[k];
      if (a.y() < b.y() || (a.y() == b.y() && a.x() < b.x())) k = i;
    }
    return k;
  };
  const std::size_t i0 = lowest(f, 1), j0 = lowest(m, -1);
  sum.clear();
  std::size_t i = 0, j = 0;
  const auto next = [](std::size_t k, std::size_t n) { return k + 1 == n ? 0 : k + 1; };
  std::size_t a = i0, b = j0;  // the current vertices: f[(i0 + i) % nf], m[(j0 + j) % nm]
  while (i < nf || j < nm) {
    sum.push_back(f[a] - m[b]);
    // The edge with the smaller direction angle goes first (angles grow from 0 to 2 pi from the
    // lowest vertex; a segment's two edges are antiparallel, which a cross product alone would
    // take for parallel).
    const bool f_left = i < nf && nf > 1, m_left = j < nm && nm > 1;  // edges still to take
    bool step_f, step_m;
    if (f_left && m_left) {
      // Whether one direction comes before the other in angle, from 0 to 2 pi (the x axis
      // first): exact (the half-plane, then the sign of the cross product), without
      // trigonometry. Equal directions step both (both edges are taken at once).
      const V ef = f[next(a, nf)] - f[a];
      const V em = m[b] - m[next(b, nm)];  // an edge of -m
      const bool uf = upper(ef), um = upper(em);
      const double c = cross(ef, em);
      step_f = uf != um ? uf : c >= 0;
      step_m = uf != um ? um : -c >= 0;  // cross(em, ef) = -c exactly
    } else {
      step_f = i < nf && (!m_left || nm == 1 || j >= nm);
      step_m = j < nm && (!f_left || nf == 1 || i >= nf);
    }
    if (step_f) ++i, a = next(a, nf);
    if (step_m) ++j, b = next(b, nm);
  }
  // Drops collinear points and fixes the start: in one pass for polygons, by sorting otherwise.
  if (nf < 3 || nm < 3 || !append_convex_cycle(sum, out)) append_hull(sum, out);
}

/// Signed distance from x to the convex hull q (counter-clockwise; 1 or 2 points allowed), whose
/// edge i (q[i] -> q[i + 1]) has the outward unit normal normals[i] (3 points or more).
inline double signed_distance(std::span<const V> q, std::span<const V> normals, const V& x) {
  const auto to_segment = [&](const V& a, const V& b) {
    const V d = b - a;
    const double t = std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (x - a - t * d).norm();
  };
  if (q.size() == 1) return (x - q[0]).norm();
  if (q.size() == 2) return to_segment(q[0], q[1]);
  double inside = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < q.size(); ++i) inside = std::max(inside, normals[i].dot(x - q[i]));
  if (inside <= 0) return inside;
  // Outside: the nearest point is on an edge that x sees (of a vertex's two edges, x lies
  // beyond at least one's line), so the others are skipped.
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < q.size(); ++i)
    if (normals[i].dot(x - q[i]) > 0) d = std::min(d, to_segment(q[i], q[(i + 1) % q.size()]));
  return d;
}

/// The nearest points of two disjoint convex polygons, vertices in order, and their distance:
/// a vertex of one and a point on an edge of the other.
inline double apart_nearest(std::span<const V> a, std::span<const V> b, V& on_a, V& on_b) {
  double d2 = std::numeric_limits<double>::infinity();
  // Vertices of `from` against the edges of `poly`; `swap`: from is b.
  const auto vertices_to_edges = [&](std::span<const V> from, std::span<const V> poly, bool swap) {
    for (const V& p : from)
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const V e = poly[(i + 1) % poly.size()] - poly[i];
        const double t = std::clamp((p - poly[i]).dot(e) / e.squaredNorm(), 0.0, 1.0);
        const V q = poly[i] + t * e;
        if (const double s = (p - q).squaredNorm(); s < d2) {
          d2 = s;
          on_a = swap ? q : p, on_b = swap ? p : q;
        }
      }
  };
  vertices_to_edges(a, b, false);
  vertices_to_edges(b, a, true);
  return std::sqrt(d2);
}

/// Distance between two disjoint convex polygons, vertices in order.
inline double apart_distance(std::span<const V> a, std::span<const V> b) {
  V on_a, on_b;
  return apart_nearest(a, b, on_a, on_b);
}

}  // namespace fp::convex_polygon
