#pragma once
// Independent checks of packings for the front and CLI tests: brute-force overlap and contact
// counts (sort and sweep, no library metric), closed-form container distances, and a
// brute-force point-to-triangle distance with a winding-number sign for meshes.
// Deliberately shares no code with core/metrics: these checks must catch the library's bugs.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include <Eigen/Geometry>  // cross()

#include "core/geometry/packing.hpp"
#include "core/geometry/triangle_closest_point.hpp"
#include "core/geometry/vec.hpp"
#include "core/io/scene_yaml.hpp"

namespace fptest {

using fp::Vec;
using fp::Vec2;
using fp::Vec3;

/// Scenes written in the tests resolve relative mesh paths from tests/data/scenes-e2e/.
inline fp::Scene scene_from_yaml(const std::string& text) {
  return fp::parse_scene(text, std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/scenes-e2e/inline.yaml");
}

/// Visits every pair (i, j), i < j, whose x-intervals [x - r - margin, x + r + margin] meet:
/// a superset of the pairs within `margin` of touching (sort and sweep on the first axis).
template <int D, class F>
void for_each_close_pair(const fp::Packing<D>& P, double margin, F&& visit) {
  const std::size_t n = P.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return P.centers[a][0] - P.radii[a] < P.centers[b][0] - P.radii[b];
  });
  for (std::size_t a = 0; a < n; ++a) {
    const std::size_t i = order[a];
    const double hi = P.centers[i][0] + P.radii[i] + margin;
    for (std::size_t b = a + 1; b < n; ++b) {
      const std::size_t j = order[b];
      if (P.centers[j][0] - P.radii[j] - margin > hi) break;
      visit(std::min(i, j), std::max(i, j));
    }
  }
}

struct OverlapReport {
  double max_over_pair_rmin = 0;  ///< max (ri + rj - d) / min(ri, rj) over overlapping pairs
  double max_over_rmin = 0;       ///< max (ri + rj - d) / r_min of the packing
  std::size_t worst_i = 0, worst_j = 0;
};

template <int D>
OverlapReport overlaps(const fp::Packing<D>& P) {
  OverlapReport rep;
  if (P.empty()) return rep;
  const double rmin = *std::min_element(P.radii.begin(), P.radii.end());
  for_each_close_pair<D>(P, 0.0, [&](std::size_t i, std::size_t j) {
    const double d = (P.centers[i] - P.centers[j]).norm();
    const double ov = P.radii[i] + P.radii[j] - d;
    if (ov <= 0) return;
    const double rel = ov / std::min(P.radii[i], P.radii[j]);
    if (rel > rep.max_over_pair_rmin) {
      rep.max_over_pair_rmin = rel;
      rep.worst_i = i;
      rep.worst_j = j;
    }
    rep.max_over_rmin = std::max(rep.max_over_rmin, ov / rmin);
  });
  return rep;
}

/// Per particle: the number of other particles it touches (|gap| <= tol * min(ri, rj)).
template <int D>
std::vector<int> particle_contacts(const fp::Packing<D>& P, double tol) {
  std::vector<int> z(P.size(), 0);
  const double rmax = P.empty() ? 0.0 : *std::max_element(P.radii.begin(), P.radii.end());
  for_each_close_pair<D>(P, tol * rmax, [&](std::size_t i, std::size_t j) {
    const double gap = (P.centers[i] - P.centers[j]).norm() - P.radii[i] - P.radii[j];
    if (std::abs(gap) <= tol * std::min(P.radii[i], P.radii[j])) {
      ++z[i];
      ++z[j];
    }
  });
  return z;
}

// ---- closed-form signed distances (< 0 inside) ----------------------------------------------
// Called with a point in a packing's local frame and that frame's origin (absolute): the
// container's absolute geometry is moved into the frame (x - origin, exact near the container,
// core/geometry/local_frame.hpp) and the distance computed there, so that far-off coordinates
// are checked to the same relative tolerance as plain ones, with no code of the library.

template <int D>
using SignedDistance = std::function<double(const Vec<D>& local, const Vec<D>& origin)>;

template <int D>
SignedDistance<D> box_distance(Vec<D> lo_abs, Vec<D> hi_abs) {
  return [=](const Vec<D>& p, const Vec<D>& origin) {
    const Vec<D> lo = lo_abs - origin, hi = hi_abs - origin;
    double outside2 = 0, inside = std::numeric_limits<double>::infinity();
    for (int a = 0; a < D; ++a) {
      const double below = lo[a] - p[a], above = p[a] - hi[a];
      const double o = std::max({below, above, 0.0});
      outside2 += o * o;
      inside = std::min({inside, -below, -above});
    }
    return outside2 > 0 ? std::sqrt(outside2) : -inside;
  };
}

