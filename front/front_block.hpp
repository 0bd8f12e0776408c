#pragma once
// One block of a container decomposed for parallel growth (front/block_front.hpp): the front
// places centres inside `box` only. The `fixed` particles, placed around the box before by the
// blocks of earlier phases, are obstacles, contact bodies and the front the block grows from;
// they are not part of the block's result.
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D, class Draft>
struct FrontBlock {
  Aabb<D> box;                         ///< the block
  /// Where its new centres may lie (closed): the box, reaching into the neighbours that have
  /// grown, where pockets of their faces are filled (their particles' centres stop at their face).
  Aabb<D> reach;
  double halo = 0.0;                   ///< fixed centres lie within this distance of `reach`
  /// Growth is ordered by the distance to this point (the single front's seed point): outside
  /// the box, beyond its low corner, so the front is a wide cap sweeping from the low faces, where
  /// the neighbours grew, to the high ones (front/block_front.hpp).
  Vec<D> seed_point = Vec<D>::Zero();
  std::vector<Draft> fixed_drafts;     ///< the fixed particles, as drafts ...
  std::vector<Vec<D>> fixed_positions; ///< ... and where they are
};

}  // namespace fp
