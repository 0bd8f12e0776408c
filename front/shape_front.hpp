#pragma once
// The advancing front for particles of any shape: paper 002 Pseudocode 1 (as in
// advancing_front.hpp) with each placement delegated to the contact solver the registry picks
// for the shape kinds involved (paper 004: minimisation by default, analytic where registered).
// Neighbourhoods use circumscribed radii (the grid is the broad phase); candidate tests use the
// narrow phase. Same levers and defaults as the sphere front where they apply: s0 closest to the
// seed point, neighbours nearest first, walls as bodies (planes, spheres, cylinders, reflex
// corners), the kept candidate closest to the seed (wall contacts first), a pool of drafts so a
// particle that does not fit waits instead of being resized, resumption in voids when F empties.
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
