#pragma once
// Broad phase of the packer: a uniform grid of cells ~ factor * r_max, and for wide size
// distributions (r_max / r_min above a threshold) a hierarchy of such grids, one per octave of
// radius, so that a query touches O(1) cells and O(1) particles whatever the radius ratio
// (the O(n) argument of paper 002, Sect. 6, needs the neighbour search to be O(1)).
// Cells hold singly linked lists (head per cell, next per particle). Each list item carries a
// copy of its particle's centre and radius, so a query reads one cache line per particle rather
// than chasing ids into the packing's arrays (the query dominated at 10^6 particles).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D>
class NeighbourGrid {
 public:
  /// `domain`: where centres can be; radii in [r_min, r_max]; cells of `cell_factor * r_max`
  /// of their level; one level per octave of radius when r_max / r_min > `hierarchy_ratio`.
  NeighbourGrid(const Aabb<D>& domain, double r_min, double r_max, double cell_factor = 2.0,
                double hierarchy_ratio = 4.0, std::size_t max_cells_per_level = std::size_t(1) << 26) {
    if (!(r_min > 0.0) || !(r_max >= r_min)) throw std::invalid_argument("NeighbourGrid: need 0 < r_min <= r_max");
    if (!(cell_factor >= 1.0)) throw std::invalid_argument("NeighbourGrid: cell_factor must be >= 1");
    int levels = 1;
    if (r_max / r_min > hierarchy_ratio)
      levels = std::max(1, static_cast<int>(std::ceil(std::log2(r_max / r_min) - 1e-12)));  // one per octave of [r_min, r_max]
    levels_.resize(levels);
    for (int l = 0; l < levels; ++l) {
      Level& L = levels_[l];
      L.r_top = r_max / std::ldexp(1.0, l);  // level l holds radii in (r_top/2, r_top]; the last level takes the rest
      double cell = cell_factor * L.r_top;
      L.lo = domain.lo;
      Vec<D> size = domain.size();
      // Coarsen when a level would need too many cells (tiny particles in a huge domain).
      for (;;) {
        std::size_t total = 1;
        for (int a = 0; a < D; ++a) {
          L.dims[a] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(size[a] / cell)));
          total *= static_cast<std::size_t>(L.dims[a]);
          if (total > max_cells_per_level) break;
        }
        if (total <= max_cells_per_level) {
          L.head.assign(total, -1);
          break;
        }
        cell *= 1.26;
      }
      L.cell = cell;
      L.inv_cell = 1.0 / cell;
    }
  }

  int levels() const { return static_cast<int>(levels_.size()); }
  double cell_size(int level) const { return levels_[level].cell; }

  void insert(int id, const Vec<D>& c, double r) {
    if (static_cast<std::size_t>(id) >= items_.size()) items_.resize(std::max<std::size_t>(id + 1, items_.size() * 2));
    Level& L = levels_[level_of(r)];
    std::int64_t k = flat_index(L, c);
    items_[id] = Item{c, r, L.head[k]};
    L.head[k] = id;
  }

  /// Calls f(id) for every inserted particle that may lie within `reach` of c, i.e. whose ball
  /// (centre c_k, radius r_k) may come closer than `reach` to c: |c - c_k| <= reach + r_k.
  /// A superset; the caller filters with exact distances.
  template <class F>
  void for_each_near(const Vec<D>& c, double reach, F&& f) const {
    for_each_item_near(c, reach, [&](int id, const Item&) { f(id); });
  }

  /// Calls f(id, c_k, r_k, d2) for exactly the inserted particles with |c - c_k| <= reach + r_k,
  /// d2 = |c - c_k|^2.
  template <class F>
  void for_each_within(const Vec<D>& c, double reach, F&& f) const {
    for_each_item_near(c, reach, [&](int id, const Item& it) {
      const double d2 = (it.c - c).squaredNorm();
      const double lim = reach + it.r;
      if (d2 <= lim * lim) f(id, it.c, it.r, d2);
    });
  }

  /// Memory held by the grid, in bytes (for the run record).
  std::size_t memory_bytes() const {
    std::size_t b = items_.capacity() * sizeof(Item);
    for (const Level& L : levels_) b += L.head.capacity() * sizeof(int);
    return b;
  }

 private:
  struct Item {
    Vec<D> c;
    double r = 0;
    int next = -1;
  };

  template <class F>
  void for_each_item_near(const Vec<D>& c, double reach, F&& f) const {
    for (const Level& L : levels_) {
      const double half = reach + L.r_top;
      std::int64_t lo[D], hi[D];
      for (int a = 0; a < D; ++a) {
        lo[a] = clamp_cell(L, a, (c[a] - half - L.lo[a]) * L.inv_cell);
        hi[a] = clamp_cell(L, a, (c[a] + half - L.lo[a]) * L.inv_cell);
      }
      if constexpr (D == 2) {
        for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
          for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
            for (int id = L.head[x + L.dims[0] * y]; id >= 0; id = items_[id].next) f(id, items_[id]);
      } else {
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
          for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
            const std::int64_t row = L.dims[0] * (y + L.dims[1] * z);
            for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
              for (int id = L.head[x + row]; id >= 0; id = items_[id].next) f(id, items_[id]);
          }
      }
    }
  }

  struct Level {
    double r_top = 0, cell = 0, inv_cell = 0;
    Vec<D> lo;
    std::int64_t dims[D] = {};
    std::vector<int> head;
  };

  int level_of(double r) const {
    // Level l holds r in (r_top(l)/2, r_top(l)]; comparisons, not log2, so that a radius on an
    // octave boundary lands on the same level on every platform.
    int l = 0;
    while (l + 1 < static_cast<int>(levels_.size()) && r <= levels_[l + 1].r_top) ++l;
    return l;
  }
  static std::int64_t clamp_cell(const Level& L, int a, double x) {
    if (!(x > 0.0)) return 0;  // also catches NaN
    if (!(x < static_cast<double>(L.dims[a]))) return L.dims[a] - 1;  // before the cast: huge x overflows int64
    return static_cast<std::int64_t>(x);
  }
  static std::int64_t flat_index(const Level& L, const Vec<D>& c) {
    std::int64_t k = 0, stride = 1;
    for (int a = 0; a < D; ++a) {
      k += clamp_cell(L, a, (c[a] - L.lo[a]) * L.inv_cell) * stride;
      stride *= L.dims[a];
    }
    return k;
  }

  std::vector<Level> levels_;
  std::vector<Item> items_;  // by particle id
};

}  // namespace fp
