#pragma once
// The blocks a container's bounding box is cut into for parallel growth (front/block_front.hpp),
// and the order they grow in. Blocks are a regular grid; block (i, j, k) has the rank
// i + 2j + 4k (2D: i + 2j). Two neighbours (across a face, an edge or a corner) never share a
// rank, and across each face the neighbour that grows first is the one on the low side: a block
// grows from its low corner against what its low neighbours placed, and its high faces are free.
// (Fronts grown towards each other leave a seam of holes where they meet, as loose as a wall's
// layer; a block whose neighbours on both sides grew first would have one.) The layout depends
// on the domain, r_max and the requested edge only, never on the thread count.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/geometry/vec.hpp"
#include "core/io/scene.hpp"

namespace fp {

template <int D>
class BlockLayout {
 public:
  /// Smallest block edge, in r_max: above the 2 r_max within which two particles can touch (so a
  /// block's particles can meet only its immediate neighbours' ones) with room for a bulk.
  static constexpr double kMinEdge = kMinBlockEdge;
  /// Automatic edge: about kAutoBlocks blocks (a cube: 8 per axis in 3D, 16 in 2D: enough for
  /// the threads of a large machine), never below kAutoMinEdge r_max (a block's faces are where
  /// it grows against its neighbours: few blocks of many particles each).
  static constexpr double kAutoBlocks = D == 3 ? 512.0 : 256.0;
  static constexpr double kAutoMinEdge = 16.0;

  /// `edge`: the requested block edge, or <= 0 for the automatic one.
  BlockLayout(const Aabb<D>& domain, double r_max, double edge) : domain_(domain) {
    const Vec<D> size = domain.size();
    if (!(edge > 0)) {
      double measure = 1;
      for (int a = 0; a < D; ++a) measure *= size[a];
      edge = std::max(std::pow(measure / kAutoBlocks, 1.0 / D), kAutoMinEdge * r_max);
    } else if (edge < kMinEdge * r_max) {
      throw std::invalid_argument("block edge " + std::to_string(edge) + " is below " + std::to_string(kMinEdge) +
                                  " r_max = " + std::to_string(kMinEdge * r_max));
    }
    double count = 1;
    for (int a = 0; a < D; ++a) count *= blocks_along(size[a], r_max, edge);
    if (!(count <= kMaxBlocks))
      throw std::invalid_argument("block edge " + std::to_string(edge) + " cuts the container into " + std::to_string(count) +
                                  " blocks, more than " + std::to_string(kMaxBlocks));
    count_ = 1;
    for (int a = 0; a < D; ++a) {
      n_[a] = static_cast<int>(blocks_along(size[a], r_max, edge));
      count_ *= n_[a];
    }
  }

  int count() const { return count_; }
  int blocks_on_axis(int a) const { return n_[a]; }

  std::array<int, D> coords(int b) const {
    std::array<int, D> k{};
    for (int a = 0; a < D; ++a) k[a] = b % n_[a], b /= n_[a];
    return k;
  }
  int index(const std::array<int, D>& k) const {
    int b = 0;
    for (int a = D - 1; a >= 0; --a) b = b * n_[a] + k[a];
    return b;
  }
  /// The order of growth: a block grows after every neighbour of lower rank.
  int rank(int b) const {
    const std::array<int, D> k = coords(b);
    int r = 0;
    for (int a = D - 1; a >= 0; --a) r = 2 * r + k[a];
    return r;
  }

  /// The closed box of block b. Neighbours share their face coordinate bit for bit; the last
  /// block on an axis ends exactly at the domain's end.
  Aabb<D> box(int b) const {
    const std::array<int, D> k = coords(b);
    Aabb<D> x;
    for (int a = 0; a < D; ++a) {
      x.lo[a] = plane(a, k[a]);
      x.hi[a] = plane(a, k[a] + 1);
    }
    return x;
  }

  /// The blocks sharing a face, an edge or a corner with b, in index order.
  std::vector<int> neighbours(int b) const {
    const std::array<int, D> k = coords(b);
    std::vector<int> out;
    int steps = 1;
    for (int a = 0; a < D; ++a) steps *= 3;
    for (int s = 0; s < steps; ++s) {
      std::array<int, D> m = k;
      bool inside = true, self = true;
      for (int a = 0, t = s; a < D; ++a, t /= 3) {
        const int d = t % 3 - 1;
        m[a] += d;
        self &= d == 0;
        inside &= m[a] >= 0 && m[a] < n_[a];
      }
      if (inside && !self) out.push_back(index(m));
    }
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  double plane(int a, int k) const {
    if (k >= n_[a]) return domain_.hi[a];
    return domain_.lo[a] + (domain_.hi[a] - domain_.lo[a]) * (static_cast<double>(k) / n_[a]);
  }

  Aabb<D> domain_;
  std::array<int, D> n_{};
  int count_ = 1;
};

/// Distance from p to the closed box (0 inside).
template <int D>
double distance_to_box(const Aabb<D>& box, const Vec<D>& p) {
  const Vec<D> out = (box.lo - p).cwiseMax(p - box.hi).cwiseMax(Vec<D>::Zero());
  return out.norm();
}

}  // namespace fp
