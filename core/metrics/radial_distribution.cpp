#include "core/metrics/radial_distribution.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/metrics/container_volume_fraction.hpp"
#include "core/system/parallel_parts.hpp"

namespace fp {
namespace {

// The kept centres bucketed in a uniform grid (counting sort by cell; copies of the centres are
// stored in cell order, so that a query reads memory in sequence), and the cell offsets that the
// ball of radius `reach` around any point of a cell can touch.
template <int D>
class CentreGrid {
 public:
  using Coords = std::array<std::int64_t, D>;

  CentreGrid(const std::vector<Vec<D>>& centers, const std::vector<char>& keep, double cell, double reach) {
    Aabb<D> box;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < centers.size(); ++i)
      if (keep[i]) box.extend(centers[i]), ++kept;
    origin_ = box.lo;
    // Coarsen until the dense cell table is O(N) (sparse or elongated packings).
    for (cell_ = cell;; cell_ *= 2.0) {
      double cells = 1.0;
      for (int a = 0; a < D; ++a) {
        dims_[a] = static_cast<std::int64_t>(std::floor((box.hi[a] - box.lo[a]) / cell_)) + 1;
        cells *= static_cast<double>(dims_[a]);
      }
      if (cells <= 4.0 * static_cast<double>(kept) + 4096.0) break;
    }
    std::int64_t cells = 1;
    for (int a = 0; a < D; ++a) stride_[a] = cells, cells *= dims_[a];
    start_.assign(static_cast<std::size_t>(cells) + 1, 0);
    for (std::size_t i = 0; i < centers.size(); ++i)
      if (keep[i]) ++start_[key(coords(centers[i])) + 1];
    for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
    ids_.resize(kept);
    points_.resize(kept);
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < centers.size(); ++i)
      if (keep[i]) {
        const std::uint32_t slot = fill[key(coords(centers[i]))]++;
        ids_[slot] = static_cast<std::uint32_t>(i);
        points_[slot] = centers[i];
      }

    const auto m = static_cast<std::int64_t>(std::ceil(reach / cell_));
    Coords o;
    o.fill(-m);
    for (;;) {
      double gap2 = 0.0;  // squared distance between the closest points of cell 0 and cell o
      for (int a = 0; a < D; ++a) {
        const double g = cell_ * static_cast<double>(std::max<std::int64_t>(std::abs(o[a]) - 1, 0));
        gap2 += g * g;
      }
      if (gap2 <= reach * reach) offsets_.push_back(o);
      int a = 0;
      while (a < D && o[a] == m) o[a++] = -m;
      if (a == D) break;
      ++o[a];
    }
  }

  /// visit(centre, slot) for every kept centre in the cells that the ball (p, reach) touches;
  /// id(slot) is its index in the packing.
  template <class Visit>
  void for_each_near(const Vec<D>& p, Visit&& visit) const {
    const Coords c = coords(p);
    for (const Coords& o : offsets_) {
      Coords n;
      bool in = true;
      for (int a = 0; a < D; ++a) {
        n[a] = c[a] + o[a];
        in = in && n[a] >= 0 && n[a] < dims_[a];
      }
      if (!in) continue;
      const std::int64_t k = key(n);
      for (std::uint32_t q = start_[k]; q < start_[k + 1]; ++q) visit(points_[q], q);
    }
  }
  std::uint32_t id(std::uint32_t slot) const { return ids_[slot]; }
  /// Linear index of the cell holding p (queries in this order reuse the cache).
  std::int64_t cell_of(const Vec<D>& p) const { return key(coords(p)); }

 private:
  Coords coords(const Vec<D>& p) const {
    Coords c;
    for (int a = 0; a < D; ++a) {
      const auto k = static_cast<std::int64_t>(std::floor((p[a] - origin_[a]) / cell_));
      c[a] = std::clamp<std::int64_t>(k, 0, dims_[a] - 1);
    }
    return c;
  }
  std::int64_t key(const Coords& c) const {
    std::int64_t k = 0;
    for (int a = 0; a < D; ++a) k += c[a] * stride_[a];
    return k;
  }

  Vec<D> origin_;
  double cell_ = 0.0;
  Coords dims_{}, stride_{};
  std::vector<std::uint32_t> start_, ids_;
  std::vector<Vec<D>> points_;
  std::vector<Coords> offsets_;
};

}  // namespace

