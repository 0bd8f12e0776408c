#pragma once
// Private to the mesh container: a uniform grid over a closed triangle surface, built once for the
// scale of a scene's queries (the largest particle), so that most queries of a packing need no
// tree search (57 % of a femur packing went to the AABB tree and ray shooting).
//  * Each cell lists the facets within `margin` of it (so a point's facets within margin are all
//    in its cell's list), keeps a lower bound of its distance to the surface, and the side of a
//    sample point in it.
//  * A point in a cell no facet comes near is on that cell's side, at least that bound from the
//    surface: deep inside or outside without any distance computed.
//  * Near the surface, distances are the exact point-triangle distances over the list (the same
//    arithmetic as the tree's, so both answer alike bit for bit), and the side is the parity of
//    the crossings of the segment to the cell's sample point, decided by exact orientation
//    predicates. A segment through an edge or a vertex, or a point on a facet's plane, is left
//    to the caller's exact query (`Unknown`).
// Sides of the samples are found once, at build, by walking from the grid's padding (outside the
// surface's bounding box) across the cells, with the same crossing parity.
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp::detail {

class MeshCells {
 public:
  /// vertices and triangles in the frame of the exact queries; `solid`: per facet, non-zero area
  /// (only those are listed); cells of side `cell` list the facets within `margin` of them; `side_of`: the exact side (+1 in, 0 on, -1 out) where a crossing is
  /// degenerate. Gives up (built() false) when the grid would hold more than `max_entries` facet
  /// listings, e.g. facets far smaller than the margin by the million.
  MeshCells(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles,
            const std::vector<char>& solid, double cell, double margin, std::size_t max_cells,
            std::size_t max_entries, const std::function<int(const Vec3&)>& side_of);

  bool built() const { return built_; }
  double margin() const { return margin_; }
  std::size_t cells() const { return side_.size(); }
  std::size_t entries() const { return items_.size(); }

  /// +1 inside, -1 outside, 0 unknown (ask the exact query).
  int side(const Vec3& p) const;
  enum class Answer { No, Yes, Unknown };
  /// Is p strictly inside with no facet strictly closer than `clearance` (> 0)?
  Answer ball_inside(const Vec3& p, double clearance) const;
  /// The nearest point of the surface and its side, if the nearest facet is within the margin
  /// (then it is in p's list, and the answer is exact); side 0 when the parity cannot tell.
  bool nearest(const Vec3& p, Vec3& closest, int& side) const;
  /// A lower bound of p's distance to the surface (0 outside the grid).
  double distance_lower_bound(const Vec3& p) const;

 private:
  struct Crossings {
    int parity = 0;
    bool degenerate = false;
  };
  // The build, in order (the constructor): the grid, the facet lists, the distance bounds, the
  // samples' sides. list_facets and find_sides return false where the index gives up.
  void size_grid(const std::vector<Vec3>& vertices, double cell, std::size_t max_cells);
  bool list_facets(const std::vector<char>& solid, std::size_t max_entries, std::vector<double>& nearest2);
  void bound_distances(const std::vector<double>& nearest2);
  bool find_sides(const std::function<int(const Vec3&)>& side_of);

  long cell_of(const Vec3& p) const;  ///< -1 outside the grid
  bool listed(long cell) const;       ///< some facet comes within the margin of the cell
  std::array<long, 3> coords(long cell) const;
  Vec3 sample(long cell) const;
  /// Crossings of segment pq with the listed facets of `cell` (and of `other`'s list, without
  /// repeating those in both, when other >= 0).
  Crossings crossings(const Vec3& p, const Vec3& q, long cell, long other) const;
  int cross(const Vec3& p, const Vec3& q, int facet) const;  ///< 0 no, 1 yes, -1 degenerate
  bool listed_in_head(std::int32_t facet, long cell) const;   ///< among the facets meeting the cell's box

  bool built_ = false;
  double margin_ = 0.0, h_ = 1.0;
  /// Of a cell, widened a little: the pruning bound, and the reach from its centre of the facets
  /// that may meet its box (the head of its list).
  double half_diagonal_ = 0.0;
  Vec3 lo_ = Vec3::Zero();
  std::array<long, 3> n_{0, 0, 0};
  std::vector<std::array<Vec3, 3>> tri_;  ///< corners of each facet, in the query frame
  std::vector<std::uint32_t> start_;      ///< facets of cell c: items_[start_[c] .. start_[c + 1])
  std::vector<std::int32_t> items_;       ///< nearest to the cell's centre first (then by id)
  std::vector<float> item_distance_;      ///< per listing: the facet's distance from the centre, rounded down
  std::vector<float> lower_bound_;        ///< per cell, rounded down
  std::vector<std::int8_t> side_;         ///< per cell: side of its sample (+1 / -1)
  std::vector<std::uint8_t> nudge_;       ///< per cell: which sample point (0: the usual one)
};

}  // namespace fp::detail
