#pragma once
// Packing particles of any shape: the one advancing front (front/advancing_front.hpp) with the
// particle model of general shapes (front/shape_model.hpp). Its result type, which carries the
// general solvers' counters, is declared here so that the sphere packer never includes them.
#include <cstdint>
#include <vector>

#include "contact/minimisation_solver.hpp"
#include "core/geometry/container.hpp"
#include "core/io/scene.hpp"
#include "front/pack_result.hpp"
#include "front/shape_template.hpp"
#include "shapes/particle.hpp"

namespace fp {

template <int D>
struct ShapePackResult {
  ShapePacking<D> packing;
  StopReason stop = StopReason::FrontExhausted;
  FrontCounters counters;
  MinimisationStats minimisation;
  std::uint64_t fcl_queries = 0;
  std::uint64_t analytic_solves = 0;   ///< solves the registry sent to a non-default (analytic) solver
  double seconds = 0.0;
  double solid_measure = 0.0;          ///< sum of particle volumes (areas)
  double gap_tolerance = 0.0;          ///< contact / overlap tolerance, relative to the smaller circumscribed radius
};

template <int D>
ShapePackResult<D> pack_shapes(const Container<D>& container, const std::vector<ShapeTemplate<D>>& templates,
                               const PackerOptions& options, const StopCriteria& stop, std::uint64_t seed,
                               const ProgressFn& progress = {});

}  // namespace fp