template <int D>
RadialDistribution radial_distribution(const Packing<D>& packing, const Container<D>& container,
                                       const RdfOptions& options, int threads) {
  if (!(options.range > 0.0) || !std::isfinite(options.range) || options.bins < 1 || options.max_reference < 1)
    throw std::invalid_argument("radial_distribution: need range > 0, bins >= 1 and max_reference >= 1");
  const std::size_t n = packing.size();
  std::vector<char> usable(n, 0);
  double sum_r = 0.0, r_max = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = packing.radii[i];
    if (!(r > 0.0) || !std::isfinite(r) || !packing.centers[i].allFinite()) continue;
    usable[i] = 1;
    sum_r += r;
    r_max = std::max(r_max, r);
    ++count;
  }

  RadialDistribution out;
  out.range = options.range;
  const auto bins = static_cast<std::size_t>(options.bins);
  const double width = options.range / options.bins;  // in mean diameters
  for (std::size_t k = 0; k < bins; ++k) out.r.push_back((static_cast<double>(k) + 0.5) * width);
  out.g.assign(bins, 0.0);
  if (count == 0) return out;
  out.mean_diameter = 2.0 * sum_r / static_cast<double>(count);
  const double r_cut = options.range * out.mean_diameter;
  out.reference_margin = r_cut + r_max;

  std::vector<std::uint32_t> eligible;
  for (std::size_t i = 0; i < n; ++i)
    if (usable[i] && container.contains_ball(packing.centers[i], out.reference_margin, 0.0))  // signed distance <= -margin
      eligible.push_back(static_cast<std::uint32_t>(i));
  out.eligible_particles = eligible.size();
  out.reference_measure = region_measure(container, out.reference_margin, options.qmc);
  if (eligible.empty() || !(out.reference_measure.value > 0.0)) return out;
  out.density = static_cast<double>(eligible.size()) / out.reference_measure.value;
  const std::size_t step = (eligible.size() + options.max_reference - 1) / options.max_reference;

  const CentreGrid<D> grid(packing.centers, usable, r_cut / 3.0, r_cut);
  std::vector<std::pair<std::int64_t, std::uint32_t>> refs;  // (cell, id), visited in cell order
  for (std::size_t e = 0; e < eligible.size(); e += step)
    refs.emplace_back(grid.cell_of(packing.centers[eligible[e]]), eligible[e]);
  std::sort(refs.begin(), refs.end());
  out.reference_particles = refs.size();

  const double to_bin = 1.0 / (width * out.mean_diameter), r_cut2 = r_cut * r_cut;
  // Counts per part of the references (runs of cells), summed: the same for any thread count.
  const std::size_t parts = 8 * static_cast<std::size_t>(std::max(threads, 1));
  std::vector<std::vector<std::uint64_t>> part_hits(parts, std::vector<std::uint64_t>(bins, 0));
  for_each_part(parts, threads, [&](std::size_t part) {
    std::vector<std::uint64_t>& hits = part_hits[part];
    const auto [first, last] = part_range(refs.size(), part, parts);
    for (std::size_t r = first; r < last; ++r) {
      const std::uint32_t i = refs[r].second;
      const Vec<D>& c = packing.centers[i];
      grid.for_each_near(c, [&](const Vec<D>& q, std::uint32_t slot) {
        const double d2 = (q - c).squaredNorm();
        if (d2 >= r_cut2 || (d2 == 0.0 && grid.id(slot) == i)) return;
        const auto k = static_cast<std::size_t>(std::sqrt(d2) * to_bin);
        if (k < bins) ++hits[k];
      });
    }
  });
  std::vector<std::uint64_t> hits(bins, 0);
  for (const std::vector<std::uint64_t>& h : part_hits)
    for (std::size_t k = 0; k < bins; ++k) hits[k] += h[k];

  const double ideal = static_cast<double>(out.reference_particles) * out.density;
  for (std::size_t k = 0; k < bins; ++k) {
    const double lo = static_cast<double>(k) * width * out.mean_diameter;
    const double shell = ball_measure<D>(lo + width * out.mean_diameter) - ball_measure<D>(lo);
    out.g[k] = static_cast<double>(hits[k]) / (ideal * shell);
  }
  return out;
}

template RadialDistribution radial_distribution<2>(const Packing<2>&, const Container<2>&, const RdfOptions&, int);
template RadialDistribution radial_distribution<3>(const Packing<3>&, const Container<3>&, const RdfOptions&, int);

}  // namespace fp
