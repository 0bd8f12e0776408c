#pragma once
// Entry point of the packers for a scene: picks the method and the dimension.
#include "core/io/scene.hpp"
#include "front/pack_result.hpp"

namespace fp {

class BlockExchange;

/// Packs the scene's container with its size distribution (dimension D must match the scene).
/// With an `exchange` of several processes (MPI ranks), they grow its blocks together
/// (front/block_front.hpp); process 0 returns the packing, the others an empty one.
template <int D>
PackResult<D> pack(const Scene& scene, const ProgressFn& progress = {}, BlockExchange* exchange = nullptr);

}  // namespace fp
