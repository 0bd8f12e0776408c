#include "core/metrics/cell_volume_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/metrics/ball_box.hpp"
#include "core/metrics/compensated_sum.hpp"

namespace fp {

template <int D>
CellVolumeFraction cell_volume_fraction(const Packing<D>& packing, const Container<D>& container, double edge,
                                        double margin) {
  if (!(edge > 0.0) || !std::isfinite(edge)) throw std::invalid_argument("cell_volume_fraction: edge must be > 0");
  if (!(margin >= 0.0) || !std::isfinite(margin)) throw std::invalid_argument("cell_volume_fraction: margin must be >= 0");
  CellVolumeFraction out;
  out.edge = edge;
  out.margin = margin;
  const Aabb<D> box = container.bounds();
  std::array<std::int64_t, D> n{};
  double total = 1.0;
  for (int k = 0; k < D; ++k) {
    n[k] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor((box.hi[k] - box.lo[k]) / edge)));
    total *= static_cast<double>(n[k]);
  }
  if (total > static_cast<double>(1 << 26)) throw std::invalid_argument("cell_volume_fraction: too many cells");
  // Which cells count (-1: not), and their solid measure.
  const double reach = std::sqrt(static_cast<double>(D)) * edge / 2 + margin;
  std::vector<std::int64_t> slot(static_cast<std::size_t>(total), -1);
  std::vector<Vec<D>> lows;
  for (std::size_t flat = 0; flat < slot.size(); ++flat) {
    Vec<D> lo;
    std::size_t rest = flat;
    for (int k = 0; k < D; ++k) {
      lo[k] = box.lo[k] + static_cast<double>(rest % static_cast<std::size_t>(n[k])) * edge;
      rest /= static_cast<std::size_t>(n[k]);
    }
    if (container.signed_distance(lo + Vec<D>::Constant(edge / 2)) <= -reach) {
      slot[flat] = static_cast<std::int64_t>(lows.size());
      lows.push_back(lo);
    }
  }
  out.cells = lows.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (lows.empty()) {
    out.mean = out.std_dev = out.min = out.max = out.worst = nan;
    return out;
  }
  std::vector<CompensatedSum> solid(lows.size());
  for (std::size_t i = 0; i < packing.size(); ++i) {
    const Vec<D>& c = packing.centers[i];
    const double r = packing.radii[i];
    if (!(r > 0.0) || !std::isfinite(r) || !c.allFinite()) continue;
    std::array<std::int64_t, D> from{}, to{};
    bool none = false;
    for (int k = 0; k < D; ++k) {
      from[k] = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor((c[k] - r - box.lo[k]) / edge)));
      to[k] = std::min<std::int64_t>(n[k] - 1, static_cast<std::int64_t>(std::floor((c[k] + r - box.lo[k]) / edge)));
      none |= from[k] > to[k];
    }
    if (none) continue;
    std::array<std::int64_t, D> at = from;
    for (;;) {
      std::int64_t flat = 0;
      for (int k = D - 1; k >= 0; --k) flat = flat * n[k] + at[k];
      if (const std::int64_t s = slot[static_cast<std::size_t>(flat)]; s >= 0) {
        const Vec<D>& lo = lows[static_cast<std::size_t>(s)];
        solid[static_cast<std::size_t>(s)].add(ball_box_measure<D>(c, r, lo, lo + Vec<D>::Constant(edge)));
      }
      int k = 0;
      while (k < D && at[k] == to[k]) at[k] = from[k], ++k;
      if (k == D) break;
      ++at[k];
    }
  }
  const double cell = std::pow(edge, D);
  std::vector<double> vf(lows.size());
  CompensatedSum sum;
  for (std::size_t s = 0; s < lows.size(); ++s) sum.add(vf[s] = solid[s].value() / cell);
  out.mean = sum.value() / static_cast<double>(vf.size());
  CompensatedSum squares;
  std::size_t worst = 0;
  for (std::size_t s = 0; s < vf.size(); ++s) {
    squares.add((vf[s] - out.mean) * (vf[s] - out.mean));
    if (std::abs(vf[s] - out.mean) > std::abs(vf[worst] - out.mean)) worst = s;
  }
  out.std_dev = std::sqrt(squares.value() / static_cast<double>(vf.size()));
  out.min = *std::min_element(vf.begin(), vf.end());
  out.max = *std::max_element(vf.begin(), vf.end());
  out.worst = vf[worst];
  const Vec<D> centre = lows[worst] + Vec<D>::Constant(edge / 2) + container.origin();
  out.worst_centre.assign(centre.data(), centre.data() + D);
  return out;
}

template <int D>
CellVolumeFraction cell_volume_fraction_auto(const Packing<D>& packing, const Container<D>& container, double r_mean,
                                             double r_max, double diameters, std::uint64_t min_cells) {
  CellVolumeFraction out;
  if (!(r_mean > 0.0) || !std::isfinite(r_mean)) return out;
  const Aabb<D> box = container.bounds();
  for (double d = diameters; d >= 2.0; d /= 2) {
    const double edge = 2 * r_mean * d;
    double cells = 1.0;
    for (int k = 0; k < D; ++k) cells *= std::max(1.0, std::floor((box.hi[k] - box.lo[k]) / edge));
    if (cells > static_cast<double>(1 << 26)) break;  // smaller cells only have more
    out = cell_volume_fraction(packing, container, edge, 2 * r_max);
    out.diameters = d;
    if (out.cells >= min_cells) break;
  }
  return out;
}

template CellVolumeFraction cell_volume_fraction<2>(const Packing<2>&, const Container<2>&, double, double);
template CellVolumeFraction cell_volume_fraction<3>(const Packing<3>&, const Container<3>&, double, double);
template CellVolumeFraction cell_volume_fraction_auto<2>(const Packing<2>&, const Container<2>&, double, double, double,
                                                         std::uint64_t);
template CellVolumeFraction cell_volume_fraction_auto<3>(const Packing<3>&, const Container<3>&, double, double, double,
                                                         std::uint64_t);

}  // namespace fp
