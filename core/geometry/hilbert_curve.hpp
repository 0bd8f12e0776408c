#pragma once
// A Hilbert curve through a grid of cells: an order of points in which each stretch is a compact
// region (the thinning's walk; the least-squares densification's memory order).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/geometry/vec.hpp"

namespace fp {

/// The index along a Hilbert curve of the cell of `edge` holding x, cells counted from `lo`, at
/// most 2^21 per axis: a stretch of the curve is a compact region (a Morton order jumps across
/// regions at every power of two, and a cell of the analysis then holds many short stretches).
/// Skilling's transpose form (AIP Conf. Proc. 707, 381, 2004), any dimension.
template <int D>
std::uint64_t hilbert_key(const Vec<D>& x, const Vec<D>& lo, double edge) {
  constexpr int kBits = 21;
  std::uint32_t X[D];
  for (int k = 0; k < D; ++k)
    X[k] = static_cast<std::uint32_t>(std::clamp(std::floor((x[k] - lo[k]) / edge), 0.0, double((1u << kBits) - 1)));
  // Axes to transpose: undo the excess work of the inverse, then Gray-encode.
  for (std::uint32_t q = 1u << (kBits - 1); q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < D; ++i) {
      if (X[i] & q) {
        X[0] ^= p;
      } else {
        const std::uint32_t t = (X[0] ^ X[i]) & p;
        X[0] ^= t;
        X[i] ^= t;
      }
    }
  }
  for (int i = 1; i < D; ++i) X[i] ^= X[i - 1];
  std::uint32_t t = 0;
  for (std::uint32_t q = 1u << (kBits - 1); q > 1; q >>= 1)
    if (X[D - 1] & q) t ^= q - 1;
  for (int i = 0; i < D; ++i) X[i] ^= t;
  // The transposed bits, interleaved from the top.
  std::uint64_t key = 0;
  for (int b = kBits - 1; b >= 0; --b)
    for (int i = 0; i < D; ++i) key = (key << 1) | ((X[i] >> b) & 1u);
  return key;
}

}  // namespace fp
