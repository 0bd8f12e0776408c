#pragma once
// Entry point of the packers for a scene: picks the method and the dimension.
#include "core/io/scene.hpp"
#include "front/pack_result.hpp"

namespace fp {

/// Packs the scene's container with its size distribution (dimension D must match the scene).
template <int D>
PackResult<D> pack(const Scene& scene, const ProgressFn& progress = {});

}  // namespace fp
