#pragma once
// Helpers of the analysis tests (fabric, VF of regions, g(r), the packing analysis): the test
// meshes, and a box whose sides are whole periods of a lattice, in which the lattice's packing
// fraction is exact whatever the offset.
#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/box_container.hpp"
#include "core/geometry/vec.hpp"
#include "core/sampling/rng.hpp"
#include "core/sampling/standard_normal.hpp"

namespace fp::test {

inline std::string mesh_path(const std::string& name) {
  return std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/meshes/" + name;
}

/// The container whose core (shrunk by `shrink`) is the box [core_lo, core_lo + periods * period].
template <int D>
BoxContainer<D> container_around_core(const Vec<D>& core_lo, const Vec<D>& period, const Vec<D>& periods, double shrink) {
  const Vec<D> lo = core_lo - Vec<D>::Constant(shrink);
  return BoxContainer<D>(lo, core_lo + period.cwiseProduct(periods) + Vec<D>::Constant(shrink));
}

/// n isotropic random directions (normalised Gaussian vectors), reproducible from the seed.
template <int D>
std::vector<Vec<D>> random_directions(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Vec<D>> out(n);
  for (Vec<D>& v : out) {
    for (int a = 0; a < D; ++a) v[a] = normal_quantile(rng.uniform_open01());
    v.normalize();
  }
  return out;
}

}  // namespace fp::test
