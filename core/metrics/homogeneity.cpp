#include "core/metrics/homogeneity.hpp"

#include <algorithm>
#include <cmath>

namespace fp {

template <int D>
CentreHomogeneity centre_homogeneity(const Packing<D>& packing, const Aabb<D>& bounds, double margin) {
  CentreHomogeneity out;
  out.margin = margin;
  std::vector<double> x;
  x.reserve(packing.size());
  for (int a = 0; a < D; ++a) {
    const double lo = bounds.lo[a] + margin, hi = bounds.hi[a] - margin;
    out.lo.push_back(lo);
    out.hi.push_back(hi);
    x.clear();
    for (std::size_t i = 0; i < packing.size(); ++i)
      if (std::isfinite(packing.radii[i]) && packing.centers[i].allFinite()) x.push_back(packing.centers[i][a]);
    if (!(hi > lo)) {
      out.axis.emplace_back();
      continue;
    }
    out.axis.push_back(ks_one_sample(x, [lo, hi](double v) { return std::clamp((v - lo) / (hi - lo), 0.0, 1.0); }));
  }
  return out;
}

template CentreHomogeneity centre_homogeneity<2>(const Packing<2>&, const Aabb<2>&, double);
template CentreHomogeneity centre_homogeneity<3>(const Packing<3>&, const Aabb<3>&, double);

}  // namespace fp
