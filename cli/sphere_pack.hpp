#pragma once
// `frontpack pack` for a scene of spheres (disks): the advancing front over centres and radii,
// then every figure of `frontpack analyze` (the independent validation included).
#include "cli/pack_check.hpp"
#include "core/io/scene.hpp"
#include "front/pack_result.hpp"

namespace fp {

class BlockExchange;

template <int D>
struct SpherePack {
  using Result = PackResult<D>;
  static Result pack(const Scene& scene, const ProgressFn& progress, BlockExchange* exchange);
  static PackCheck check(const Scene& scene, const Result& result, CheckDepth depth);
};

}  // namespace fp
