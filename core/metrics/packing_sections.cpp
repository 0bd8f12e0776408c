#include "core/metrics/packing_sections.hpp"

#include <cmath>

namespace fp {
namespace {

/// The zero level of f on a grid of the rectangle [lo, hi] (n x n cells), as segments by
/// marching squares with linear interpolation along the cell edges (a saddle cell: both of its
/// segment pairs, joined the same way every time).
template <class F>
std::vector<std::array<double, 4>> zero_level(const F& f, double u0, double v0, double u1, double v1, int n) {
  std::vector<std::array<double, 4>> out;
  const double du = (u1 - u0) / n, dv = (v1 - v0) / n;
  std::vector<double> row(n + 1), next(n + 1);
  for (int i = 0; i <= n; ++i) row[i] = f(u0 + i * du, v0);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i <= n; ++i) next[i] = f(u0 + i * du, v0 + (j + 1) * dv);
    for (int i = 0; i < n; ++i) {
      // Corners counter-clockwise from (i, j); a point on an edge where f changes sign.
      const double c[4] = {row[i], row[i + 1], next[i + 1], next[i]};
      const double cu[4] = {u0 + i * du, u0 + (i + 1) * du, u0 + (i + 1) * du, u0 + i * du};
      const double cv[4] = {v0 + j * dv, v0 + j * dv, v0 + (j + 1) * dv, v0 + (j + 1) * dv};
      std::array<double, 2> cut[4];
      int cuts = 0;
      for (int e = 0; e < 4; ++e) {
        const int a = e, b = (e + 1) % 4;
        if ((c[a] < 0) == (c[b] < 0)) continue;
        const double t = c[a] / (c[a] - c[b]);
        cut[cuts++] = {cu[a] + t * (cu[b] - cu[a]), cv[a] + t * (cv[b] - cv[a])};
      }
      for (int k = 0; k + 1 < cuts; k += 2) out.push_back({cut[k][0], cut[k][1], cut[k + 1][0], cut[k + 1][1]});
    }
    row.swap(next);
  }
  return out;
}

}  // namespace

template <int D>
std::vector<PackingSection> section_planes(const Container<D>& container, const Vec<D>& origin, int grid) {
  const Aabb<D> bounds = container.bounds();
  const Vec<D> middle = (bounds.lo + bounds.hi) / 2;
  std::vector<PackingSection> out;
  const int planes = D == 3 ? 3 : 1;
  for (int k = 0; k < planes; ++k) {
    PackingSection s;
    s.normal_axis = D == 3 ? k : 2;
    s.u_axis = D == 3 ? (k == 0 ? 1 : 0) : 0;
    s.v_axis = D == 3 ? (k == 2 ? 1 : 2) : 1;
    s.local_offset = D == 3 ? middle[k] : 0.0;
    s.offset = D == 3 ? middle[k] + origin[k] : 0.0;
    const int U = s.u_axis, V = s.v_axis;
    // The outline on the bounds padded by 2 % (a boundary on the bounds still changes sign).
    const double pu = 0.02 * (bounds.hi[U] - bounds.lo[U]), pv = 0.02 * (bounds.hi[V] - bounds.lo[V]);
    const auto f = [&](double u, double v) {
      Vec<D> p = middle;
      p[U] = u, p[V] = v;
      return container.signed_distance(p);
    };
    s.outline = zero_level(f, bounds.lo[U] - pu, bounds.lo[V] - pv, bounds.hi[U] + pu, bounds.hi[V] + pv, grid);
    for (auto& seg : s.outline) {
      seg[0] += origin[U], seg[2] += origin[U];
      seg[1] += origin[V], seg[3] += origin[V];
    }
    out.push_back(std::move(s));
  }
  return out;
}

template <int D>
std::vector<PackingSection> packing_sections(const Packing<D>& packing, const Container<D>& container, int grid) {
  std::vector<PackingSection> out = section_planes<D>(container, packing.origin, grid);
  for (PackingSection& s : out) {
    const int k = s.normal_axis, U = s.u_axis, V = s.v_axis;
    const double c = s.local_offset;
    for (std::size_t i = 0; i < packing.size(); ++i) {
      const double r = packing.radii[i];
      if (!std::isfinite(r) || !packing.centers[i].allFinite()) continue;
      const double h = D == 3 ? packing.centers[i][k] - c : 0.0;
      if (!(std::abs(h) < r)) continue;
      s.disks.push_back({packing.centers[i][U] + packing.origin[U], packing.centers[i][V] + packing.origin[V],
                         std::sqrt((r - h) * (r + h)), r});
    }
  }
  return out;
}

template std::vector<PackingSection> section_planes<2>(const Container<2>&, const Vec<2>&, int);
template std::vector<PackingSection> section_planes<3>(const Container<3>&, const Vec<3>&, int);
template std::vector<PackingSection> packing_sections<2>(const Packing<2>&, const Container<2>&, int);
template std::vector<PackingSection> packing_sections<3>(const Packing<3>&, const Container<3>&, int);

}  // namespace fp
