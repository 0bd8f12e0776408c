#pragma once
// Shared helpers of the metrics tests: lattices with integer coordinates (so that the expected
// neighbours of every site are known exactly), jittered random packings, brute-force pair lists.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "core/geometry/packing.hpp"
#include "core/sampling/rng.hpp"

namespace fp::test {

/// Lattice sites as integer coordinates, their packing (centre = origin + unit * site) and the
/// integer offsets of the nearest neighbours.
template <int D>
struct Lattice {
  std::vector<std::array<int, D>> sites;
  std::vector<std::array<int, D>> neighbour_offsets;
  Packing<D> packing;

  /// Expected particle-particle coordination of every site: neighbours present in the lattice.
  std::vector<std::uint32_t> expected_coordination() const {
    std::map<std::array<int, D>, int> index;
    for (std::size_t i = 0; i < sites.size(); ++i) index[sites[i]] = static_cast<int>(i);
    std::vector<std::uint32_t> z(sites.size(), 0);
    for (std::size_t i = 0; i < sites.size(); ++i)
      for (const auto& o : neighbour_offsets) {
        std::array<int, D> n = sites[i];
        for (int a = 0; a < D; ++a) n[a] += o[a];
        z[i] += index.count(n) ? 1 : 0;
      }
    return z;
  }
};

/// n^3 simple cubic sites, spacing = unit, touching spheres of radius unit / 2.
inline Lattice<3> simple_cubic(int n, double unit, const Vec3& origin) {
  Lattice<3> l;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        l.sites.push_back({i, j, k});
        l.packing.add(origin + unit * Vec3(i, j, k), 0.5 * unit);
      }
  l.neighbour_offsets = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  return l;
}

/// FCC: integer sites in [0, 2n)^3 with an even coordinate sum, unit = half the cubic cell,
/// touching spheres of radius unit / sqrt(2). 4 n^3 sites.
inline Lattice<3> fcc(int n, double unit, const Vec3& origin) {
  Lattice<3> l;
  for (int i = 0; i < 2 * n; ++i)
    for (int j = 0; j < 2 * n; ++j)
      for (int k = 0; k < 2 * n; ++k)
        if ((i + j + k) % 2 == 0) {
          l.sites.push_back({i, j, k});
          l.packing.add(origin + unit * Vec3(i, j, k), unit / std::sqrt(2.0));
        }
  for (int a = 0; a < 3; ++a)
    for (int s = -1; s <= 1; s += 2)
      for (int t = -1; t <= 1; t += 2) {
        std::array<int, 3> o{0, 0, 0};
        o[a] = s;
        o[(a + 1) % 3] = t;
        l.neighbour_offsets.push_back(o);
      }
  return l;
}

/// Triangular lattice of nx * ny disks, spacing = unit (site (i, j) at i a1 + j a2 with
/// a1 = (1, 0), a2 = (1/2, sqrt(3)/2)), touching disks of radius unit / 2. Rows are sheared
/// back so that the patch is a rectangle.
inline Lattice<2> hexagonal(int nx, int ny, double unit, const Vec2& origin) {
  Lattice<2> l;
  for (int j = 0; j < ny; ++j)
    for (int i = -(j / 2); i < nx - (j / 2); ++i) {
      l.sites.push_back({i, j});
      l.packing.add(origin + unit * Vec2(i + 0.5 * j, 0.5 * std::sqrt(3.0) * j), 0.5 * unit);
    }
  l.neighbour_offsets = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, -1}, {-1, 1}};
  return l;
}

/// n^D sites of spacing 2 with radii uniform in [r_lo, r_hi] (r_hi < 1 - jitter) and centres
/// jittered by up to `jitter` per axis: non-overlapping by construction.
template <int D>
Packing<D> jittered_lattice(int n, double r_lo, double r_hi, double jitter, std::uint64_t seed, double offset = 0.0) {
  Rng rng(seed);
  Packing<D> p;
  std::array<int, D> idx{};
  for (;;) {
    Vec<D> c;
    for (int a = 0; a < D; ++a) c[a] = offset + 2.0 * idx[a] + rng.uniform(-jitter, jitter);
    p.add(c, rng.uniform(r_lo, r_hi));
    int a = 0;
    while (a < D && idx[a] == n - 1) idx[a++] = 0;
    if (a == D) break;
    ++idx[a];
  }
  return p;
}

/// 4 n^3 FCC sites (cubic cell 2), radii uniform in [0.9, 0.99] of the touching radius and
/// centres jittered by up to 0.002 per axis: dense, every site has 12 near neighbours, and
/// non-overlapping by construction (the smallest gap, 0.014, exceeds twice the jitter norm).
inline Packing<3> jittered_fcc(int n, std::uint64_t seed) {
  Rng rng(seed);
  Packing<3> p;
  const double touching = 1.0 / std::sqrt(2.0);
  for (int i = 0; i < 2 * n; ++i)
    for (int j = 0; j < 2 * n; ++j)
      for (int k = 0; k < 2 * n; ++k)
        if ((i + j + k) % 2 == 0)
          p.add(Vec3(i + rng.uniform(-0.002, 0.002), j + rng.uniform(-0.002, 0.002), k + rng.uniform(-0.002, 0.002)),
                touching * rng.uniform(0.9, 0.99));
  return p;
}

/// Every pair (i < j) whose centres are at most (ri + rj)(1 + reach_rel) apart, by brute force.
template <int D>
std::vector<std::pair<std::uint32_t, std::uint32_t>> brute_force_pairs(const Packing<D>& p, double reach_rel) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for (std::uint32_t j = i + 1; j < p.size(); ++j)
      if ((p.centers[i] - p.centers[j]).norm() <= (p.radii[i] + p.radii[j]) * (1.0 + reach_rel)) out.emplace_back(i, j);
  return out;
}

}  // namespace fp::test
