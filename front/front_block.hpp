#pragma once
// One block of a container decomposed for parallel growth (front/block_front.hpp): the front
// places centres inside `box` only. The fixed particles, placed around it before by the blocks
// that grew earlier, are obstacles, contact bodies and the front the block grows from; they are
// not part of the block's result.
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D, class Draft>
struct FrontBlock {
  Aabb<D> box;                         ///< where its new centres lie (closed)
  double halo = 0.0;                   ///< fixed centres lie within this distance of the box
  /// Growth is ordered along this direction (the key of a position x is its dot product with
  /// x - box.lo): a plane sweeping from the low corner, where the neighbours grew, through the
  /// block (front/block_front.hpp).
  Vec<D> growth_direction = Vec<D>::Ones();
  std::vector<Draft> fixed_drafts;     ///< the fixed particles, as drafts ...
  std::vector<Vec<D>> fixed_positions; ///< ... and where they are
};

}  // namespace fp
