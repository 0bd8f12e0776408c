#include "core/metrics/bed_profile.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <utility>

#include <Eigen/Geometry>

#include "core/metrics/ball_box.hpp"
#include "core/metrics/compensated_sum.hpp"

namespace fp {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The measure of a ball's part below a plane at signed height t over its centre.
template <int D>
double ball_below(double r, double t) {
  if (t <= -r) return 0.0;
  if (t >= r) return ball_measure<D>(r);
  return ball_inside_plane<D>(r, t);
}

/// The slabs' edges (heights above the floor) and their exact measures.
template <int D>
BedProfile slabs_of(const BedRegion<D>& bed, double r_max, std::vector<double>& edges, std::vector<double>& measures) {
  BedProfile p;
  p.height = bed.height();
  // Slabs of at most r_max / 2 (at most kMaxBedSlabs of them) that end exactly at the level.
  const double most = std::max(0.5 * r_max, p.height / kMaxBedSlabs);
  const auto count = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(p.height / most)));
  p.width = p.height / static_cast<double>(count);
  edges.clear();
  for (std::size_t k = 0; k < count; ++k) edges.push_back(static_cast<double>(k) * p.width);
  edges.push_back(p.height);
  double below = 0.0;
  measures.clear();
  for (std::size_t k = 1; k < edges.size(); ++k) {
    const double up_to = bed.measure_up_to(edges[k]);
    measures.push_back(up_to - below);
    below = up_to;
  }
  return p;
}

/// Bulk, top layer and half-bulk height from the slabs' solids (with their errors) and measures.
void summarise(BedProfile& p, const std::vector<double>& edges, const std::vector<Estimate>& solid,
               const std::vector<double>& measures, double r_max) {
  auto over = [&](double from, double to) {
    double s = 0.0, e2 = 0.0, m = 0.0;
    for (std::size_t k = 0; k < measures.size(); ++k)
      if (edges[k] >= from - 1e-12 * p.height && edges[k + 1] <= to + 1e-12 * p.height)
        s += solid[k].value, e2 += solid[k].std_error * solid[k].std_error, m += measures[k];
    return m > 0.0 ? Estimate{s / m, std::sqrt(e2) / m} : Estimate{kNaN, 0.0};
  };
  for (std::size_t k = 0; k < measures.size(); ++k)
    p.vf.push_back(measures[k] > 0.0 ? Estimate{solid[k].value / measures[k], solid[k].std_error / measures[k]} : Estimate{0.0, 0.0});
  p.bulk = over(2.0 * r_max, p.height - 2.0 * r_max);
  p.top_layer = over(p.height - 2.0 * r_max, p.height);
  p.half_bulk_height = kNaN;
  if (!std::isfinite(p.bulk.value)) return;
  const double half = 0.5 * p.bulk.value;
  for (std::size_t k = p.vf.size(); k-- > 0;) {
    if (p.vf[k].value < half) continue;
    if (k + 1 == p.vf.size()) { p.half_bulk_height = p.height; break; }
    // Between slab k's middle (at or above half) and slab k + 1's (below it).
    const double a = p.middle(k), b = p.middle(k + 1), va = p.vf[k].value, vb = p.vf[k + 1].value;
    p.half_bulk_height = a + (va - half) / (va - vb) * (b - a);
    break;
  }
}

/// The highest top over the columns of 4 r_max across `up` (a lattice in a frame of the plane)
/// that are clear of the walls: a column counts when its corners, 2 r_max under the level, lie a
/// radius inside the walls (the columns the walls cut short hold the few particles that fit
/// there and say nothing of the top). `tops[i]`: particle i's highest point above the floor.
template <int D>
BedSurfaceTops surface_tops(const std::vector<Vec<D>>& centres, const std::vector<double>& tops, const BedRegion<D>& bed,
                            double r_max) {
  Eigen::Matrix<double, D, D - 1> across;
  if constexpr (D == 3) {
    const Vec3 a = bed.up().unitOrthogonal();
    across.col(0) = a;
    across.col(1) = bed.up().cross(a);
  } else {
    across.col(0) = Vec2(-bed.up().y(), bed.up().x());
  }
  const double column = 4.0 * r_max;
  std::map<std::array<long long, D - 1>, double> highest;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    if (!centres[i].allFinite() || !std::isfinite(tops[i])) continue;
    std::array<long long, D - 1> key;
    const Eigen::Matrix<double, D - 1, 1> at = across.transpose() * centres[i];
    for (int a = 0; a < D - 1; ++a) key[static_cast<std::size_t>(a)] = static_cast<long long>(std::floor(at[a] / column));
    auto [it, added] = highest.emplace(key, tops[i]);
    if (!added) it->second = std::max(it->second, tops[i]);
  }
  for (auto it = highest.begin(); it != highest.end();) {
    bool inside = true;
    for (int corner = 0; corner < (1 << (D - 1)) && inside; ++corner) {
      Vec<D> at = (bed.level() - 2.0 * r_max) * bed.up();
      for (int a = 0; a < D - 1; ++a)
        at += (static_cast<double>(it->first[static_cast<std::size_t>(a)] + ((corner >> a) & 1)) * column) * across.col(a);
      inside = bed.signed_distance(at) <= -r_max;
    }
    it = inside ? std::next(it) : highest.erase(it);
  }
  BedSurfaceTops t;
  if (highest.empty()) return t;
  t.columns = highest.size();
  t.min = std::numeric_limits<double>::infinity();
  t.max = -t.min;
  double sum = 0.0, sum2 = 0.0;
  for (const auto& [key, top] : highest) sum += top, t.min = std::min(t.min, top), t.max = std::max(t.max, top);
  t.mean = sum / static_cast<double>(highest.size());
  for (const auto& [key, top] : highest) sum2 += (top - t.mean) * (top - t.mean);
  t.std_dev = std::sqrt(sum2 / static_cast<double>(highest.size()));
  return t;
}

}  // namespace

