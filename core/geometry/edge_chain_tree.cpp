#include "core/geometry/edge_chain_tree.hpp"

#include <stdexcept>
#include <utility>

namespace fp {

// Why winding_beyond may sum a run whose crossings of p's height all lie left of p, or all right
// of it, by more than the margin, without looking at its edges. Sunday's loop finds p on an edge
// when orient(a, b, p) == 0 and counts an edge crossing p's height by the sign of
// orient(a, b, p) = (bx - ax)(py - ay) - (by - ay)(px - ax). For an edge crossing p's height at
// x = xc (dy = by - ay != 0), the exact value is -dy (px - xc), and |py - ay| <= |dy|,
// |px - ax| <= |bx - ax| + |px - xc|, so the sum of the magnitudes of the two products is at most
// |dy| (2 |bx - ax| + |px - xc|). Shewchuk's bound for this evaluation (ccwerrboundA, about
// 3.3e-16 of that sum: "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates", 1997) then says the computed sign is the exact one once |px - xc| > 1e-15 |bx - ax|,
// far below the margin (1e-12 of the diagonal): such an edge counts exactly its crossing number,
// 0 left of p, +1 (up) or -1 (down) right of it, and never finds p on it. An edge that does not
// cross p's height counts 0, and a horizontal one at it counts 0 unless p is on it. Per edge the
// crossing number right of p is [ay <= py] - [by <= py]; along a run the sum telescopes.
// (No underflow assumed: coordinates of the container's size, not 1e-150.)

EdgeChainTree::EdgeChainTree(std::vector<Vec2> vertices) : v_(std::move(vertices)) {
  if (v_.size() < 2) throw std::invalid_argument("EdgeChainTree: need at least 2 vertices");
  if (v_.size() > static_cast<std::size_t>(std::numeric_limits<int>::max() / 2))
    throw std::invalid_argument("EdgeChainTree: too many vertices");
  for (const Vec2& p : v_) box_.extend(p);
  slack_abs_ = kSlackAbs * box_.size().norm();
  const int leaves = (size() + kLeafEdges - 1) / kLeafEdges;
  nodes_.reserve(static_cast<std::size_t>(2 * leaves));
  build(0, size());
}

namespace {

Vec2 left_of(const Vec2& u) { return Vec2(-u.y(), u.x()); }

/// Extends the run's extents along u and its left normal by point q.
void extend(Vec2& t_range, Vec2& s_range, const Vec2& origin, const Vec2& u, const Vec2& q) {
  const Vec2 d = q - origin;
  const double t = d.dot(u), s = d.dot(left_of(u));
  t_range = Vec2(std::min(t_range[0], t), std::max(t_range[1], t));
  s_range = Vec2(std::min(s_range[0], s), std::max(s_range[1], s));
}

}  // namespace

// Preorder layout: a node's left child follows it, so a subtree is one contiguous block.
int EdgeChainTree::build(int first, int count) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.first = first;
  node.count = count;
  node.ca = a(first);
  node.cb = b(first + count - 1);
  node.u = node.ca == node.cb ? Vec2(1, 0) : Vec2((node.cb - node.ca).normalized());
  node.t_range = node.s_range = Vec2::Zero();  // ca itself
  if (count <= kLeafEdges) {
    node.lo = node.hi = node.ca;
    for (int i = first; i < first + count; ++i) {
      node.lo = node.lo.cwiseMin(b(i));
      node.hi = node.hi.cwiseMax(b(i));
      extend(node.t_range, node.s_range, node.ca, node.u, b(i));
    }
  } else {
    // Split on a leaf boundary, halves of (nearly) equal leaf counts: depth log2(n / kLeafEdges).
    const int leaves = (count + kLeafEdges - 1) / kLeafEdges;
    const int left_count = (leaves / 2) * kLeafEdges;
    build(first, left_count);
    node.right = build(first + left_count, count - left_count);
    const Node& l = nodes_[static_cast<std::size_t>(index) + 1];
    const Node& r = nodes_[static_cast<std::size_t>(node.right)];
    node.lo = l.lo.cwiseMin(r.lo);
    node.hi = l.hi.cwiseMax(r.hi);
    // The children's aligned boxes hold their runs, so their corners bound the parent's extents
    // (O(1) a node; looser than the vertices by the children's turn, which is small on a smooth run).
    for (const Node* c : {&l, &r})
      for (const double t : {c->t_range[0], c->t_range[1]})
        for (const double s : {c->s_range[0], c->s_range[1]})
          extend(node.t_range, node.s_range, node.ca, node.u, c->ca + t * c->u + s * left_of(c->u));
  }
  nodes_[static_cast<std::size_t>(index)] = node;
  return index;
}

