#pragma once
// Pieces of the advancing front (advancing_front.hpp) that need no particle model: the front's
// heap entry, the neighbourhood V and its order, random directions, the search for the direction
// with the most room and the lattice of void probes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/vec.hpp"
#include "core/io/scene.hpp"
#include "core/sampling/random_unit.hpp"
#include "core/sampling/rng.hpp"
#include "front/pack_result.hpp"

namespace fp::front_parts {

/// A particle in F keyed by its squared distance to the seed point (min-heap order, ties by id).
struct FrontEntry {
  double key;
  int id;
  bool operator<(const FrontEntry& o) const { return key != o.key ? key > o.key : id > o.id; }
};

/// A neighbour of s0: gap between circumscribed spheres, particle id.
struct Neighbour {
  double gap;
  int id;
};

/// Nearest first (ties by id), or particle index order (the grid's visiting order would favour a
/// direction of space).
inline void order_neighbours(std::vector<Neighbour>& nb, PairOrder order) {
  if (order == PairOrder::NearestFirst)
    std::sort(nb.begin(), nb.end(), [](const Neighbour& a, const Neighbour& b) { return a.gap < b.gap || (a.gap == b.gap && a.id < b.id); });
  else
    std::sort(nb.begin(), nb.end(), [](const Neighbour& a, const Neighbour& b) { return a.id < b.id; });
}

/// V of Pseudocode 1 for a front particle (c0, circumscribed radius r0) and a mobile of radius R:
/// the particles whose spheres come within 2R of s0's (gap between the spheres, ordered by
/// `opt.pair_order`), and, with walls as bodies, the walls within r0 + 2R of c0.
template <int D, class Grid>
void gather_v(const Grid& grid, const Container<D>& container, const PackerOptions& opt, int s0, const Vec<D>& c0,
              double r0, double R, std::vector<Neighbour>& nb, std::vector<Wall<D>>& walls, FrontCounters& counters) {
  nb.clear();
  grid.for_each_within(c0, r0 + 2 * R, [&](int id, const Vec<D>&, double rk, double d2) {
    if (id != s0) nb.push_back({std::sqrt(d2) - r0 - rk, id});
  });
  order_neighbours(nb, opt.pair_order);
  counters.max_neighbours = std::max<std::uint64_t>(counters.max_neighbours, nb.size());
  walls.clear();
  if (opt.walls_as_bodies) {
    container.walls_near(c0, r0 + 2 * R, walls);
    counters.wall_bodies += walls.size();
  }
}

/// Where growth starts, in the container's local frame: the scene's seed_point (absolute) or
/// the container's interior point.
template <int D>
Vec<D> local_seed_point(const Container<D>& container, const PackerOptions& opt) {
  if (!opt.seed_point) return container.interior_point();
  if (static_cast<int>(opt.seed_point->size()) != D) throw std::invalid_argument("seed_point has the wrong dimension");
  Vec<D> s;
  for (int a = 0; a < D; ++a) s[a] = (*opt.seed_point)[a];
  return s - container.origin();
}

/// A uniformly distributed unit vector (2 draws in 3D, 1 in 2D).
using fp::random_unit;  // core/sampling/random_unit.hpp

/// Directions spread evenly over the unit sphere (Fibonacci lattice) or circle, n of them.
template <int D>
Vec<D> spread_direction(int k, int n) {
  if constexpr (D == 2) {
    const double phi = 2 * kPi * (k + 0.5) / n;
    return Vec2(std::cos(phi), std::sin(phi));
  } else {
    const double z = 1 - (2 * k + 1.0) / n;
    const double phi = k * 2.399963229728653;  // the golden angle
    const double s = std::sqrt(std::max(0.0, 1 - z * z));
    return Vec3(s * std::cos(phi), s * std::sin(phi), z);
  }
}

/// The direction u (unit) that maximises room(c + dist * u), for when random directions found
/// no place for a particle touching the one at c: a thin container (a slab, a needle) leaves
/// only a small window of directions. Evenly spread directions, then a pattern search around
/// the best one (angles halved down to 1e-7 rad), so that windows narrower than the sampling
/// are found too. `room` > 0 where the particle fits in the container.
template <int D, class Room>
Vec<D> direction_with_most_room(const Vec<D>& c, double dist, Room&& room) {
  constexpr int kDirections = D == 2 ? 720 : 2048;
  Vec<D> best = spread_direction<D>(0, kDirections);
  double best_room = room(Vec<D>(c + dist * best));
  for (int k = 1; k < kDirections; ++k) {
    const Vec<D> u = spread_direction<D>(k, kDirections);
    const double g = room(Vec<D>(c + dist * u));
    if (g > best_room) best_room = g, best = u;
  }
  for (double step = D == 2 ? 2 * kPi / kDirections : 0.08; step > 1e-7; step *= 0.5) {
    for (bool improved = true; improved;) {
      improved = false;
      // Tangent directions at `best`: rotate by +-step in each.
      Vec<D> t1, t2;
      if constexpr (D == 2) {
        t1 = Vec2(-best.y(), best.x());
        t2 = t1;
      } else {
        t1 = (std::abs(best.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY()).cross(best).normalized();
        t2 = best.cross(t1);
      }
      for (const Vec<D>& t : {t1, Vec<D>(-t1), t2, Vec<D>(-t2)}) {
        const Vec<D> u = (std::cos(step) * best + std::sin(step) * t).normalized();
        const double g = room(Vec<D>(c + dist * u));
        if (g > best_room) {
          best_room = g;
          best = u;
          improved = true;
        }
      }
    }
  }
  return best;
}

/// Points of spacing ~h (coarsened by 1.26x until there are at most `max_points`) centred in a
/// box: where a front that ran empty looks for voids. Calls f(flat index, point) for each. With
/// `through_centre`, an odd number per axis, so the box's centre is one (a block of a slab one
/// particle thick has room only on its mid-plane).
template <int D, class F>
void for_each_lattice_point(const Aabb<D>& box, double h, double max_points, F&& f, bool through_centre = false) {
  std::int64_t dims[D];
  for (;;) {
    double points = 1;
    for (int a = 0; a < D; ++a) {
      const double n = std::floor(box.size()[a] / h);
      dims[a] = through_centre ? 2 * static_cast<std::int64_t>(std::floor(n / 2)) + 1 : static_cast<std::int64_t>(n) + 1;
      points *= static_cast<double>(dims[a]);
    }
    if (points <= max_points) break;
    h *= 1.26;
  }
  std::int64_t idx[D] = {};
  for (std::int64_t flat = 0;; ++flat) {
    Vec<D> p;
    for (int a = 0; a < D; ++a) p[a] = box.lo[a] + 0.5 * (box.size()[a] - (dims[a] - 1) * h) + idx[a] * h;
    f(flat, p);
    int a = 0;
    while (a < D && ++idx[a] == dims[a]) idx[a++] = 0;
    if (a == D) break;
  }
}

}  // namespace fp::front_parts
