#pragma once
// Packing particles of any shape: the one advancing front (front/advancing_front.hpp) with the
// particle model of general shapes (front/shape_model.hpp), returning the front's one result type
// over a ShapePacking.
#include <vector>

#include "core/geometry/container.hpp"
#include "core/io/scene.hpp"
#include "front/pack_result.hpp"
#include "front/shape_template.hpp"
#include "shapes/particle.hpp"

namespace fp {

template <int D>
using ShapePackResult = PackResult<D, ShapePacking<D>>;

template <int D>
ShapePackResult<D> pack_shapes(const Container<D>& container, const std::vector<ShapeTemplate<D>>& templates,
                               const PackerOptions& options, const StopCriteria& stop, std::uint64_t seed,
                               const ProgressFn& progress = {});

}  // namespace fp