double BedProfile::middle(std::size_t k) const { return (static_cast<double>(k) + 0.5) * width; }

template <int D>
BedProfile bed_profile(const Packing<D>& packing, const BedRegion<D>& bed, double r_max) {
  std::vector<double> edges, measures;
  BedProfile p = slabs_of(bed, r_max, edges, measures);
  const std::size_t slabs = measures.size();
  std::vector<CompensatedSum> solid(slabs);
  std::vector<Vec<D>> centres;
  std::vector<double> tops;
  for (std::size_t i = 0; i < packing.size(); ++i) {
    const double r = packing.radii[i];
    const Vec<D>& c = packing.centers[i];
    if (!(r > 0.0) || !std::isfinite(r) || !c.allFinite()) continue;
    const double h = bed.up().dot(c) - bed.floor_level();  // the centre's height above the floor
    const auto first = static_cast<std::size_t>(std::clamp(std::floor((h - r) / p.width), 0.0, static_cast<double>(slabs - 1)));
    for (std::size_t k = first; k < slabs && edges[k] < h + r; ++k)
      solid[k].add(ball_below<D>(r, edges[k + 1] - h) - ball_below<D>(r, edges[k] - h));
    centres.push_back(c);
    tops.push_back(h + r);
  }
  std::vector<Estimate> exact;
  for (const CompensatedSum& s : solid) exact.push_back({s.value(), 0.0});
  summarise(p, edges, exact, measures, r_max);
  p.surface = surface_tops<D>(centres, tops, bed, r_max);
  return p;
}

template <int D>
BedProfile bed_profile(const RegionBodies<D>& bodies, const BedRegion<D>& bed, double r_max, const QmcOptions& qmc,
                       const std::vector<double>& tops) {
  std::vector<double> edges, measures;
  BedProfile p = slabs_of(bed, r_max, edges, measures);
  // The solid below each edge through vf_region of the bed filled to it; a slab's is the difference.
  std::vector<Estimate> below(edges.size());
  for (std::size_t k = 1; k < edges.size(); ++k) {
    const BedRegion<D> cut = bed.filled_to(edges[k]);
    const RegionVolumeFraction r = vf_region<D>(bodies, cut, 0.0, qmc);
    below[k] = {r.vf.value * r.measure.value, r.vf.std_error * r.measure.value};
  }
  std::vector<Estimate> solid;
  for (std::size_t k = 0; k + 1 < edges.size(); ++k)
    solid.push_back({below[k + 1].value - below[k].value, std::hypot(below[k + 1].std_error, below[k].std_error)});
  summarise(p, edges, solid, measures, r_max);
  if (!tops.empty()) {
    std::vector<double> above_floor;
    for (const double t : tops) above_floor.push_back(t - bed.floor_level());
    p.surface = surface_tops<D>(bodies.centres, above_floor, bed, r_max);
  }
  return p;
}

template BedProfile bed_profile<2>(const Packing<2>&, const BedRegion<2>&, double);
template BedProfile bed_profile<3>(const Packing<3>&, const BedRegion<3>&, double);
template BedProfile bed_profile<2>(const RegionBodies<2>&, const BedRegion<2>&, double, const QmcOptions&,
                                   const std::vector<double>&);
template BedProfile bed_profile<3>(const RegionBodies<3>&, const BedRegion<3>&, double, const QmcOptions&,
                                   const std::vector<double>&);

}  // namespace fp
