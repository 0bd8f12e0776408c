#include "core/geometry/polygon_container.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/geometry/container_checks.hpp"
#include "core/geometry/deepest_point.hpp"

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

double segment_distance2(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double t = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (p - a - t * e).squaredNorm();
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
  // Non-adjacent edges must not meet: sweep over x so that only overlapping x-ranges are tested.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto xmin = [&](int e) { return std::min(v[e].x(), v[(e + 1) % n].x()); };
  auto xmax = [&](int e) { return std::max(v[e].x(), v[(e + 1) % n].x()); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return xmin(a) < xmin(b) || (xmin(a) == xmin(b) && a < b); });
  for (int k = 0; k < n; ++k) {
    const int e = order[k];
    const double right = xmax(e);
    for (int m = k + 1; m < n && xmin(order[m]) <= right; ++m) {
      const int f = order[m];
      const int d = std::abs(e - f);
      if (d == 1 || d == n - 1) continue;  // adjacent, handled above
      if (segments_meet(v[e], v[(e + 1) % n], v[f], v[(f + 1) % n]))
        throw std::invalid_argument("PolygonContainer: vertices: edges " + std::to_string(std::min(e, f)) + " and " +
                                    std::to_string(std::max(e, f)) + " intersect (self-intersecting polygon)");
    }
  }
}

}  // namespace

PolygonContainer::PolygonContainer(std::vector<Vec2> vertices, const Vec2& origin)
    : Container<2>(origin), v_(std::move(vertices)) {
  detail::require_finite<2>(origin, "PolygonContainer", "origin");
  for (Vec2& p : v_) p -= origin;
  const int n = static_cast<int>(v_.size());
  if (n < 3)
    throw std::invalid_argument("PolygonContainer: vertices: need at least 3, got " + std::to_string(n));
  for (int i = 0; i < n; ++i) {
    if (!v_[i].allFinite())
      throw std::invalid_argument("PolygonContainer: vertices: vertex " + std::to_string(i) + " is not finite: " +
                                  detail::format_vec<2>(Vec2(v_[i] + origin)));
    box_.extend(v_[i]);
  }
  {
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    auto less = [&](int a, int b) {
      return v_[a].x() < v_[b].x() || (v_[a].x() == v_[b].x() && (v_[a].y() < v_[b].y() || (v_[a].y() == v_[b].y() && a < b)));
    };
    std::sort(order.begin(), order.end(), less);
    for (int k = 1; k < n; ++k)
      if (v_[order[k]] == v_[order[k - 1]])
        throw std::invalid_argument("PolygonContainer: vertices: vertices " + std::to_string(order[k - 1]) + " and " +
                                    std::to_string(order[k]) + " are the same point " +
                                    detail::format_vec<2>(Vec2(v_[order[k]] + origin)));
  }
  double twice_area = 0.0;
  const Vec2 o = box_.center();  // shoelace about the centre: less cancellation far from the origin
  for (int i = 0; i < n; ++i) {
    const Vec2 a = v_[i] - o, b = v_[(i + 1) % n] - o;
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  const double diag2 = box_.size().squaredNorm();
  const bool flat = !(std::abs(twice_area) > 1e-12 * diag2);
  if (flat) {
    // All on one line? Then say so; otherwise the simplicity check names the crossing edges
    // (a symmetric bow-tie also has zero signed area).
    int far = 1;
    for (int i = 2; i < n; ++i)
      if ((v_[i] - v_[0]).squaredNorm() > (v_[far] - v_[0]).squaredNorm()) far = i;
    bool on_line = true;
    for (int i = 1; i < n; ++i) on_line = on_line && std::abs(orient(v_[0], v_[far], v_[i])) <= 1e-12 * diag2;
    if (on_line) throw std::invalid_argument("PolygonContainer: vertices: zero area (all points on one line)");
  }
  check_simple(v_);
  if (flat) throw std::invalid_argument("PolygonContainer: vertices: zero area");
  if (twice_area < 0.0) std::reverse(v_.begin(), v_.end());
  area_ = 0.5 * std::abs(twice_area);

  inward_.resize(n);
  reflex_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Vec2 e = (v_[(i + 1) % n] - v_[i]).normalized();
    inward_[i] = Vec2(-e.y(), e.x());  // left of a counter-clockwise edge
    reflex_[i] = orient(v_[(i + n - 1) % n], v_[i], v_[(i + 1) % n]) < 0.0;
  }

  std::vector<Vec2> candidates;
  candidates.reserve(n);
  for (int i = 0; i < n; ++i) {
    const Vec2 a = v_[i], b = v_[(i + 1) % n];
    candidates.push_back(0.5 * (a + b) + 1e-3 * (b - a).norm() * inward_[i]);
  }
  interior_ = detail::deepest_point<2>(*this, 32, candidates, 1e-4);
}

bool PolygonContainer::locate(const Vec2& p, double* dist2) const {
  const int n = static_cast<int>(v_.size());
  int winding = 0;
  bool on_boundary = false;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const Vec2& a = v_[i];
    const Vec2& b = v_[i + 1 == n ? 0 : i + 1];
    if (dist2) best = std::min(best, segment_distance2(p, a, b));
    // Sunday's winding number: upward edges crossing the ray to +x with p on their left count +1.
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
  }
  if (dist2) *dist2 = on_boundary ? 0.0 : best;
  return on_boundary || winding != 0;
}

bool PolygonContainer::inside(const Vec2& p) const {
  return locate(p, nullptr);
}

double PolygonContainer::signed_distance(const Vec2& p) const {
  double d2;
  const bool in = locate(p, &d2);
  const double d = std::sqrt(d2);
  return in ? -d : d;
}

void PolygonContainer::walls_near(const Vec2& p, double reach, std::vector<Wall<2>>& out) const {
  const int n = static_cast<int>(v_.size());
  const double reach2 = reach * reach;
  for (int i = 0; i < n; ++i) {
    const Vec2& a = v_[i];
    const Vec2& b = v_[i + 1 == n ? 0 : i + 1];
    if (segment_distance2(p, a, b) <= reach2) out.push_back(Wall<2>::plane(a, inward_[i], i));
  }
  for (int i = 0; i < n; ++i)
    if (reflex_[i] && (p - v_[i]).squaredNorm() <= reach2) out.push_back(Wall<2>::vertex(v_[i], n + i));
}

std::string PolygonContainer::describe() const {
  return "polygon (" + std::to_string(v_.size()) + " vertices, area " + detail::format_short(area_) + ")";
}

}  // namespace fp
