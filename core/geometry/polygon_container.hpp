#pragma once
// Simple polygon (2D), convex or not. Walls: the edges (as lines) and the reflex corners
// (as Vertex walls), since a disk can touch a corner that points into the container.
#include <vector>

#include "core/geometry/container.hpp"

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
  Aabb<2> bounds() const override { return box_; }
  double measure() const override { return area_; }
  /// Wall ids: edge i (from vertex i to i+1) is id i, a Plane through vertex i with inward
  /// normal; reflex vertex i is id n + i, a Vertex wall. Returned when the distance from p to
  /// the edge segment (or to the vertex) is <= reach.
  void walls_near(const Vec2& p, double reach, std::vector<Wall<2>>& out) const override;
  /// A deep inside point (grid search + local polish), computed once in the constructor.
  Vec2 interior_point() const override { return interior_; }
  std::string describe() const override;

  /// Counter-clockwise vertices, in the local frame.
  const std::vector<Vec2>& vertices() const { return v_; }
  /// True if the interior angle at vertex i exceeds 180 degrees.
  bool is_reflex(int i) const { return reflex_[i] != 0; }

 private:
  /// Winding-number inside test (boundary counts as inside) and squared distance to the boundary.
  bool locate(const Vec2& p, double* dist2) const;

  std::vector<Vec2> v_;
  std::vector<Vec2> inward_;  ///< unit inward normal of edge i
  std::vector<char> reflex_;
  double area_ = 0.0;
  Aabb<2> box_;
  Vec2 interior_ = Vec2::Zero();
};

}  // namespace fp