template <int D>
SignedDistance<D> ball_distance(Vec<D> c, double R) {
  return [=](const Vec<D>& p, const Vec<D>& origin) { return (p - (c - origin)).norm() - R; };
}

inline SignedDistance<3> cylinder_distance(Vec3 base, Vec3 axis, double R, double h) {
  axis.normalize();
  return [=](const Vec3& p, const Vec3& origin) {
    const Vec3 d = p - (base - origin);
    const double t = d.dot(axis);
    const double rho = (d - t * axis).norm();
    const double dr = rho - R, dt = std::max(-t, t - h);
    if (dr <= 0 && dt <= 0) return std::max(dr, dt);
    const double a = std::max(dr, 0.0), b = std::max(dt, 0.0);
    return std::sqrt(a * a + b * b);
  };
}

inline double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

/// Simple polygon: distance to the nearest edge, sign by the crossing number.
inline SignedDistance<2> polygon_distance(std::vector<Vec2> v_abs) {
  return [v_abs = std::move(v_abs)](const Vec2& p, const Vec2& origin) {
    std::vector<Vec2> v = v_abs;
    for (Vec2& x : v) x -= origin;
    double dist = std::numeric_limits<double>::infinity();
    bool in = false;
    const std::size_t n = v.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      dist = std::min(dist, segment_distance(p, v[j], v[i]));
      if ((v[i].y() > p.y()) != (v[j].y() > p.y()) &&
          p.x() < (v[j].x() - v[i].x()) * (p.y() - v[i].y()) / (v[j].y() - v[i].y()) + v[i].x())
        in = !in;
    }
    return in ? -dist : dist;
  };
}

/// Closed triangle mesh: brute-force distance to every facet, sign by the winding number
/// (sum of the facets' solid angles, Van Oosterom & Strackee): ~±1 inside, ~0 outside, so it
/// does not depend on the facets' orientation being outward, only consistent.
inline SignedDistance<3> mesh_distance(std::vector<Vec3> v, std::vector<std::array<int, 3>> t) {
  return [v = std::move(v), t = std::move(t)](const Vec3& p, const Vec3& origin) {
    double dist2 = std::numeric_limits<double>::infinity();
    double omega = 0;
    for (const auto& f : t) {
      const Vec3 a = v[f[0]] - origin, b = v[f[1]] - origin, c = v[f[2]] - origin;
      dist2 = std::min(dist2, (fp::detail::closest_on_triangle(p, a, b, c) - p).squaredNorm());
      const Vec3 x = a - p, y = b - p, z = c - p;
      const double lx = x.norm(), ly = y.norm(), lz = z.norm();
      const double num = x.dot(y.cross(z));
      const double den = lx * ly * lz + x.dot(y) * lz + y.dot(z) * lx + z.dot(x) * ly;
      omega += 2 * std::atan2(num, den);
    }
    const bool in = std::abs(omega) > 2 * fp::kPi;  // |winding| > 1/2
    return in ? -std::sqrt(dist2) : std::sqrt(dist2);
  };
}

struct ContainmentReport {
  double max_outside_over_r = -std::numeric_limits<double>::infinity();  ///< max (sd(c) + r) / r
  std::size_t worst = 0;
  std::size_t touching_walls = 0;  ///< particles with |sd(c) + r| <= tol r
};

template <int D>
ContainmentReport containment(const fp::Packing<D>& P, const SignedDistance<D>& sd, double tol) {
  ContainmentReport rep;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double r = P.radii[i];
    const double out = (sd(P.centers[i], P.origin) + r) / r;
    if (out > rep.max_outside_over_r) {
      rep.max_outside_over_r = out;
      rep.worst = i;
    }
    if (std::abs(out) <= tol) ++rep.touching_walls;
  }
  return rep;
}

/// True if every centre and radius is bitwise equal (and the sizes match).
template <int D>
bool bitwise_equal(const fp::Packing<D>& a, const fp::Packing<D>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a.radii[i]) != std::bit_cast<std::uint64_t>(b.radii[i])) return false;
    for (int k = 0; k < D; ++k)
      if (std::bit_cast<std::uint64_t>(a.centers[i][k]) != std::bit_cast<std::uint64_t>(b.centers[i][k])) return false;
  }
  return true;
}

}  // namespace fptest
