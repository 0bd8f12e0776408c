#include "core/metrics/contact_normals.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fp {

template <int D>
double isotropic_projection_cdf(double t) {
  const double u = std::clamp(t, 0.0, 1.0);
  if constexpr (D == 3) return u;
  else return 2.0 / kPi * std::asin(u);
}

template <int D>
RelativeProjections relative_projections(const std::vector<Vec<D>>& directions, int bins) {
  if (bins < 1) throw std::invalid_argument("relative_projections: bins must be >= 1");
  RelativeProjections out;
  out.bins = bins;
  out.reference = D == 3 ? "uniform on [0, 1]" : "arcsine, (2/pi) asin t";
  std::vector<std::vector<double>> proj(D);
  for (auto& p : proj) p.reserve(directions.size());
  for (const Vec<D>& d : directions) {
    const double len = d.norm();
    if (!(len > 0.0)) continue;
    for (int a = 0; a < D; ++a) proj[a].push_back(std::min(1.0, std::abs(d[a]) / len));
  }
  out.contacts = proj[0].size();
  for (int a = 0; a < D; ++a) {
    std::vector<std::uint64_t> h(static_cast<std::size_t>(bins), 0);
    for (const double t : proj[a]) ++h[std::min(static_cast<std::size_t>(t * bins), h.size() - 1)];
    out.histogram.push_back(std::move(h));
    out.ks.push_back(ks_one_sample(std::move(proj[a]), isotropic_projection_cdf<D>));
  }
  return out;
}

template <int D>
RelativeProjections relative_projections(const Packing<D>& packing, const std::vector<PairContact>& contacts,
                                         int bins) {
  return relative_projections<D>(centre_lines(packing, contacts), bins);
}

template double isotropic_projection_cdf<2>(double);
template double isotropic_projection_cdf<3>(double);
template RelativeProjections relative_projections<2>(const Packing<2>&, const std::vector<PairContact>&, int);
template RelativeProjections relative_projections<3>(const Packing<3>&, const std::vector<PairContact>&, int);
template RelativeProjections relative_projections<2>(const std::vector<Vec<2>>&, int);
template RelativeProjections relative_projections<3>(const std::vector<Vec<3>>&, int);

}  // namespace fp
