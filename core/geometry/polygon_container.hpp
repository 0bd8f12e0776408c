#pragma once
// Simple polygon (2D), convex or not. Walls: the edges (as lines) and the reflex corners
// (as Vertex walls), since a disk can touch a corner that points into the container.
// Queries go through a tree over the edges (edge_chain_tree.hpp): about log n per query on a
// reasonable polygon, with the same doubles as the loops over every edge.
#include <array>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/edge_chain_tree.hpp"

namespace fp {

class PolygonContainer final : public Container<2> {
 public:
  /// `vertices` in either orientation (stored counter-clockwise). Throws std::invalid_argument
  /// for fewer than 3 vertices, non-finite or repeated points, zero area, or a self-intersecting
  /// boundary (including an edge that doubles back on its neighbour).
  /// `vertices` are absolute; the polygon is stored relative to `origin` (its local frame).
  explicit PolygonContainer(std::vector<Vec2> vertices, const Vec2& origin = Vec2::Zero());

  /// Closed: points on the boundary are inside.
  bool inside(const Vec2& p) const override;
  /// Exact: minimum distance to the edges, sign by the winding number.
  double signed_distance(const Vec2& p) const override;
  Aabb<2> bounds() const override { return tree_.bounds(); }
  double measure() const override { return area_; }
  /// Wall ids: edge i (from vertex i to i+1) is id i, a Plane through vertex i with inward
  /// normal; reflex vertex i is id n + i, a Vertex wall. Returned when the distance from p to
  /// the edge segment (or to the vertex) is <= reach: edges by increasing id, then corners.
  void walls_near(const Vec2& p, double reach, std::vector<Wall<2>>& out) const override;
  /// A deep inside point (grid search + local polish), computed once in the constructor.
  Vec2 interior_point() const override { return interior_; }
  std::string describe() const override;
  /// The default's answer (signed_distance(c) <= -r + rel_tol r), without finding the nearest
  /// edge: any edge closer than the clearance decides.
  bool contains_ball(const Vec2& c, double r, double rel_tol = 1e-9) const override;

  /// Counter-clockwise vertices, in the local frame.
  const std::vector<Vec2>& vertices() const { return tree_.vertices(); }
  /// True if the interior angle at vertex i exceeds 180 degrees.
  bool is_reflex(int i) const { return reflex_[i] != 0; }

 private:
  /// Winding-number inside test; *on_boundary set when p is on an edge.
  bool locate(const Vec2& p, bool* on_boundary) const;

  EdgeChainTree tree_;
  std::vector<Vec2> inward_;  ///< unit inward normal of edge i
  std::vector<std::array<FaceEdge<2>, 2>> ends_;  ///< edge i as a bounded wall: its two end points
  std::vector<char> reflex_;
  double area_ = 0.0;
  Vec2 interior_ = Vec2::Zero();
};

}  // namespace fp
