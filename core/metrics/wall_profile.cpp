#include "core/metrics/wall_profile.hpp"

#include <cmath>
#include <stdexcept>

namespace fp {
namespace {

/// Solid and measure of a region, with their standard errors.
struct RegionSolid {
  Estimate solid, measure;
};

template <int D, class Bodies>
WallProfile profile_of(const Bodies& bodies, const Container<D>& container, double width, int shells, const QmcOptions& qmc) {
  if (!(width > 0.0) || !std::isfinite(width)) throw std::invalid_argument("wall_profile: the shell width must be positive");
  auto region = [&](double shrink) {
    const RegionVolumeFraction r = vf_region<D>(bodies, container, shrink, qmc);
    RegionSolid s;
    s.measure = r.measure;
    if (r.measure.value > 0.0) {
      s.solid.value = r.vf.value * r.measure.value;
      // d(vf M) = M d(vf) + vf d(M), the two taken as independent.
      s.solid.std_error = std::hypot(r.measure.value * r.vf.std_error, r.vf.value * r.measure.std_error);
    }
    return s;
  };
  auto between = [](const RegionSolid& outer, const RegionSolid& inner) {
    Estimate vf;
    const double m = outer.measure.value - inner.measure.value;
    if (!(m > 0.0)) return vf;
    vf.value = (outer.solid.value - inner.solid.value) / m;
    const double ds = std::hypot(outer.solid.std_error, inner.solid.std_error);
    const double dm = std::hypot(outer.measure.std_error, inner.measure.std_error);
    vf.std_error = std::hypot(ds / m, vf.value * dm / m);
    return vf;
  };
  WallProfile p;
  p.width = width;
  const RegionSolid whole = region(0.0);
  RegionSolid outer = whole, last = whole;
  for (int k = 0; k < shells; ++k) {
    const RegionSolid inner = region((k + 1) * width);
    if (!(outer.measure.value - inner.measure.value > 0.0)) break;
    p.vf.push_back(between(outer, inner));
    outer = last = inner;
  }
  if (p.computed()) p.layer = between(whole, last);
  return p;
}

}  // namespace

template <int D>
WallProfile wall_profile(const Packing<D>& packing, const Container<D>& container, double width, int shells, const QmcOptions& qmc) {
  return profile_of<D>(packing, container, width, shells, qmc);
}

template <int D>
WallProfile wall_profile(const RegionBodies<D>& bodies, const Container<D>& container, double width, int shells,
                         const QmcOptions& qmc) {
  return profile_of<D>(bodies, container, width, shells, qmc);
}

template WallProfile wall_profile<2>(const Packing<2>&, const Container<2>&, double, int, const QmcOptions&);
template WallProfile wall_profile<3>(const Packing<3>&, const Container<3>&, double, int, const QmcOptions&);
template WallProfile wall_profile<2>(const RegionBodies<2>&, const Container<2>&, double, int, const QmcOptions&);
template WallProfile wall_profile<3>(const RegionBodies<3>&, const Container<3>&, double, int, const QmcOptions&);

}  // namespace fp
