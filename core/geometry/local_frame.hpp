#pragma once
// The local frame of a container: the origin its coordinates are stored relative to, so that a
// scene far from the origin keeps its digits (site or CAD coordinates, offsets of 1e6
// or 1e9). A double carries 53 bits; at 1e9 its spacing is 1.2e-7, a millionth of a particle
// of radius 0.01 and far above the contact tolerance of 1e-9 r. Everything the packer, the
// contact solvers and the metrics compute is in the local frame; only the scene reader (inputs)
// and the writers and readers of packing files (outputs) see absolute coordinates.
//
// The rule: q is the smallest power of two at least twice the largest extent, and the origin is
// the centre of the absolute bounds rounded to a multiple of q, per axis. Hence
//  * a container near the origin (|centre| < q/2 on an axis) keeps origin 0 there: plain scenes
//    are stored exactly as written;
//  * a box [t, t + e] with t a multiple of q (1e6, 1e9, any integer when e <= 1/2) is stored as
//    [0, e], a ball centred on such a t is stored centred on 0: a scene shifted by a round offset
//    packs bit for bit like the unshifted one;
//  * the origin has few significant bits, so its decimal expansion is short and absolute
//    coordinates written as origin + local are exact (core/io/exact_decimal.hpp), and
//    x - origin is exact for every x of the container (Sterbenz: |x - origin| <= q <= |origin|).
#include <cmath>

#include "core/geometry/vec.hpp"

namespace fp {

/// Whether a container read from a file takes its own local frame (scenes) or keeps origin 0
/// (code and tests that want the file's coordinates as they are).
enum class FrameChoice { Absolute, Local };

/// The origin of the local frame of a container whose absolute bounds are `bounds` (finite, lo <= hi).
template <int D>
Vec<D> frame_origin(const Aabb<D>& bounds) {
  const double extent = bounds.size().maxCoeff();
  Vec<D> origin = Vec<D>::Zero();
  if (!(extent > 0.0) || !std::isfinite(extent)) return origin;
  int e = 0;
  std::frexp(extent, &e);                  // extent < 2^e
  const double q = std::ldexp(1.0, e + 1); // >= 2 * extent
  if (!std::isfinite(q)) return origin;    // extent >= 2^1022: q overflows, 0 is its only multiple (inf * 0 is nan)
  for (int a = 0; a < D; ++a) {
    // 0.5 lo + 0.5 hi: no overflow for bounds near the largest doubles.
    const double c = 0.5 * bounds.lo[a] + 0.5 * bounds.hi[a];
    origin[a] = q * std::round(c / q);
  }
  return origin;
}

/// The origin of a frame centred on where growth starts (`seed`, absolute), for a container too
/// large ever to be filled: the seed rounded to a multiple of the power of two at least 2 r_max.
template <int D>
Vec<D> seed_frame_origin(const Vec<D>& seed, double r_max) {
  int e = 0;
  std::frexp(r_max, &e);
  const double q = std::ldexp(1.0, e + 1);
  if (!std::isfinite(q)) return Vec<D>::Zero();  // r_max >= 2^1022, as in frame_origin
  Vec<D> origin;
  for (int a = 0; a < D; ++a) origin[a] = q * std::round(seed[a] / q);
  return origin;
}

}  // namespace fp
