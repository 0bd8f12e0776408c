#include "core/metrics/homogeneity.hpp"

#include <algorithm>
#include <cmath>

#include "core/metrics/qmc.hpp"

namespace fp {
namespace {

template <int D>
bool usable(const Packing<D>& packing, std::size_t i) {
  return std::isfinite(packing.radii[i]) && packing.centers[i].allFinite();
}

}  // namespace

template <int D>
CentreHomogeneity centre_homogeneity(const Packing<D>& packing, const Aabb<D>& bounds, double margin) {
  CentreHomogeneity out;
  out.margin = margin;
  Vec<D> lo, hi;
  for (int a = 0; a < D; ++a) {
    lo[a] = bounds.lo[a] + margin, hi[a] = bounds.hi[a] - margin;
    out.lo.push_back(lo[a]);
    out.hi.push_back(hi[a]);
  }
  std::vector<std::size_t> core;
  for (std::size_t i = 0; i < packing.size(); ++i)
    if (usable(packing, i) && (packing.centers[i].array() >= lo.array()).all() && (packing.centers[i].array() <= hi.array()).all())
      core.push_back(i);
  std::vector<double> x;
  for (int a = 0; a < D; ++a) {
    if (!(hi[a] > lo[a])) {
      out.axis.emplace_back();
      continue;
    }
    x.clear();
    for (const std::size_t i : core) x.push_back(packing.centers[i][a]);
    const double from = lo[a], to = hi[a];
    out.axis.push_back(ks_one_sample(x, [from, to](double v) { return std::clamp((v - from) / (to - from), 0.0, 1.0); }));
  }
  return out;
}

template <int D>
CentreHomogeneity centre_homogeneity(const Packing<D>& packing, const Container<D>& container, double margin,
                                     std::size_t points) {
  const Aabb<D> bounds = container.bounds();
  double box_measure = 1.0;
  for (int a = 0; a < D; ++a) box_measure *= bounds.hi[a] - bounds.lo[a];
  if (std::abs(container.measure() - box_measure) <= 1e-12 * box_measure) return centre_homogeneity(packing, bounds, margin);
  CentreHomogeneity out;
  out.margin = margin;
  std::vector<std::vector<double>> reference(D);
  for (const Vec<D>& u : halton_points<D>(points)) {
    const Vec<D> p = bounds.lo + (u.array() * (bounds.hi - bounds.lo).array()).matrix();
    if (container.signed_distance(p) <= -margin)
      for (int a = 0; a < D; ++a) reference[a].push_back(p[a]);
  }
  out.reference_points = reference[0].size();
  std::vector<std::size_t> core;
  for (std::size_t i = 0; i < packing.size(); ++i)
    if (usable(packing, i) && container.signed_distance(packing.centers[i]) <= -margin) core.push_back(i);
  std::vector<double> x;
  for (int a = 0; a < D; ++a) {
    std::vector<double>& ref = reference[a];
    std::sort(ref.begin(), ref.end());
    out.lo.push_back(ref.empty() ? NAN : ref.front());
    out.hi.push_back(ref.empty() ? NAN : ref.back());
    if (ref.empty()) {
      out.axis.emplace_back();
      continue;
    }
    x.clear();
    for (const std::size_t i : core) x.push_back(packing.centers[i][a]);
    const double m = static_cast<double>(ref.size());
    out.axis.push_back(ks_one_sample(x, [&ref, m](double v) {
      return static_cast<double>(std::upper_bound(ref.begin(), ref.end(), v) - ref.begin()) / m;
    }));
  }
  return out;
}

template CentreHomogeneity centre_homogeneity<2>(const Packing<2>&, const Aabb<2>&, double);
template CentreHomogeneity centre_homogeneity<3>(const Packing<3>&, const Aabb<3>&, double);
template CentreHomogeneity centre_homogeneity<2>(const Packing<2>&, const Container<2>&, double, std::size_t);
template CentreHomogeneity centre_homogeneity<3>(const Packing<3>&, const Container<3>&, double, std::size_t);

}  // namespace fp
