#pragma once
// The part of a run record every `pack` fills the same way, spheres or shapes: what was run
// (version, scene, seed, dimension) and the container (description, bounds; 2D with z = 0).
#include <cstddef>

#include "core/geometry/container.hpp"
#include "core/io/run_record.hpp"
#include "core/io/scene.hpp"
#include "frontpack/version.hpp"

namespace fp {

template <int D>
RunRecord start_run_record(const Scene& scene, const Container<D>& container, std::size_t n) {
  RunRecord rec;
  rec.version = kVersion;
  rec.scene_path = scene.source_path;
  rec.scene_text = scene.source_text;
  rec.seed = scene.seed;
  rec.dimension = D;
  rec.n = n;
  rec.container_description = container.describe();
  const Aabb<D> b = container.bounds();
  Aabb<3> b3;
  b3.lo.setZero();
  b3.hi.setZero();
  b3.lo.template head<D>() = b.lo;
  b3.hi.template head<D>() = b.hi;
  rec.bounds = b3;
  return rec;
}

}  // namespace fp
