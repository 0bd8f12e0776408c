#pragma once
// `frontpack pack` for a scene of non-spherical particles: templates -> general advancing front
// -> independent validation -> outputs (shapes/io) -> summary and run record.
#include "cli/pack_command.hpp"
#include "core/io/scene.hpp"

namespace fp {

/// Resolves every template, checks that every output format can hold these shapes and that the
/// run fits the machine (core/io/scene_limits.hpp). Throws
/// SceneError (file, line, key) or std::invalid_argument; nothing has been written.
void check_shape_scene(const Scene& scene);

template <int D>
int run_shape_pack(const Scene& scene, const PackCommandOptions& options);

}  // namespace fp
