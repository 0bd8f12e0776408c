#pragma once
// A direction drawn uniformly on the unit circle (2D) or sphere (3D, Archimedes: z uniform).
#include <algorithm>
#include <cmath>

#include "core/geometry/vec.hpp"
#include "core/sampling/rng.hpp"

namespace fp {

template <int D>
Vec<D> random_unit(Rng& rng) {
  if constexpr (D == 2) {
    const double phi = 2 * kPi * rng.uniform01();
    return Vec2(std::cos(phi), std::sin(phi));
  } else {
    const double z = 2 * rng.uniform01() - 1, phi = 2 * kPi * rng.uniform01();
    const double s = std::sqrt(std::max(0.0, 1 - z * z));
    return Vec3(s * std::cos(phi), s * std::sin(phi), z);
  }
}

}  // namespace fp
