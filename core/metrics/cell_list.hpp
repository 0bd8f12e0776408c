#pragma once
// Broad phase of the metrics and the validator. Written apart from the packer's NeighbourGrid on
// purpose: `validate` must not share a code path (or a bug) with the packer it checks.
//
// Every ball gets a reach box, centre +- pad with pad = r (1 + reach_rel) plus a rounding slack;
// for_each_candidate_pair visits, exactly once, every pair whose boxes overlap, hence every pair at
// distance <= (r_i + r_j)(1 + reach_rel). Wide radius ratios stay O(N): balls are split into
// bands of pad a factor 4 wide (one level each); a level is a grid of cells of side twice its
// largest pad, indexed by centre. Pairs inside a level come from a cell and its forward half of neighbours;
// pairs across levels from each ball querying the few cells of every coarser level its box
// reaches. A level's cell table is a dense array when the grid is not much larger than the
// level's population, a sorted key list behind an open-addressing table otherwise (sparse or
// elongated packings), so memory stays O(N) whatever the bounding box.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/geometry/vec.hpp"

namespace fp {

template <int D>
class CellList {
 public:
  /// Indexes the balls (centers[i], radii[i]). Balls with a non-finite centre or radius, or a
  /// negative radius, are left out (the validator reports them itself). `centers` must outlive
  /// the CellList. reach_rel >= 0 widens the boxes, e.g. by the contact tolerance.
  CellList(const std::vector<Vec<D>>& centers, const std::vector<double>& radii, double reach_rel = 0.0);

  /// Calls visit(i, j), i < j, once for every pair of indexed balls whose reach boxes overlap.
  /// The order of the calls is deterministic.
  template <class Visit>
  void for_each_candidate_pair(Visit&& visit) const {
    for_each_candidate_pair(0, 1, visit);
  }
  /// The same pairs cut into `parts` parts (every pair in exactly one): part `part` of them, in a
  /// deterministic order. Parts may run on different threads at once (they only read).
  template <class Visit>
  void for_each_candidate_pair(std::size_t part, std::size_t parts, Visit&& visit) const;

  /// Number of indexed balls (those not left out).
  std::size_t indexed() const { return indexed_; }
  int level_count() const { return static_cast<int>(levels_.size()); }
  /// Levels whose cell table is hashed rather than a dense array (diagnostics and tests).
  int sparse_levels() const {
    int n = 0;
    for (const Level& lv : levels_) n += lv.dense ? 0 : 1;
    return n;
  }
  /// Reach half-width of ball i (its pad).
  double pad(std::size_t i) const { return pads_[i]; }

 private:
  using Coords = std::array<std::int64_t, D>;

  struct Level {
    double half_cell = 0.0;  // largest pad in the level
    double cell = 0.0;       // cell side, >= 2 * half_cell
    Coords dims{};
    Coords stride{};
    std::vector<std::uint32_t> members;     // ball ids, sorted by cell then id
    bool dense = true;
    std::vector<std::uint32_t> cell_start;  // dense: indexed by key; sparse: by rank in keys (size + 1)
    std::vector<std::uint64_t> keys;        // sparse only: sorted occupied cell keys
    std::vector<std::uint32_t> slots;       // sparse only: 1 + rank in keys, 0 = empty slot

    std::uint64_t key_of(const Coords& c) const {
      std::uint64_t k = 0;
      for (int a = 0; a < D; ++a) k += static_cast<std::uint64_t>(c[a]) * static_cast<std::uint64_t>(stride[a]);
      return k;
    }
    // Members of the cell with this key, as [begin, end) in `members`.
    std::pair<std::uint32_t, std::uint32_t> range(std::uint64_t key) const {
      if (dense) return {cell_start[key], cell_start[key + 1]};
      const std::uint64_t mask = slots.size() - 1;
      for (std::uint64_t s = mix(key) & mask;; s = (s + 1) & mask) {
        const std::uint32_t v = slots[s];
        if (v == 0) return {0, 0};
        if (keys[v - 1] == key) return {cell_start[v - 1], cell_start[v]};
      }
    }
  };

