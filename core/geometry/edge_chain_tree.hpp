#pragma once
// A bounding-volume hierarchy over the edges of a closed polygonal chain (edge i runs from vertex
// i to vertex i+1 mod n), for polygon containers with many vertices. A node is a run of
// consecutive edges; it is bounded by the box of its vertices and by a box aligned with its chord
// (the segment from its first to its last vertex). On a smooth boundary, and on one with teeth,
// the aligned box's slack on the inner side is the sagitta, which shrinks with the square of the
// run's length, the axis-aligned box's only linearly: what keeps deep queries (a point near the
// centre of a fine regular n-gon is almost equidistant from every edge) from opening most leaves.
//
// The queries reproduce the loops over all edges double for double: a node is skipped only when
// its bound exceeds the threshold by far more than the rounding of any distance computed inside
// it (kSlackRel, kSlackAbs), so every edge that could decide the result is evaluated with the
// same expression as the loop. Nothing assumes where the coordinates are (any local frame).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

/// Squared distance from p to the segment [a, b] (a != b): the one expression every polygon query
/// uses, so that indexed and brute-force answers are the same doubles.
inline double segment_distance2(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double t = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (p - a - t * e).squaredNorm();
}

class EdgeChainTree {
 public:
  /// Edges per leaf: enough to amortise the bounds of a node, few enough to prune well.
  static constexpr int kLeafEdges = 8;
  /// A node is skipped only if its bound exceeds the threshold by this relative margin plus
  /// kSlackAbs times the chain's bounding-box diagonal: rounding in the distances and bounds is
  /// about 1e-15 of the same quantities.
  static constexpr double kSlackRel = 1e-12;
  static constexpr double kSlackAbs = 1e-12;

  EdgeChainTree() = default;
  /// `vertices`: at least 2 points of the closed chain, consecutive ones distinct. O(n).
  explicit EdgeChainTree(std::vector<Vec2> vertices);

  const std::vector<Vec2>& vertices() const { return v_; }
  int size() const { return static_cast<int>(v_.size()); }
  const Vec2& a(int i) const { return v_[static_cast<std::size_t>(i)]; }
  const Vec2& b(int i) const { return v_[static_cast<std::size_t>(i + 1 == size() ? 0 : i + 1)]; }

  /// min over all edges of segment_distance2(p, a(i), b(i)); +inf if p is not finite enough to
  /// compare (as the loop's std::min gives).
  double min_distance2(const Vec2& p) const;

  /// True if some edge i has std::sqrt(segment_distance2(p, a(i), b(i))) < radius. Stops at the
  /// first one found.
  bool any_edge_closer_than(const Vec2& p, double radius) const;

  /// Calls f(i), in increasing i, for a superset of the edges whose distance to p is <= radius
  /// (the caller applies its own exact test): the edges of every leaf within reach.
  template <class F>
  void for_each_edge_near(const Vec2& p, double radius, F&& f) const;

  /// Sunday's winding number of p, split: calls f(i) for the edges whose term the caller computes
  /// (every edge that meets p's height within ray_margin() of p.x(), and maybe more), and returns
  /// the sum of the terms of all other edges: +1 for an edge going up across p's height
  /// (ay <= py < by) right of p, -1 going down (by <= py < ay) right of p, 0 otherwise, summed over
  /// a run as [first vertex's y <= py] - [last vertex's y <= py]. The .cpp says why that is the
  /// very sum the floating-point loop over every edge finds.
  template <class F>
  int winding_beyond(const Vec2& p, F&& f) const;

  /// Calls f(i, j), i < j, for a superset of the pairs of non-adjacent edges whose closed boxes
  /// overlap, by increasing i; stops when f returns true. For naming crossing edges.
  template <class F>
  bool any_overlapping_pair(F&& f) const;

  /// Bounding box of the vertices.
  const Aabb<2>& bounds() const { return box_; }

 private:
  struct Node {
    Vec2 lo, hi;        ///< box of the run's vertices
    Vec2 ca, cb;        ///< first and last vertex of the run (the chord)
    Vec2 u;             ///< unit vector along the chord (x if the run is closed)
    Vec2 t_range;       ///< the run's extent along u, from ca ...
    Vec2 s_range;       ///< ... and along u turned left
    int first = 0;      ///< first edge of the run
    int count = 0;      ///< number of edges
    int right = -1;     ///< index of the right child (the left one is the next node); -1 for a leaf
  };

  int build(int first, int count);
  /// A lower bound on the distance from p to the node's edges (up to the slack).
  double lower_bound(const Node& node, const Vec2& p) const;
  /// Threshold `limit` widened by the slack: nodes whose lower bound exceeds it are skipped.
  double widened(double limit) const { return limit * (1.0 + kSlackRel) + slack_abs_; }
  double ray_margin() const { return slack_abs_; }
  /// Where the run can meet the line y = p.y(): -1 only left of p.x() - ray_margin(), +1 only
  /// right of p.x() + ray_margin() (or nowhere), 0 undecided.
  int side_at_height(const Node& node, const Vec2& p) const;

  std::vector<Vec2> v_;
  std::vector<Node> nodes_;
  Aabb<2> box_;
  double slack_abs_ = 0.0;
};

template <class F>
void EdgeChainTree::for_each_edge_near(const Vec2& p, double radius, F&& f) const {
  if (nodes_.empty()) return;
  const double limit = widened(radius);
  std::array<int, 64> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
    if (!(lower_bound(node, p) <= limit)) continue;
    if (node.right < 0) {
      for (int i = node.first; i < node.first + node.count; ++i) f(i);
      continue;
    }
    stack[top++] = node.right;  // left child on top: edges come out in increasing order
    stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
  }
}

template <class F>
int EdgeChainTree::winding_beyond(const Vec2& p, F&& f) const {
  if (nodes_.empty()) return 0;
  int winding = 0;
  std::array<int, 64> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
    if (!(node.lo.y() <= p.y() && p.y() <= node.hi.y())) continue;  // off p's height: all terms 0
    const int side = side_at_height(node, p);
    if (side < 0) continue;  // meets p's height left of p only: all terms 0
    if (side > 0) {          // right of p only: the terms telescope
      winding += (node.ca.y() <= p.y() ? 1 : 0) - (node.cb.y() <= p.y() ? 1 : 0);
      continue;
    }
    if (node.right < 0) {
      for (int i = node.first; i < node.first + node.count; ++i) f(i);
      continue;
    }
    stack[top++] = node.right;
    stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
  }
  return winding;
}

template <class F>
bool EdgeChainTree::any_overlapping_pair(F&& f) const {
  const int n = size();
  std::array<int, 64> stack;
  for (int i = 0; i < n; ++i) {
    const Vec2 lo = a(i).cwiseMin(b(i)), hi = a(i).cwiseMax(b(i));
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
      if (node.first + node.count <= i + 1) continue;  // only partners j > i + 1
      if (!((node.lo.array() <= hi.array()).all() && (lo.array() <= node.hi.array()).all())) continue;
      if (node.right < 0) {
        for (int j = std::max(node.first, i + 2); j < node.first + node.count; ++j) {
          if (i == 0 && j == n - 1) continue;  // adjacent through vertex 0
          if (f(i, j)) return true;
        }
        continue;
      }
      stack[top++] = node.right;
      stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
    }
  }
  return false;
}

}  // namespace fp
