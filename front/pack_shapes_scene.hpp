#pragma once
// Entry point for a scene of non-spherical particles (Scene::particle_templates).
#include "core/io/scene.hpp"
#include "front/shape_front.hpp"

namespace fp {

/// Resolves the templates (SceneError on a bad family or parameter) and packs the container.
template <int D>
ShapePackResult<D> pack_shape_scene(const Scene& scene, const ProgressFn& progress = {});

}  // namespace fp
