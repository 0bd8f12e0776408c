#pragma once
// `frontpack pack` for a scene of non-spherical particles: the advancing front over shapes and
// poses, the thinning to the scene's `target:`, then the independent validation and the solvers'
// counters.
#include <optional>
#include <string>

#include "cli/pack_check.hpp"
#include "cli/target_thinning.hpp"
#include "core/io/scene.hpp"
#include "front/shape_front.hpp"

namespace fp {

class BlockExchange;

/// Resolves every template, checks that every output format can hold these shapes and that the
/// run fits the machine (core/io/scene_limits.hpp). Throws
/// SceneError (file, line, key) or std::invalid_argument; nothing has been written.
void check_shape_scene(const Scene& scene);

/// A packing of shapes and how it was made: by the front, then perhaps thinned to the target.
template <int D>
struct ShapeRun : ShapePackResult<D> {
  std::optional<TargetThinning> thinned;  ///< brought down to the scene's `target:`
};

template <int D>
struct ShapePack {
  using Result = ShapeRun<D>;
  static Result pack(const Scene& scene, const ProgressFn& progress, BlockExchange* exchange);
  static PackCheck check(const Scene& scene, const Result& result, CheckDepth depth);
  static std::string stop_text(const Result& result) {
    return std::string(to_string(result.stop)) + (result.thinned ? "; thinned to the target" : "");
  }
};

}  // namespace fp
