#pragma once
// Particle storage: structure of arrays (centres, radii), the layout the hot loops want.
#include <cstddef>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D>
struct Packing {
  std::vector<Vec<D>> centers;
  std::vector<double> radii;

  std::size_t size() const { return radii.size(); }
  bool empty() const { return radii.empty(); }
  void reserve(std::size_t n) { centers.reserve(n); radii.reserve(n); }
  int add(const Vec<D>& c, double r) {
    centers.push_back(c);
    radii.push_back(r);
    return static_cast<int>(radii.size()) - 1;
  }
  void clear() { centers.clear(); radii.clear(); }
};

}  // namespace fp
