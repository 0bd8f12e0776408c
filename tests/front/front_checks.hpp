#pragma once
// GoogleTest assertions over a packing, built on the independent checks of front_test_util.hpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <string>

#include "front/pack.hpp"
#include "front_test_util.hpp"

namespace fptest {

/// Overlap allowed by the tests: 1e-9 of the smallest radius of the packing.
inline constexpr double kOverlapTol = 1e-9;
/// A particle is inside if it sticks out by at most 1e-9 of its radius (the contact tolerance).
inline constexpr double kInsideTol = 1e-9;

struct Validity {
  OverlapReport overlap;
  ContainmentReport containment;
};

/// No pair overlaps by more than kOverlapTol * r_min, every particle is inside, every radius
/// is within [r_min, r_max] of the distribution.
template <int D>
Validity expect_valid(const fp::Packing<D>& P, const SignedDistance<D>& sd, double r_min, double r_max,
                      const std::string& what) {
  Validity v;
  EXPECT_GT(P.size(), 0u) << what;
  v.overlap = overlaps<D>(P);
  EXPECT_LE(v.overlap.max_over_rmin, kOverlapTol)
      << what << ": particles " << v.overlap.worst_i << " and " << v.overlap.worst_j << " overlap by "
      << v.overlap.max_over_pair_rmin << " min(ri, rj)";
  v.containment = containment<D>(P, sd, kInsideTol);
  EXPECT_LE(v.containment.max_outside_over_r, kInsideTol)
      << what << ": particle " << v.containment.worst << " sticks out of the container by "
      << v.containment.max_outside_over_r << " r";
  const auto [lo, hi] = std::minmax_element(P.radii.begin(), P.radii.end());
  if (!P.empty()) {
    EXPECT_GE(*lo, r_min) << what;
    EXPECT_LE(*hi, r_max) << what;
  }
  return v;
}

/// Mean number of particle contacts (walls excluded) of the particles farther than `depth`
/// from the boundary; sets `count` to how many there are.
template <int D>
double bulk_mean_coordination(const fp::Packing<D>& P, const SignedDistance<D>& sd, double depth, std::size_t& count) {
  const std::vector<int> z = particle_contacts<D>(P, kOverlapTol);
  double sum = 0;
  count = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (-sd(P.centers[i], P.origin) - P.radii[i] < depth) continue;
    sum += z[i];
    ++count;
  }
  return count ? sum / static_cast<double>(count) : 0.0;
}

/// Sum of particle volumes (areas) over the container's closed-form measure.
template <int D>
double volume_fraction(const fp::Packing<D>& P, double container_measure) {
  double s = 0;
  for (double r : P.radii) s += fp::ball_measure<D>(r);
  return s / container_measure;
}

/// Reads an OFF file (triangles only) for the brute-force reference distance.
inline void read_off(const std::string& path, std::vector<Vec3>& v, std::vector<std::array<int, 3>>& t, double scale = 1) {
  std::ifstream in(path);
  std::string magic;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> magic >> nv >> nf >> ne;
  ASSERT_EQ(magic, "OFF") << path;
  v.resize(nv);
  for (auto& p : v) {
    in >> p.x() >> p.y() >> p.z();
    p *= scale;
  }
  t.resize(nf);
  for (auto& f : t) {
    int k = 0;
    in >> k >> f[0] >> f[1] >> f[2];
    ASSERT_EQ(k, 3) << path;
  }
  ASSERT_TRUE(in) << path;
}

inline double mesh_volume(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& t) {
  double s = 0;
  for (const auto& f : t) s += v[f[0]].dot(v[f[1]].cross(v[f[2]]));
  return std::abs(s) / 6;
}

}  // namespace fptest
