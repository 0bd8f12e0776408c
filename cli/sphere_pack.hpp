#pragma once
// `frontpack pack` for a scene of spheres (disks): the advancing front over centres and radii (or
// paper 000's fill of a tetrahedral mesh, whose step 7b is the void filling, or paper 003's graded
// stacking), the void filling
// the scene may ask for (`densify:`), the least-squares densification (`least_squares:`), the thinning to its `target:`, then every figure of `frontpack analyze`
// (the independent validation included). `frontpack densify` runs the same stage on a packing
// read from a file.
#include <optional>
#include <string>

#include "cli/pack_check.hpp"
#include "cli/scaled_sizes.hpp"
#include "cli/target_thinning.hpp"
#include "core/io/scene.hpp"
#include "densify/least_squares.hpp"
#include "densify/void_filling.hpp"
#include "fill/graded_stacking.hpp"
#include "fill/tet_mesh_fill.hpp"
#include "front/pack_result.hpp"

namespace fp {

class BlockExchange;

/// A packing of spheres and how it was made: by the front, the tetrahedral-mesh fill, the stacking, or given
/// (frontpack densify); then perhaps its voids filled.
template <int D>
struct SphereRun : PackResult<D> {
  bool given = false;                            ///< read from a file, not packed
  std::optional<TetFillReport> tet_filled;       ///< packed by the tetrahedral-mesh fill (steps 2-7a)
  std::optional<StackingReport> stacked;         ///< packed by the graded stacking (paper 003)
  std::optional<VoidFillingReport> densified;    ///< the void filling, when the scene asks for it
  std::optional<LeastSquaresReport> squared;     ///< the least-squares densification (`least_squares:`)
  std::optional<TargetThinning> thinned;         ///< brought down to the scene's `target:`
  std::optional<SizeScaling> sizes_scaled;       ///< `stop.scale_sizes`: the radius law's scale solved for
};

template <int D>
struct SpherePack {
  using Result = SphereRun<D>;
  static Result pack(const Scene& scene, const ProgressFn& progress, BlockExchange* exchange);
  /// `packing` (in the scene container's frame) filled by the scene's void filling (its
  /// defaults when the scene has neither `densify:` nor `least_squares:`), then densified by
  /// least squares when it asks.
  static Result densify(const Scene& scene, Packing<D> packing);
  static PackCheck check(const Scene& scene, const Result& result, CheckDepth depth);
  static std::string stop_text(const Result& result);
};

}  // namespace fp
