#pragma once
// One block of a container decomposed for parallel growth (front/block_front.hpp): the front
// picks s0 inside `box` only and places centres in the box or within `reach` beyond it on the
// sides where a neighbour grows later (touching s0: its frozen front, which that neighbour
// resumes). The fixed particles, placed around it before by the blocks that grew earlier, are
// obstacles and contact bodies, and those in `box` the front the block resumes; they are not
// part of its result.
#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "core/geometry/vec.hpp"
#include "front/block_layout.hpp"

namespace fp {

template <int D, class Draft>
struct FrontBlock {
  Aabb<D> box;                         ///< where its s0 lie (closed)
  double reach = 0.0;                  ///< how far beyond the box its new centres may lie ...
  /// ... on the side of offset o in {-1, 0, 1}^D (index sum (o_a + 1) 3^a): true where the
  /// neighbour there grows later; the box itself (o = 0) is always open.
  std::array<bool, 27> open_side{};
  double halo = 0.0;                   ///< fixed centres lie within this distance of where it places
  /// Growth is ordered along this direction (the key of a position x is its dot product with
  /// x - box.lo): a plane sweeping from the low corner, where the neighbours grew, through the
  /// block (front/block_front.hpp).
  Vec<D> growth_direction = Vec<D>::Ones();
  std::vector<Draft> fixed_drafts;     ///< the fixed particles, as drafts ...
  std::vector<Vec<D>> fixed_positions; ///< ... and where they are

  static constexpr int kSides = D == 3 ? 27 : 9;
  static constexpr int kInside = D == 3 ? 13 : 4;  ///< the index of o = 0

  /// The part of side `s` where new centres may lie (the box itself for kInside).
  Aabb<D> side_region(int s) const {
    Aabb<D> r = box;
    for (int a = 0; a < D; ++a, s /= 3) {
      if (s % 3 == 0) r.hi[a] = box.lo[a], r.lo[a] = box.lo[a] - reach;
      if (s % 3 == 2) r.lo[a] = box.hi[a], r.hi[a] = box.hi[a] + reach;
    }
    return r;
  }
  /// Whether a new centre may lie at x.
  bool may_place(const Vec<D>& x) const {
    int s = 0;
    for (int a = D - 1; a >= 0; --a) {
      int o = 1;
      if (x[a] < box.lo[a]) {
        if (x[a] < box.lo[a] - reach) return false;
        o = 0;
      } else if (x[a] > box.hi[a]) {
        if (x[a] > box.hi[a] + reach) return false;
        o = 2;
      }
      s = 3 * s + o;
    }
    return open_side[static_cast<std::size_t>(s)];
  }
  /// Distance from p to where new centres may lie.
  double distance_to_placements(const Vec<D>& p) const {
    double d = std::numeric_limits<double>::infinity();
    for (int s = 0; s < kSides; ++s)
      if (open_side[static_cast<std::size_t>(s)]) d = std::min(d, distance_to_box(side_region(s), p));
    return d;
  }
  /// Whether a particle centred at p is within `halo` of where new centres may lie: one the
  /// block grows against. Most particles of its neighbours are farther than the halo from its
  /// box grown by its reach (which holds every side region): ruled out before the sides.
  bool fixes(const Vec<D>& p) const {
    Aabb<D> reachable = box;
    reachable.lo.array() -= reach;
    reachable.hi.array() += reach;
    return distance_to_box(reachable, p) <= halo && distance_to_placements(p) <= halo;
  }
};

}  // namespace fp
