#pragma once
// Particle storage: structure of arrays (centres, radii), the layout the hot loops want.
// Centres are in the local frame of the container they fill (core/geometry/local_frame.hpp):
// the absolute position of particle i is origin + centers[i].
#include <cstddef>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D>
struct Packing {
  std::vector<Vec<D>> centers;
  std::vector<double> radii;
  Vec<D> origin = Vec<D>::Zero();  ///< absolute position of the frame the centres are relative to

  std::size_t size() const { return radii.size(); }
  bool empty() const { return radii.empty(); }
  void reserve(std::size_t n) { centers.reserve(n); radii.reserve(n); }
  int add(const Vec<D>& c, double r) {
    centers.push_back(c);
    radii.push_back(r);
    return static_cast<int>(radii.size()) - 1;
  }
  void clear() { centers.clear(); radii.clear(); }
  /// Absolute position of particle i (rounded to a double: for display, not for checks).
  Vec<D> absolute(std::size_t i) const { return origin + centers[i]; }
};

}  // namespace fp
