#include "core/geometry/polygon_container.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/geometry/container_checks.hpp"
#include "core/geometry/deepest_point.hpp"
#include "core/geometry/polygon_cgal.hpp"

namespace fp {
namespace {

/// Twice the signed area of (a, b, c): > 0 when c is left of a->b.
double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/// c is on the closed segment [a, b], given that a, b, c are collinear.
bool on_collinear_segment(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= c.y() &&
         c.y() <= std::max(a.y(), b.y());
}

/// Closed segments [p1,p2] and [q1,q2] share at least one point.
bool segments_meet(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2) {
  const double o1 = orient(p1, p2, q1), o2 = orient(p1, p2, q2);
  const double o3 = orient(q1, q2, p1), o4 = orient(q1, q2, p2);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  return (o1 == 0 && on_collinear_segment(p1, p2, q1)) || (o2 == 0 && on_collinear_segment(p1, p2, q2)) ||
         (o3 == 0 && on_collinear_segment(q1, q2, p1)) || (o4 == 0 && on_collinear_segment(q1, q2, p2));
}

void check_simple(const std::vector<Vec2>& v) {
  const int n = static_cast<int>(v.size());
  // Adjacent edges meet at their shared vertex; they are wrong only if they fold back on each other.
  for (int i = 0; i < n; ++i) {
    const Vec2& a = v[(i + n - 1) % n];
    const Vec2& b = v[i];
    const Vec2& c = v[(i + 1) % n];
    if (orient(a, b, c) == 0.0 && (b - a).dot(c - b) < 0.0)
      throw std::invalid_argument("PolygonContainer: vertices: the boundary doubles back on itself at vertex " +
                                  std::to_string(i) + " (self-intersecting)");
  }
  // Non-adjacent edges must not meet: a sweep with exact predicates, O(n log n) in every case.
  if (detail::is_simple_polygon(v)) return;
  // Rejected: name two edges that meet (the search by boxes is fast on any reasonable polygon).
  const EdgeChainTree tree(v);
  int e = -1, f = -1;
  tree.any_overlapping_pair([&](int i, int j) {
    if (!segments_meet(tree.a(i), tree.b(i), tree.a(j), tree.b(j))) return false;
    e = i, f = j;
    return true;
  });
  if (e >= 0)
    throw std::invalid_argument("PolygonContainer: vertices: edges " + std::to_string(e) + " and " + std::to_string(f) +
                                " intersect (self-intersecting polygon)");
  // The crossing is below the rounding of the floating-point test (nearly collinear edges).
  throw std::invalid_argument("PolygonContainer: vertices: two edges touch (self-intersecting polygon)");
}

}  // namespace

PolygonContainer::PolygonContainer(std::vector<Vec2> vertices, const Vec2& origin) : Container<2>(origin) {
  std::vector<Vec2>& v = vertices;
  detail::require_finite<2>(origin, "PolygonContainer", "origin");
  for (Vec2& p : v) p -= origin;
  const int n = static_cast<int>(v.size());
  if (n < 3)
    throw std::invalid_argument("PolygonContainer: vertices: need at least 3, got " + std::to_string(n));
  Aabb<2> box;
  for (int i = 0; i < n; ++i) {
    if (!v[i].allFinite())
      throw std::invalid_argument("PolygonContainer: vertices: vertex " + std::to_string(i) + " is not finite: " +
                                  detail::format_vec<2>(Vec2(v[i] + origin)));
    box.extend(v[i]);
  }
  {
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    auto less = [&](int a, int b) {
      return v[a].x() < v[b].x() || (v[a].x() == v[b].x() && (v[a].y() < v[b].y() || (v[a].y() == v[b].y() && a < b)));
    };
    std::sort(order.begin(), order.end(), less);
    for (int k = 1; k < n; ++k)
      if (v[order[k]] == v[order[k - 1]])
        throw std::invalid_argument("PolygonContainer: vertices: vertices " + std::to_string(order[k - 1]) + " and " +
                                    std::to_string(order[k]) + " are the same point " +
                                    detail::format_vec<2>(Vec2(v[order[k]] + origin)));
  }
  double twice_area = 0.0;
  const Vec2 o = box.center();  // shoelace about the centre: less cancellation far from the origin
  for (int i = 0; i < n; ++i) {
    const Vec2 a = v[i] - o, b = v[(i + 1) % n] - o;
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  const double diag2 = box.size().squaredNorm();
  const bool flat = !(std::abs(twice_area) > 1e-12 * diag2);
  if (flat) {
    // All on one line? Then say so; otherwise the simplicity check names the crossing edges
    // (a symmetric bow-tie also has zero signed area).
    int far = 1;
    for (int i = 2; i < n; ++i)
      if ((v[i] - v[0]).squaredNorm() > (v[far] - v[0]).squaredNorm()) far = i;
    bool on_line = true;
    for (int i = 1; i < n; ++i) on_line = on_line && std::abs(orient(v[0], v[far], v[i])) <= 1e-12 * diag2;
    if (on_line) throw std::invalid_argument("PolygonContainer: vertices: zero area (all points on one line)");
  }
  check_simple(v);
  if (flat) throw std::invalid_argument("PolygonContainer: vertices: zero area");
  if (twice_area < 0.0) std::reverse(v.begin(), v.end());
  area_ = 0.5 * std::abs(twice_area);
  tree_ = EdgeChainTree(std::move(v));

  const std::vector<Vec2>& w = tree_.vertices();
  inward_.resize(n);
  ends_.resize(n);
  reflex_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Vec2 e = (w[(i + 1) % n] - w[i]).normalized();
    inward_[i] = Vec2(-e.y(), e.x());  // left of a counter-clockwise edge
    ends_[i] = {FaceEdge<2>{e, e.dot(w[(i + 1) % n]), w[i]}, FaceEdge<2>{-e, -e.dot(w[i]), w[(i + 1) % n]}};
    reflex_[i] = orient(w[(i + n - 1) % n], w[i], w[(i + 1) % n]) < 0.0;
  }

  std::vector<Vec2> candidates;
  candidates.reserve(n);
  for (int i = 0; i < n; ++i) {
    const Vec2 a = w[i], b = w[(i + 1) % n];
    candidates.push_back(0.5 * (a + b) + 1e-3 * (b - a).norm() * inward_[i]);
  }
  interior_ = detail::deepest_point<2>(*this, 32, candidates, 1e-4);
}

bool PolygonContainer::locate(const Vec2& p, bool* on_boundary_out) const {
  int winding = 0;
  bool on_boundary = false;
  // Sunday's winding number: upward edges crossing the ray to +x with p on their left count +1.
  // The tree sums the runs of edges that lie clear of p; the edges near p are counted here.
  const int beyond = tree_.winding_beyond(p, [&](int i) {
    const Vec2& a = tree_.a(i);
    const Vec2& b = tree_.b(i);
    if (a.y() <= p.y()) {
      if (b.y() > p.y()) {
        const double o = orient(a, b, p);
        if (o > 0) ++winding;
        else if (o == 0) on_boundary = true;
      } else if (b.y() == p.y() && orient(a, b, p) == 0 && on_collinear_segment(a, b, p)) {
        on_boundary = true;  // horizontal edge or a vertex at p's height
      }
    } else if (b.y() <= p.y()) {
      const double o = orient(a, b, p);
      if (o < 0) --winding;
      else if (o == 0) on_boundary = true;
    }
  });
  *on_boundary_out = on_boundary;
  return on_boundary || winding + beyond != 0;
}

bool PolygonContainer::inside(const Vec2& p) const {
  bool on_boundary;
  return locate(p, &on_boundary);
}

double PolygonContainer::signed_distance(const Vec2& p) const {
  bool on_boundary;
  const bool in = locate(p, &on_boundary);
  const double d = std::sqrt(on_boundary ? 0.0 : tree_.min_distance2(p));
  return in ? -d : d;
}

bool PolygonContainer::contains_ball(const Vec2& c, double r, double rel_tol) const {
  const double t = -r + rel_tol * r;  // the default's threshold on the signed distance
  if (!(t < 0.0)) return signed_distance(c) <= t;
  // sqrt is monotone, so -sqrt(min d2) <= t exactly when no edge has sqrt(d2) < -t.
  if (tree_.any_edge_closer_than(c, -t)) return false;
  bool on_boundary;
  return locate(c, &on_boundary) && !on_boundary;
}

void PolygonContainer::walls_near(const Vec2& p, double reach, std::vector<Wall<2>>& out) const {
  const int n = tree_.size();
  const double reach2 = reach * reach;
  // Corner i is the start of edge i, so the edges' leaves within reach hold every corner within
  // reach. Corners go after all edges (as the loops over all edges gave them): kept aside here,
  // or found by a second pass if unusually many.
  std::array<int, 32> corners;
  int found = 0;
  tree_.for_each_edge_near(p, std::sqrt(reach2), [&](int i) {
    const Vec2& a = tree_.a(i);
    if (segment_distance2(p, a, tree_.b(i)) <= reach2) out.push_back(Wall<2>::plane(a, inward_[i], i).over(ends_[i]));
    if (reflex_[i] && (p - a).squaredNorm() <= reach2) {
      if (found < static_cast<int>(corners.size())) corners[found] = i;
      ++found;
    }
  });
  if (found <= static_cast<int>(corners.size())) {
    for (int k = 0; k < found; ++k) out.push_back(Wall<2>::vertex(tree_.a(corners[k]), n + corners[k]));
    return;
  }
  tree_.for_each_edge_near(p, std::sqrt(reach2), [&](int i) {
    if (reflex_[i] && (p - tree_.a(i)).squaredNorm() <= reach2) out.push_back(Wall<2>::vertex(tree_.a(i), n + i));
  });
}

std::string PolygonContainer::describe() const {
  return "polygon (" + std::to_string(tree_.size()) + " vertices, area " + detail::format_short(area_) + ")";
}

}  // namespace fp
