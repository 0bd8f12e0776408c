#include "shapes/round_surface.hpp"

#include <algorithm>
#include <cmath>

namespace fp {

template <>
SurfaceMesh<2> capsule_surface<2>(double a, double r, int resolution) {
  SurfaceMesh<2> m;
  const int half = std::max(2, resolution / 2);
  // Right cap from -90 to +90 degrees around (+a, 0), then the left cap around (-a, 0).
  for (int side = 0; side < 2; ++side) {
    const double cx = side == 0 ? a : -a;
    for (int k = 0; k <= half; ++k) {
      const double t = -0.5 * kPi + kPi * k / half + side * kPi;
      m.vertices.push_back(Vec2(cx + r * std::cos(t), r * std::sin(t)));
    }
  }
  const int n = static_cast<int>(m.vertices.size());
  for (int i = 0; i < n; ++i) m.facets.push_back({i, (i + 1) % n});
  return m;
}

template <>
SurfaceMesh<3> capsule_surface<3>(double a, double r, int resolution) {
  SurfaceMesh<3> m;
  const int around = std::max(3, resolution);
  const int rings_per_cap = std::max(1, resolution / 4);
  // Rings from the -x pole to the +x pole; each cap is a hemisphere around its end point.
  std::vector<std::pair<double, double>> rings;  // (x, ring radius)
  for (int k = 1; k <= rings_per_cap; ++k) {
    const double t = 0.5 * kPi * k / rings_per_cap;  // from the pole
    rings.push_back({-a - r * std::cos(t), r * std::sin(t)});
  }
  for (int k = rings_per_cap - (a > 0 ? 0 : 1); k >= 1; --k) {
    const double t = 0.5 * kPi * k / rings_per_cap;
    rings.push_back({a + r * std::cos(t), r * std::sin(t)});
  }
  m.vertices.push_back(Vec3(-a - r, 0, 0));
  for (const auto& [x, rho] : rings)
    for (int j = 0; j < around; ++j) {
      const double p = 2 * kPi * j / around;
      m.vertices.push_back(Vec3(x, rho * std::cos(p), rho * std::sin(p)));
    }
  m.vertices.push_back(Vec3(a + r, 0, 0));
  const int nr = static_cast<int>(rings.size());
  const int last = static_cast<int>(m.vertices.size()) - 1;
  auto at = [&](int ring, int j) { return 1 + ring * around + (j % around); };
  for (int j = 0; j < around; ++j) m.facets.push_back({0, at(0, j + 1), at(0, j)});
  for (int q = 0; q + 1 < nr; ++q)
    for (int j = 0; j < around; ++j) {
      m.facets.push_back({at(q, j), at(q, j + 1), at(q + 1, j + 1)});
      m.facets.push_back({at(q, j), at(q + 1, j + 1), at(q + 1, j)});
    }
  for (int j = 0; j < around; ++j) m.facets.push_back({last, at(nr - 1, j), at(nr - 1, j + 1)});
  return m;
}

}  // namespace fp
