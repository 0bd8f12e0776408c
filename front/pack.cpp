#include "front/pack.hpp"

#include <stdexcept>

#include "front/advancing_front.hpp"
#include "front/block_front.hpp"

namespace fp {

const char* to_string(StopReason r) {
  switch (r) {
    case StopReason::FrontExhausted: return "front exhausted";
    case StopReason::ParticleCount: return "particle count reached";
    case StopReason::VolumeFraction: return "target volume fraction reached";
    case StopReason::TimeLimit: return "time limit reached";
  }
  return "?";
}

template <int D>
PackResult<D> pack(const Scene& scene, const ProgressFn& progress, BlockExchange* exchange) {
  if (scene.dimension != D) throw std::invalid_argument("pack<D>: scene dimension mismatch");
  const Container<D>* container = scene.container<D>();
  if (!container || !scene.radii) throw std::invalid_argument("pack: scene has no container or no size distribution");
  if (scene.packer.method != "front") throw std::invalid_argument("pack: unknown method '" + scene.packer.method + "'");
  if (exchange && exchange->processes() > 1) {
    BlockFront<D, SphereModel<D>> blocks(*container, *scene.radii, scene.packer, scene.stop, scene.seed);
    return blocks.run_distributed(*exchange);
  }
  if (scene.packer.in_blocks()) {
    BlockFront<D, SphereModel<D>> blocks(*container, *scene.radii, scene.packer, scene.stop, scene.seed);
    return blocks.run(thread_count(scene.packer.threads), progress);
  }
  AdvancingFront<D> front(*container, *scene.radii, scene.packer, scene.stop, scene.seed);
  return front.run(progress);
}

template PackResult<2> pack<2>(const Scene&, const ProgressFn&, BlockExchange*);
template PackResult<3> pack<3>(const Scene&, const ProgressFn&, BlockExchange*);

}  // namespace fp
