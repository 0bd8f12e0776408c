#include "core/metrics/cell_list.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <stdexcept>

namespace fp {

template <int D>
CellList<D>::CellList(const std::vector<Vec<D>>& centers, const std::vector<double>& radii, double reach_rel)
    : centers_(&centers) {
  if (centers.size() != radii.size())
    throw std::invalid_argument("CellList: centers and radii differ in size");
  if (!(reach_rel >= 0.0) || !std::isfinite(reach_rel))
    throw std::invalid_argument("CellList: reach_rel must be finite and >= 0");
  if (centers.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("CellList: more than 2^32 - 2 balls");

  const std::size_t n = centers.size();
  pads_.assign(n, 0.0);
  std::vector<std::uint32_t> ids;
  ids.reserve(n);
  Vec<D> lo = Vec<D>::Constant(std::numeric_limits<double>::infinity());
  Vec<D> hi = -lo;
  double magnitude = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(radii[i] >= 0.0) || !std::isfinite(radii[i]) || !centers[i].allFinite()) continue;
    ids.push_back(static_cast<std::uint32_t>(i));
    lo = lo.cwiseMin(centers[i]);
    hi = hi.cwiseMax(centers[i]);
    magnitude = std::max(magnitude, centers[i].cwiseAbs().maxCoeff());
  }
  indexed_ = ids.size();
  if (ids.empty()) return;
  origin_ = lo;

  // Slack: cell coordinates are computed from x - origin, whose rounding error is a few ulps of
  // the largest coordinate; the relative 1e-9 keeps pairs at exactly the reach inside it.
  const double slack = 16.0 * std::numeric_limits<double>::epsilon() * magnitude;
  double pad_max = 0.0;
  for (const std::uint32_t i : ids) {
    pads_[i] = radii[i] * (1.0 + reach_rel + 1e-9) + slack;
    pad_max = std::max(pad_max, pads_[i]);
  }
  // Zero radii (at the origin) would give empty cells: floor the pads, bounding the level count.
  const double pad_floor = pad_max > 0.0 ? std::ldexp(pad_max, -30) : 1.0;
  double pad_min = std::numeric_limits<double>::infinity();
  for (const std::uint32_t i : ids) {
    pads_[i] = std::max(pads_[i], pad_floor);
    pad_min = std::min(pad_min, pads_[i]);
  }

  extent_ = hi - lo;
  // Bands of pad a factor 4 wide: level L holds pad in (pad_min 4^L, pad_min 4^(L+1)] (level 0
  // also pad_min). Measured on 1e6 balls: factor 4 beats octaves for ratios 3 to 1000 (fewer
  // cross-level lookups outweigh the fuller cells).
  std::vector<std::vector<std::uint32_t>> by_level;
  for (const std::uint32_t i : ids) {
    std::size_t l = 0;
    while (pads_[i] > std::ldexp(pad_min, 2 * (static_cast<int>(l) + 1))) ++l;
    if (by_level.size() <= l) by_level.resize(l + 1);
    by_level[l].push_back(i);
  }
  for (auto& members : by_level) {
    if (members.empty()) continue;
    levels_.emplace_back();
    build_level(levels_.back(), std::move(members));
  }
}

template <int D>
void CellList<D>::build_level(Level& lv, std::vector<std::uint32_t> ids) {
  for (const std::uint32_t i : ids) lv.half_cell = std::max(lv.half_cell, pads_[i]);
  lv.cell = 2.0 * lv.half_cell;
  // Grid over the bounding box of all centres (shared by the levels); coarsen if the linear key
  // would not fit in 62 bits (only for absurd extent / radius ratios).
  for (;;) {
    double cells = 1.0;
    for (int a = 0; a < D; ++a) {
      lv.dims[a] = static_cast<std::int64_t>(std::floor(extent_[a] / lv.cell)) + 1;
      cells *= static_cast<double>(lv.dims[a]);
    }
    if (cells <= 0x1p62) break;
    lv.cell *= 2.0;
  }
  std::int64_t s = 1;
  for (int a = 0; a < D; ++a) {
    lv.stride[a] = s;
    s *= lv.dims[a];
  }
  const auto cells = static_cast<std::uint64_t>(s);

  std::vector<std::uint64_t> key(ids.size());
  for (std::size_t p = 0; p < ids.size(); ++p) {
    Coords c;
    for (int a = 0; a < D; ++a) c[a] = coord(lv, a, (*centers_)[ids[p]][a]);
    key[p] = lv.key_of(c);
  }

  // Dense when the table is small next to the level's population, or next to the whole set
  // (coarse levels of wide distributions: few balls, many lookups from the finer levels).
  lv.dense = cells <= 4 * static_cast<std::uint64_t>(ids.size()) + 4096 || cells <= indexed_ / 2;
  if (lv.dense) {
    // Counting sort by cell; ids are ascending, so each cell lists its balls by id.
    lv.cell_start.assign(cells + 1, 0);
    for (const std::uint64_t k : key) ++lv.cell_start[k + 1];
    for (std::uint64_t k = 0; k < cells; ++k) lv.cell_start[k + 1] += lv.cell_start[k];
    std::vector<std::uint32_t> fill(lv.cell_start.begin(), lv.cell_start.end() - 1);
    lv.members.resize(ids.size());
    for (std::size_t p = 0; p < ids.size(); ++p) lv.members[fill[key[p]]++] = ids[p];
    return;
  }

  std::vector<std::pair<std::uint64_t, std::uint32_t>> sorted(ids.size());
  for (std::size_t p = 0; p < ids.size(); ++p) sorted[p] = {key[p], ids[p]};
  std::sort(sorted.begin(), sorted.end());
  lv.members.resize(sorted.size());
  for (std::size_t p = 0; p < sorted.size(); ++p) {
    lv.members[p] = sorted[p].second;
    if (p == 0 || sorted[p].first != sorted[p - 1].first) {
      lv.keys.push_back(sorted[p].first);
      lv.cell_start.push_back(static_cast<std::uint32_t>(p));
    }
  }
  lv.cell_start.push_back(static_cast<std::uint32_t>(sorted.size()));
  lv.slots.assign(std::bit_ceil(2 * lv.keys.size()), 0);
  const std::uint64_t mask = lv.slots.size() - 1;
  for (std::size_t r = 0; r < lv.keys.size(); ++r) {
    std::uint64_t slot = mix(lv.keys[r]) & mask;
    while (lv.slots[slot] != 0) slot = (slot + 1) & mask;
    lv.slots[slot] = static_cast<std::uint32_t>(r + 1);
  }
}

template class CellList<2>;
template class CellList<3>;

}  // namespace fp
