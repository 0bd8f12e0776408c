#pragma once
// `frontpack pack` for a scene of non-spherical particles: the advancing front over shapes and
// poses, then the independent validation and the solvers' counters.
#include <string>

#include "cli/pack_check.hpp"
#include "core/io/scene.hpp"
#include "front/shape_front.hpp"

namespace fp {

class BlockExchange;

/// Resolves every template, checks that every output format can hold these shapes and that the
/// run fits the machine (core/io/scene_limits.hpp). Throws
/// SceneError (file, line, key) or std::invalid_argument; nothing has been written.
void check_shape_scene(const Scene& scene);

template <int D>
struct ShapePack {
  using Result = ShapePackResult<D>;
  static Result pack(const Scene& scene, const ProgressFn& progress, BlockExchange* exchange);
  static PackCheck check(const Scene& scene, const Result& result, CheckDepth depth);
  static std::string stop_text(const Result& result) { return to_string(result.stop); }
};

}  // namespace fp