  static std::uint64_t mix(std::uint64_t z) {  // SplitMix64 finaliser: spreads neighbouring keys
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  std::int64_t coord(const Level& lv, int axis, double x) const {
    const double t = std::floor((x - origin_[axis]) / lv.cell);
    if (!(t > 0.0)) return 0;
    const double top = static_cast<double>(lv.dims[axis] - 1);
    return t >= top ? lv.dims[axis] - 1 : static_cast<std::int64_t>(t);
  }

  bool boxes_overlap(std::uint32_t i, std::uint32_t j) const {
    const double reach = pads_[i] + pads_[j];
    const Vec<D>& a = (*centers_)[i];
    const Vec<D>& b = (*centers_)[j];
    for (int k = 0; k < D; ++k)
      if (std::abs(a[k] - b[k]) > reach) return false;
    return true;
  }

  void build_level(Level& lv, std::vector<std::uint32_t> ids);

  const std::vector<Vec<D>>* centers_;
  std::vector<double> pads_;
  Vec<D> origin_ = Vec<D>::Zero();  // lowest corner of the indexed centres
  Vec<D> extent_ = Vec<D>::Zero();  // size of their bounding box
  std::vector<Level> levels_;  // finest first; only non-empty levels are kept
  std::size_t indexed_ = 0;
};

template <int D>
template <class Visit>
void CellList<D>::for_each_candidate_pair(std::size_t part, std::size_t parts, Visit&& visit) const {
  // Forward half of the 3^D neighbourhood: offsets whose first non-zero component is +1.
  std::vector<Coords> forward;
  {
    Coords o;
    o.fill(-1);
    for (;;) {
      int first = 0;
      for (int a = 0; a < D && first == 0; ++a) first = static_cast<int>(o[a]);
      if (first > 0) forward.push_back(o);
      int a = 0;
      while (a < D && o[a] == 1) o[a++] = -1;
      if (a == D) break;
      ++o[a];
    }
  }
  auto emit = [&](std::uint32_t i, std::uint32_t j) {
    if (boxes_overlap(i, j)) {
      if (i < j) visit(i, j);
      else visit(j, i);
    }
  };

  for (std::size_t l = 0; l < levels_.size(); ++l) {
    const Level& lv = levels_[l];
    // Pairs inside the level.
    auto scan_cell = [&](const Coords& c, std::uint32_t b, std::uint32_t e) {
      for (std::uint32_t p = b; p < e; ++p)
        for (std::uint32_t q = p + 1; q < e; ++q) emit(lv.members[p], lv.members[q]);
      for (const Coords& o : forward) {
        Coords n;
        bool in = true;
        for (int a = 0; a < D; ++a) {
          n[a] = c[a] + o[a];
          in = in && n[a] >= 0 && n[a] < lv.dims[a];
        }
        if (!in) continue;
        const auto [nb, ne] = lv.range(lv.key_of(n));
        for (std::uint32_t p = b; p < e; ++p)
          for (std::uint32_t q = nb; q < ne; ++q) emit(lv.members[p], lv.members[q]);
      }
    };
    auto decode = [&](std::uint64_t key) {
      Coords c;
      for (int a = D - 1; a >= 0; --a) {
        c[a] = static_cast<std::int64_t>(key / static_cast<std::uint64_t>(lv.stride[a]));
        key -= static_cast<std::uint64_t>(c[a]) * static_cast<std::uint64_t>(lv.stride[a]);
      }
      return c;
    };
    // A part: a range of cells of each level, and a range of each level's balls for the pairs
    // across levels.
    auto slice = [part, parts](std::size_t count) {
      return std::pair<std::size_t, std::size_t>{count * part / parts, count * (part + 1) / parts};
    };
    if (lv.dense) {
      const auto [first, last] = slice(lv.cell_start.size() - 1);
      for (std::uint64_t k = first; k < last; ++k)
        if (lv.cell_start[k] != lv.cell_start[k + 1]) scan_cell(decode(k), lv.cell_start[k], lv.cell_start[k + 1]);
    } else {
      const auto [first, last] = slice(lv.keys.size());
      for (std::size_t r = first; r < last; ++r)
        scan_cell(decode(lv.keys[r]), lv.cell_start[r], lv.cell_start[r + 1]);
    }

    // Pairs with every coarser level, seen from the finer ball: the coarser ball's centre lies
    // within pad_i + half_cell of it on every axis.
    const auto [first_ball, last_ball] = slice(lv.members.size());
    for (std::size_t m = l + 1; m < levels_.size(); ++m) {
      const Level& up = levels_[m];
      for (std::size_t b = first_ball; b < last_ball; ++b) {
        const std::uint32_t i = lv.members[b];
        const Vec<D>& c = (*centers_)[i];
        const double reach = pads_[i] + up.half_cell;
        Coords lo, hi;
        for (int a = 0; a < D; ++a) {
          lo[a] = coord(up, a, c[a] - reach);
          hi[a] = coord(up, a, c[a] + reach);
        }
        Coords n = lo;
        for (;;) {
          const auto [nb, ne] = up.range(up.key_of(n));
          for (std::uint32_t q = nb; q < ne; ++q) emit(i, up.members[q]);
          int a = 0;
          while (a < D && n[a] == hi[a]) {
            n[a] = lo[a];
            ++a;
          }
          if (a == D) break;
          ++n[a];
        }
      }
    }
  }
}

extern template class CellList<2>;
extern template class CellList<3>;

}  // namespace fp
