#pragma once
// Broad phase of the packer: a uniform grid of cells ~ factor * r_max, and for wide size
// distributions (r_max / r_min above a threshold) a hierarchy of such grids, one per octave of
// radius, so that a query touches O(1) cells and O(1) particles whatever the radius ratio
// (the O(n) argument of paper 002, Sect. 6, needs the neighbour search to be O(1)).
// Cells hold singly linked lists (head per cell, next per particle). Each list item carries a
// copy of its particle's centre and radius, so a query reads one cache line per particle rather
// than chasing ids into the packing's arrays. Fine levels are also listed per top-level cell
// ("block"): a big query into a sparse fine level walks those lists instead of empty fine cells
// (at r_max/r_min = 50 that was 86 % of the packing time and 0.5 GB of cells).
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
                double hierarchy_ratio = 4.0, std::size_t max_cells_per_level = std::size_t(1) << 24) {
    if (!(r_min > 0.0) || !(r_max >= r_min)) throw std::invalid_argument("NeighbourGrid: need 0 < r_min <= r_max");
    if (!(cell_factor >= 1.0)) throw std::invalid_argument("NeighbourGrid: cell_factor must be >= 1");
    int levels = 1;
    if (r_max / r_min > hierarchy_ratio)
      levels = std::max(1, static_cast<int>(std::ceil(std::log2(r_max / r_min) - 1e-12)));  // one per octave of [r_min, r_max]
    levels_.resize(levels);
    for (int l = 0; l < levels; ++l) {
      Level& L = levels_[l];
      L.r_top = r_max / std::ldexp(1.0, l);  // level l holds radii in (r_top/2, r_top]; the last level takes the rest
      // A fine level needs its fine cells only for queries of its own size: it has at most
      // kFineCellsPerBlock cells per top-level cell, and all fine levels together at most
      // max_cells_per_level (memory follows the domain, not N: 10^4 spheres at r_max/r_min = 50
      // in a box of 180 r_max took 0.8 GB before this cap).
      const std::size_t cap = l == 0 ? max_cells_per_level
                                     : std::min(max_cells_per_level / static_cast<std::size_t>(levels - 1),
                                                kFineCellsPerBlock * levels_[0].cells.count());
      L.cells = Lattice(domain, cell_factor * L.r_top, cap);
      L.head.assign(L.cells.count(), -1);
      if (l > 0) L.block_head.assign(levels_[0].cells.count(), -1);
    }
  }

  int levels() const { return static_cast<int>(levels_.size()); }
  double cell_size(int level) const { return levels_[level].cells.cell; }

  void insert(int id, const Vec<D>& c, double r) {
    if (static_cast<std::size_t>(id) >= items_.size()) items_.resize(std::max<std::size_t>(id + 1, items_.size() * 2));
    const int l = level_of(r);
    Level& L = levels_[l];
    Item& it = items_[id];
    it.c = c;
    it.r = r;
    const std::size_t k = L.cells.index_of(c);
    it.next = L.head[k];
    L.head[k] = id;
    if (l > 0) {
      const std::size_t b = levels_[0].cells.index_of(c);
      it.next_in_block = L.block_head[b];
      L.block_head[b] = id;
    }
  }

  /// Takes an inserted particle out (a particle moved: erase, then insert at its new centre).
  /// O(particles in its cell).
  void erase(int id) {
    const Item& it = items_[id];
    const int l = level_of(it.r);
    Level& L = levels_[l];
    unlink(L.head[L.cells.index_of(it.c)], id, &Item::next);
    if (l > 0) unlink(L.block_head[levels_[0].cells.index_of(it.c)], id, &Item::next_in_block);
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
    for (const Level& L : levels_) b += (L.head.capacity() + L.block_head.capacity()) * sizeof(int);
    return b;
  }

 private:
  /// A fine level scanned cell by cell costs its cells; scanned through the top level's blocks it
  /// costs its particles there. A query much larger than the level's cells (a big particle next to
  /// a small one) would visit mostly empty fine cells: it takes the block lists instead.
  static constexpr std::size_t kFineCellsPerBlock = 64;
  static constexpr std::size_t kBlockScanRatio = 8;

  /// Axis-aligned cells of one size over the domain, flattened x fastest.
  struct Lattice {
    Vec<D> lo;
    double cell = 0, inv_cell = 0;
    std::int64_t dims[D] = {};

    Lattice() = default;
    /// Cells of `cell` (coarsened by 1.26x steps until there are at most `max_cells`).
    Lattice(const Aabb<D>& domain, double cell_size, std::size_t max_cells) : lo(domain.lo), cell(cell_size) {
      const Vec<D> size = domain.size();
      for (;;) {
        std::size_t total = 1;
        for (int a = 0; a < D; ++a) {
          dims[a] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(size[a] / cell)));
          total *= static_cast<std::size_t>(dims[a]);
          if (total > max_cells) break;
        }
        if (total <= max_cells) break;
        cell *= 1.26;
      }
      inv_cell = 1.0 / cell;
    }
    std::size_t count() const {
      std::size_t n = 1;
      for (int a = 0; a < D; ++a) n *= static_cast<std::size_t>(dims[a]);
      return n;
    }
    std::int64_t clamp_cell(int a, double x) const {
      if (!(x > 0.0)) return 0;  // also catches NaN
      if (!(x < static_cast<double>(dims[a]))) return dims[a] - 1;  // before the cast: huge x overflows int64
      return static_cast<std::int64_t>(x);
    }
    std::size_t index_of(const Vec<D>& c) const {
      std::int64_t k = 0, stride = 1;
      for (int a = 0; a < D; ++a) {
        k += clamp_cell(a, (c[a] - lo[a]) * inv_cell) * stride;
        stride *= dims[a];
      }
      return static_cast<std::size_t>(k);
    }
    /// The cells meeting the box [c - half, c + half]; returns how many.
    std::size_t range(const Vec<D>& c, double half, std::int64_t (&from)[D], std::int64_t (&to)[D]) const {
      std::size_t n = 1;
      for (int a = 0; a < D; ++a) {
        from[a] = clamp_cell(a, (c[a] - half - lo[a]) * inv_cell);
        to[a] = clamp_cell(a, (c[a] + half - lo[a]) * inv_cell);
        n *= static_cast<std::size_t>(to[a] - from[a] + 1);
      }
      return n;
    }
    template <class G>
    void for_each_cell(const std::int64_t (&from)[D], const std::int64_t (&to)[D], G&& g) const {
      if constexpr (D == 2) {
        for (std::int64_t y = from[1]; y <= to[1]; ++y)
          for (std::int64_t x = from[0]; x <= to[0]; ++x) g(static_cast<std::size_t>(x + dims[0] * y));
      } else {
        for (std::int64_t z = from[2]; z <= to[2]; ++z)
          for (std::int64_t y = from[1]; y <= to[1]; ++y) {
            const std::int64_t row = dims[0] * (y + dims[1] * z);
            for (std::int64_t x = from[0]; x <= to[0]; ++x) g(static_cast<std::size_t>(x + row));
          }
      }
    }
  };

  struct Item {
    Vec<D> c;
    double r = 0;
    int next = -1;           // next particle of the same level in the same cell
    int next_in_block = -1;  // next particle of the same (fine) level in the same top-level cell
  };

  struct Level {
    double r_top = 0;
    Lattice cells;
    std::vector<int> head;        // per cell of `cells`
    std::vector<int> block_head;  // per cell of level 0's lattice (fine levels only)
  };

  template <class F>
  void for_each_item_near(const Vec<D>& c, double reach, F&& f) const {
    for (std::size_t l = 0; l < levels_.size(); ++l) {
      const Level& L = levels_[l];
      const double half = reach + L.r_top;
      std::int64_t from[D], to[D];
      const std::size_t n_cells = L.cells.range(c, half, from, to);
      if (l > 0) {
        std::int64_t bfrom[D], bto[D];
        const Lattice& blocks = levels_[0].cells;
        if (n_cells > kBlockScanRatio * blocks.range(c, half, bfrom, bto)) {
          blocks.for_each_cell(bfrom, bto, [&](std::size_t b) {
            for (int id = L.block_head[b]; id >= 0; id = items_[id].next_in_block) f(id, items_[id]);
          });
          continue;
        }
      }
      L.cells.for_each_cell(from, to, [&](std::size_t k) {
        for (int id = L.head[k]; id >= 0; id = items_[id].next) f(id, items_[id]);
      });
    }
  }

  /// Removes `id` from the singly linked list starting at `head`, linked through `link`.
  void unlink(int& head, int id, int Item::*link) {
    if (head == id) {
      head = items_[id].*link;
      return;
    }
    for (int k = head; k >= 0; k = items_[k].*link)
      if (items_[k].*link == id) {
        items_[k].*link = items_[id].*link;
        return;
      }
  }

  int level_of(double r) const {
    // Level l holds r in (r_top(l)/2, r_top(l)]; comparisons, not log2, so that a radius on an
    // octave boundary lands on the same level on every platform.
    int l = 0;
    while (l + 1 < static_cast<int>(levels_.size()) && r <= levels_[l + 1].r_top) ++l;
    return l;
  }

  std::vector<Level> levels_;
  std::vector<Item> items_;  // by particle id
};

}  // namespace fp