double EdgeChainTree::lower_bound(const Node& node, const Vec2& p) const {
  const double gx = std::max({node.lo.x() - p.x(), p.x() - node.hi.x(), 0.0});
  const double gy = std::max({node.lo.y() - p.y(), p.y() - node.hi.y(), 0.0});
  const Vec2 d = p - node.ca;
  const double t = d.dot(node.u), s = d.dot(left_of(node.u));
  const double gt = std::max({node.t_range[0] - t, t - node.t_range[1], 0.0});
  const double gs = std::max({node.s_range[0] - s, s - node.s_range[1], 0.0});
  return std::sqrt(std::max(gx * gx + gy * gy, gt * gt + gs * gs));
}

int EdgeChainTree::side_at_height(const Node& node, const Vec2& p) const {
  const double m = ray_margin();
  if (node.hi.x() < p.x() - m) return -1;
  if (node.lo.x() > p.x() + m) return 1;
  // The aligned box on the line, as offsets xi = x - ca.x: t = xi ux + eta uy in t_range and
  // s = -xi uy + eta ux in s_range. Each bound is widened far beyond its rounding.
  const double eta = p.y() - node.ca.y(), delta = p.x() - node.ca.x();
  const double scale = std::abs(node.t_range[0]) + std::abs(node.t_range[1]) + std::abs(node.s_range[0]) +
                       std::abs(node.s_range[1]) + std::abs(eta) + std::abs(delta);
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  auto clip = [&](double coef, double offset, const Vec2& range) {  // coef xi + offset in range
    if (std::abs(coef) < 0.1) return;  // nearly parallel to the line: the other side bounds it
    double a = (range[0] - offset) / coef, b = (range[1] - offset) / coef;
    if (coef < 0) std::swap(a, b);
    const double widen = 1e-12 * scale / std::abs(coef);
    lo = std::max(lo, a - widen);
    hi = std::min(hi, b + widen);
  };
  clip(node.u.x(), eta * node.u.y(), node.t_range);
  clip(-node.u.y(), eta * node.u.x(), node.s_range);
  if (hi < delta - m) return -1;
  if (lo > delta + m) return 1;
  return 0;
}

double EdgeChainTree::min_distance2(const Vec2& p) const {
  double best = std::numeric_limits<double>::infinity();
  if (nodes_.empty()) return best;
  double limit = std::numeric_limits<double>::infinity();
  // Depth first, nearer child first, so that a close edge is found early and prunes the rest.
  std::array<std::pair<int, double>, 64> stack;
  int top = 0;
  stack[top++] = {0, lower_bound(nodes_[0], p)};
  while (top > 0) {
    const auto [k, bound] = stack[--top];
    if (!(bound <= limit)) continue;
    const Node& node = nodes_[static_cast<std::size_t>(k)];
    if (node.right < 0) {
      for (int i = node.first; i < node.first + node.count; ++i) best = std::min(best, segment_distance2(p, a(i), b(i)));
      limit = widened(std::sqrt(best));
      continue;
    }
    const int l = k + 1, r = node.right;
    const double bl = lower_bound(nodes_[static_cast<std::size_t>(l)], p);
    const double br = lower_bound(nodes_[static_cast<std::size_t>(r)], p);
    if (bl <= br) {
      stack[top++] = {r, br};
      stack[top++] = {l, bl};
    } else {
      stack[top++] = {l, bl};
      stack[top++] = {r, br};
    }
  }
  return best;
}

bool EdgeChainTree::any_edge_closer_than(const Vec2& p, double radius) const {
  bool found = false;
  // for_each_edge_near has no early exit; this one stops at the first hit.
  if (nodes_.empty()) return false;
  const double limit = widened(radius);
  std::array<int, 64> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0 && !found) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
    if (!(lower_bound(node, p) <= limit)) continue;
    if (node.right < 0) {
      for (int i = node.first; i < node.first + node.count && !found; ++i)
        found = std::sqrt(segment_distance2(p, a(i), b(i))) < radius;
      continue;
    }
    stack[top++] = node.right;
    stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
  }
  return found;
}

}  // namespace fp
