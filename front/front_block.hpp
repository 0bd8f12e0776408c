#pragma once
// One block of a container decomposed for parallel growth (front/block_front.hpp): the front
// picks s0 inside `box` only and places centres within `reach` of it (touching s0). The fixed
// particles, placed around it before by the blocks that grew earlier, are obstacles and contact
// bodies, and those in `box` the front the block resumes; they are not part of its result.
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D, class Draft>
struct FrontBlock {
  Aabb<D> box;                         ///< where its s0 lie (closed)
  double halo = 0.0;                   ///< fixed centres lie within this distance of the box
  double reach = 0.0;                  ///< new centres lie within this distance of the box (picks: in it)
  /// Growth is ordered along this direction (the key of a position x is its dot product with
  /// x - box.lo): a plane sweeping from the low corner, where the neighbours grew, through the
  /// block (front/block_front.hpp).
  Vec<D> growth_direction = Vec<D>::Ones();
  std::vector<Draft> fixed_drafts;     ///< the fixed particles, as drafts ...
  std::vector<Vec<D>> fixed_positions; ///< ... and where they are
};

}  // namespace fp
