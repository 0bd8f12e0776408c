#include "front/pack_shapes_scene.hpp"

#include <stdexcept>

namespace fp {

template <int D>
ShapePackResult<D> pack_shape_scene(const Scene& scene, const ProgressFn& progress) {
  if (scene.dimension != D) throw std::invalid_argument("pack_shape_scene<D>: scene dimension mismatch");
  const Container<D>* container = scene.container<D>();
  if (!container || scene.particle_templates.empty()) throw std::invalid_argument("pack_shape_scene: no container or no particle templates");
  if (scene.packer.method != "front") throw std::invalid_argument("pack: unknown method '" + scene.packer.method + "'");
  const std::vector<ShapeTemplate<D>> templates = resolve_templates<D>(scene);
  return pack_shapes<D>(*container, templates, scene.packer, scene.stop, scene.seed, progress);
}

template ShapePackResult<2> pack_shape_scene<2>(const Scene&, const ProgressFn&);
template ShapePackResult<3> pack_shape_scene<3>(const Scene&, const ProgressFn&);
}  // namespace fp
