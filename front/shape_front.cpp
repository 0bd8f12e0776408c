#include "front/shape_front.hpp"

#include "front/advancing_front.hpp"
#include "front/block_front.hpp"
#include "front/shape_model.hpp"

namespace fp {

template <int D>
ShapePackResult<D> pack_shapes(const Container<D>& container, const std::vector<ShapeTemplate<D>>& templates,
                               const PackerOptions& options, const StopCriteria& stop, std::uint64_t seed,
                               const ProgressFn& progress) {
  if (options.in_blocks()) {
    BlockFront<D, ShapeModel<D>> blocks(container, templates, options, stop, seed);
    return blocks.run(thread_count(options.threads), progress);
  }
  AdvancingFront<D, ShapeModel<D>> front(container, templates, options, stop, seed);
  return front.run(progress);
}

template ShapePackResult<2> pack_shapes<2>(const Container<2>&, const std::vector<ShapeTemplate<2>>&, const PackerOptions&,
                                           const StopCriteria&, std::uint64_t, const ProgressFn&);
template ShapePackResult<3> pack_shapes<3>(const Container<3>&, const std::vector<ShapeTemplate<3>>&, const PackerOptions&,
                                           const StopCriteria&, std::uint64_t, const ProgressFn&);

}  // namespace fp
