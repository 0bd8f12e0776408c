#pragma once
// The advancing-front packer, paper 002 Pseudocode 1 (Roselló Valera et al. 2015):
//   F = front, S = placed set; draw r; loop: pick s0 in F; V = {s in S : d(c0, c) <= r0 + r_s + 2r};
//   for pairs (si, sj) of V: candidates = f(s0, si, sj, G, V, r); keep one inside G that overlaps
//   nothing in V; on success add it to S and F and draw a new r; if no pair works remove s0 from F.
// In 2D each new disk touches s0 and ONE neighbour, so "pairs" are single neighbours.
//
// Shape-agnostic in structure: the manager sees bodies and a ContactSolver; `Solver` is a
// template parameter so that the sphere/disk solver (a final class) is inlined into the loop.
// Differences from the paper, each an option measured in experiments/front-levers/RESULTS.md:
//  * walls are bodies (PackerOptions::walls_as_bodies): near the boundary the walls within
//    reach of s0 join V, so particles sit tangent to the container (the paper's listed drawback);
//    every candidate is required to lie fully inside the container, not just its centre.
//  * which s0 (random as the paper, FIFO, or closest to the seed point: compact growth);
//  * pair order (index, or nearest neighbours first) and which candidate to keep (the first
//    found, or the one closest to the seed point over all pairs);
//  * which neighbours serve as contact bodies: all of V (paper) or only those still in F;
//  * with a pool, whether the smallest radius is tried first as a probe (s0 dropped if it fails);
//  * a pool of radii drawn ahead: a radius that does not fit at s0 waits while the others are
//    tried; every drawn radius is placed except the pool's last few, so the size distribution
//    is not distorted (no radius is ever shrunk or discarded to make it fit).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <unordered_set>
#include <stdexcept>
#include <vector>

#include "contact/sphere_contact_solver.hpp"
#include "contact/sphere_two_contact.hpp"
#include "core/geometry/container.hpp"
#include "core/geometry/neighbour_grid.hpp"
#include "core/io/scene.hpp"
#include "core/sampling/radius_distribution.hpp"
#include "core/sampling/rng.hpp"
#include "front/front_parts.hpp"
#include "front/pack_result.hpp"

namespace fp {

template <int D, class Solver = SphereContactSolver<D>>
class AdvancingFront {
 public:
  AdvancingFront(const Container<D>& container, const RadiusDistribution& radii, const PackerOptions& options,
                 const StopCriteria& stop, std::uint64_t seed)
      : container_(container), dist_(radii), opt_(options), stop_(stop), rng_(seed),
        grid_(grid_domain(container, radii), radii.r_min(), radii.r_max(), options.grid_cell_factor,
              options.hierarchical_grid_ratio) {
    if (opt_.radius_pool < 1) throw std::invalid_argument("radius_pool must be >= 1");
    seed_point_ = front_parts::local_seed_point<D>(container, opt_);
    tol_ = opt_.contact_tolerance;
    measure_ = container_.measure();
    probe_smallest_ = opt_.probe_smallest.value_or(radii.r_max() <= kProbeRatioLimit * radii.r_min());
  }

  PackResult<D> run(const ProgressFn& progress = {}) {
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    PackResult<D> res;
    Packing<D>& P = res.packing;
    P.origin = container_.origin();
    if (stop_.max_particles) P.reserve(*stop_.max_particles);
    const double measure = measure_;
    auto elapsed = [&] { return std::chrono::duration<double>(clock::now() - t0).count(); };

    for (int k = 0; k < opt_.radius_pool; ++k) pool_.push_back(draw(res));
    initialise(P, res);

    std::uint64_t iter = 0;
    double next_progress = 0.5;
    res.stop = StopReason::FrontExhausted;
    while (!front_empty() || resume_at_voids(P, res)) {
      if (const auto reached = count_or_fraction_reached(P, res)) { res.stop = *reached; break; }
      if ((++iter & 1023) == 0 && (stop_.time_limit_seconds || progress)) {
        const double t = elapsed();
        if (stop_.time_limit_seconds && t >= *stop_.time_limit_seconds) { res.stop = StopReason::TimeLimit; break; }
        if (progress && t >= next_progress) {
          progress(P.size(), t, res.solid_measure / measure);
          next_progress = t + 0.5;
        }
      }
      const int s0 = front_top();
      ++res.counters.front_picks;
      if (!try_place_around(s0, P, res)) {
        front_pop();
        ++res.counters.front_removals;
      }
    }
    res.counters.radii_unplaced = pool_.size();
    res.seconds = elapsed();
    res.grid_bytes = grid_.memory_bytes();
    res.grid_levels = grid_.levels();
    return res;
  }

 private:
  using FrontEntry = front_parts::FrontEntry;
  using Neighbour = front_parts::Neighbour;

  static Aabb<D> grid_domain(const Container<D>& c, const RadiusDistribution& d) {
    Aabb<D> b = c.bounds();
    b.lo.array() -= d.r_max();
    b.hi.array() += d.r_max();
    return b;
  }

  double draw(PackResult<D>& res) {
    ++res.counters.radii_drawn;
    return dist_.sample(rng_);
  }

  // ---- the front F ----
  bool front_empty() const {
    return opt_.front_pick == FrontPick::ClosestToSeed ? heap_.empty() : fifo_head_ >= list_.size();
  }
  int front_top() {
    switch (opt_.front_pick) {
      case FrontPick::ClosestToSeed: return heap_.top().id;
      case FrontPick::Fifo: return list_[fifo_head_];
      case FrontPick::Random: {
        // Paper 002: s0 picked at random. Swap the pick to the head so front_pop() is O(1).
        const std::size_t n = list_.size() - fifo_head_;
        const std::size_t k = fifo_head_ + static_cast<std::size_t>(rng_.below(n));
        std::swap(list_[fifo_head_], list_[k]);
        return list_[fifo_head_];
      }
    }
    return -1;
  }
  void front_pop() {
    if (opt_.front_pick == FrontPick::ClosestToSeed) {
      in_front_[heap_.top().id] = 0;
      heap_.pop();
    } else {
      in_front_[list_[fifo_head_]] = 0;
      ++fifo_head_;
    }
    if (fifo_head_ > 4096 && fifo_head_ * 2 > list_.size()) {  // keep the list compact
      list_.erase(list_.begin(), list_.begin() + static_cast<std::ptrdiff_t>(fifo_head_));
      fifo_head_ = 0;
    }
  }
  void front_push(int id, const Vec<D>& c) {
    if (in_front_.size() <= static_cast<std::size_t>(id)) in_front_.resize(static_cast<std::size_t>(id) + 1, 0);
    in_front_[id] = 1;
    if (opt_.front_pick == FrontPick::ClosestToSeed) heap_.push({(c - seed_point_).squaredNorm(), id});
    else list_.push_back(id);
  }

  void add_particle(Packing<D>& P, PackResult<D>& res, const Vec<D>& c, double r) {
    const int id = P.add(c, r);
    grid_.insert(id, c, r);
    front_push(id, c);
    res.solid_measure += ball_measure<D>(r);
  }

  /// The front ran empty. If the container still has a void (room for a ball of the largest
  /// pooled radius centred on a lattice point of spacing ~2 r_max, touching nothing), growth
  /// resumes there: the particles around each void go back into F with their failure memo
  /// cleared; when no void has new surroundings to reopen, a new initial cluster is started in
  /// the void closest to the seed point (one at a time: growth from it usually fills the rest).
  /// Without this a wide size distribution (r_max/r_min = 50: a small s0 sunk between big
  /// neighbours, pooled radii too small to bridge a gap) or a container with a narrow neck can
  /// stop with the container nearly empty. Returns false when there is no void: the normal end,
  /// at the cost of one lattice sweep.
  bool resume_at_voids(Packing<D>& P, PackResult<D>& res) {
    const std::size_t k_seed = largest_in_pool();
    const double r_seed = pool_[k_seed];
    const Aabb<D> box = container_.bounds();
    // About 2 r_max between lattice points; coarser for a huge container (at most 2^24 points).
    bool reopened = false, found = false;
    Vec<D> best;
    double best_d2 = std::numeric_limits<double>::infinity();
    front_parts::for_each_lattice_point<D>(box, 2 * dist_.r_max(), double(1 << 24), [&](std::int64_t flat, const Vec<D>& p) {
      if (!container_.contains_ball(p, r_seed, tol_)) return;
      bool empty = true;
      grid_.for_each_within(p, r_seed, [&](int, const Vec<D>&, double, double) { empty = false; });
      if (!empty) return;
      if (voids_reopened_.insert(flat).second) reopened |= reopen_around(p, 3 * r_seed, P);
      const double d2 = (p - seed_point_).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = p, found = true;
    });
    if (reopened) {
      ++res.counters.voids_reopened;
      return true;
    }
    if (!found) return false;
    start_cluster(P, res, best, k_seed);
    ++res.counters.voids_seeded;
    return true;
  }

  /// Puts the particles within `reach` of p back into F, their failure memo cleared.
  bool reopen_around(const Vec<D>& p, double reach, const Packing<D>& P) {
    bool any = false;
    if (failed_radius_.size() < P.size()) failed_radius_.resize(P.size(), std::numeric_limits<double>::infinity());
    grid_.for_each_within(p, reach, [&](int id, const Vec<D>& c, double, double) {
      failed_radius_[id] = std::numeric_limits<double>::infinity();
      if (in_front_[id]) return;
      front_push(id, c);
      any = true;
    });
    return any;
  }

  /// The stop criteria that depend only on what has been placed (the time limit is checked in run()).
  std::optional<StopReason> count_or_fraction_reached(const Packing<D>& P, const PackResult<D>& res) const {
    if (stop_.max_particles && P.size() >= *stop_.max_particles) return StopReason::ParticleCount;
    if (stop_.target_volume_fraction && res.solid_measure >= *stop_.target_volume_fraction * measure_)
      return StopReason::VolumeFraction;
    return std::nullopt;
  }

  /// Step 1 of Pseudocode 1: D mutually tangent particles at the seed point (3 in 3D, 2 in 2D).
  /// Each takes the largest radius of the pool (the pool still follows the requested
  /// distribution): three mutually tangent spheres leave a 4th room only if it is not much
  /// smaller than they are, and a tiny one sunk between two big ones leaves none.
  void initialise(Packing<D>& P, PackResult<D>& res) {
    // The largest pooled radius the container can hold at all (a thin container may not take r_max).
    const Vec<D> deep = container_.interior_point();
    std::size_t k = pool_.size();
    for (std::size_t q = 0; q < pool_.size(); ++q)
      if (container_.contains_ball(deep, pool_[q], tol_) && (k == pool_.size() || pool_[q] > pool_[k])) k = q;
    if (k == pool_.size())
      throw std::runtime_error("the container cannot hold a first particle of radius " + std::to_string(pool_[0]) +
                               " at its interior point: container too small for the size distribution");
    start_cluster(P, res, first_centre(pool_[k]), k);
  }

  /// D mutually tangent particles: the first at c1 with radius pool_[k1] (it must fit there), the
  /// others with the largest pooled radii, tangent in random directions, where they fit. A
  /// container barely larger than one particle may leave the cluster with fewer.
  void start_cluster(Packing<D>& P, PackResult<D>& res, const Vec<D>& c1, std::size_t k1) {
    const double r1 = take_from_pool(k1, res);
    add_particle(P, res, c1, r1);
    const int i1 = static_cast<int>(P.size()) - 1;
    if (count_or_fraction_reached(P, res)) return;  // a stop of 1 particle (or a tiny φ0) is honoured
    int i2 = -1;
    for (int attempt = 0; attempt < 64 && i2 < 0; ++attempt) {
      const std::size_t k2 = largest_in_pool();
      const double r2 = pool_[k2];
      const Vec<D> c2 = P.centers[i1] + (r1 + r2) * random_unit();
      if (!fits(c2, r2)) continue;
      take_from_pool(k2, res);
      add_particle(P, res, c2, r2);
      i2 = static_cast<int>(P.size()) - 1;
    }
    if (i2 < 0) {  // a thin container (slab, needle): search the narrow window of directions
      const std::size_t k2 = largest_in_pool();
      const double r2 = pool_[k2];
      const Vec<D> u = front_parts::direction_with_most_room<D>(P.centers[i1], r1 + r2,
                                                                [&](const Vec<D>& x) { return room(x, r2); });
      const Vec<D> c2 = P.centers[i1] + (r1 + r2) * u;
      if (fits(c2, r2)) {
        take_from_pool(k2, res);
        add_particle(P, res, c2, r2);
        i2 = static_cast<int>(P.size()) - 1;
      }
    }
    if constexpr (D == 3) {
      if (i2 < 0 || count_or_fraction_reached(P, res)) return;
      const std::size_t k3 = largest_in_pool();
      const double r3 = pool_[k3];
      // The circle of centres tangent to both.
      const Vec3 a = P.centers[i1], b = P.centers[i2];
      const double ra = P.radii[i1] + r3, rb = P.radii[i2] + r3;
      const Vec3 ab = b - a;
      const double d = ab.norm();
      const Vec3 k = ab / d;
      const double x = (d * d + ra * ra - rb * rb) / (2 * d);
      const double h = std::sqrt(std::max(0.0, ra * ra - x * x));
      Vec3 e1 = (std::abs(k.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY()).cross(k).normalized();
      const Vec3 e2 = k.cross(e1);
      auto on_circle = [&](double phi) -> Vec3 { return a + x * k + h * (std::cos(phi) * e1 + std::sin(phi) * e2); };
      for (int attempt = 0; attempt < 64; ++attempt) {
        const Vec3 c3 = on_circle(2 * kPi * rng_.uniform01());  // a random point of it
        if (!fits(c3, r3)) continue;
        take_from_pool(k3, res);
        add_particle(P, res, c3, r3);
        return;
      }
      // A slab leaves a window of a few degrees: the point of the circle with the most room.
      constexpr int kSteps = 4096;
      double best_room = -std::numeric_limits<double>::infinity(), best_phi = 0;
      for (int s = 0; s < kSteps; ++s) {
        const double phi = 2 * kPi * s / kSteps, g = room(on_circle(phi), r3);
        if (g > best_room) best_room = g, best_phi = phi;
      }
      for (double step = kPi / kSteps; step > 1e-9; step *= 0.5)
        for (const double phi : {best_phi - step, best_phi + step}) {
          const double g = room(on_circle(phi), r3);
          if (g > best_room) best_room = g, best_phi = phi;
        }
      const Vec3 c3 = on_circle(best_phi);
      if (fits(c3, r3)) {
        take_from_pool(k3, res);
        add_particle(P, res, c3, r3);
      }
    }
  }

  /// How far the ball (x, r) is from touching the container boundary or a placed particle
  /// (> 0: it fits with that much to spare): what the thin-container searches maximise.
  double room(const Vec<D>& x, double r) const {
    double g = -container_.signed_distance(x) - r;
    grid_.for_each_within(x, r, [&](int, const Vec<D>&, double rk, double d2) { g = std::min(g, std::sqrt(d2) - rk - r); });
    return g;
  }

  /// The ball (x, r), inside the container, touches its boundary (within the contact tolerance).
  bool touches_boundary(const Vec<D>& x, double r) const { return container_.signed_distance(x) >= -r - tol_ * r; }

  /// Inside the container and overlapping no placed particle (beyond the contact tolerance).
  bool fits(const Vec<D>& c, double r) const {
    if (!container_.contains_ball(c, r, tol_)) return false;
    bool free = true;
    grid_.for_each_within(c, r, [&](int, const Vec<D>&, double rk, double d2) {
      const double lim = r + rk - tol_ * std::min(r, rk);
      if (d2 < lim * lim) free = false;
    });
    return free;
  }

  /// The seed point if the first particle fits there; else the point nearest to it, on the segment
  /// to the container's interior point (where it fits), where it fits (a seed point in a corner
  /// is a common choice).
  Vec<D> first_centre(double r1) const {
    if (container_.contains_ball(seed_point_, r1, 0.0)) return seed_point_;
    const Vec<D> deep = container_.interior_point();
    // Strictly inside (no tolerance): the slide would otherwise stop exactly at the tolerance,
    // where any other rounding of the same distance (the validator's) sees the ball stick out.
    double lo = 0, hi = 1;  // fits at hi, not at lo
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (container_.contains_ball(seed_point_ + mid * (deep - seed_point_), r1, 0.0) ? hi : lo) = mid;
    }
    return seed_point_ + hi * (deep - seed_point_);
  }

  std::size_t largest_in_pool() const {
    return static_cast<std::size_t>(std::max_element(pool_.begin(), pool_.end()) - pool_.begin());
  }

  double take_from_pool(std::size_t k, PackResult<D>& res) {
    const double r = pool_[k];
    pool_.erase(pool_.begin() + static_cast<std::ptrdiff_t>(k));
    pool_.push_back(draw(res));
    return r;
  }

  Vec<D> random_unit() { return front_parts::random_unit<D>(rng_); }

  /// Step 2.1-2.2 for one s0: returns true if a particle was placed.
  bool try_place_around(int s0, Packing<D>& P, PackResult<D>& res) {
    const Vec<D> c0 = P.centers[s0];
    const double r0 = P.radii[s0];
    if (pool_.size() == 1) {
      gather_neighbours(s0, c0, r0, pool_[0], P, res);
      return place_radius(0, s0, c0, r0, P, res);
    }
    // Pool: try the radii from the largest down (big particles first keeps small ones for the
    // gaps). A radius at least as large as one that already failed at s0 is not tried there
    // again: s0 stays in F only while a smaller radius fits, so re-trying the large one would
    // repeat a failed scan. (Heuristic: new neighbours can in principle open a new position.)
    // With probe_smallest_ the smallest radius is tried first: if it fails, s0 is dropped after
    // one scan; if it fits, its position is kept in case every larger radius fails.
    if (failed_radius_.size() < P.size()) failed_radius_.resize(P.size(), std::numeric_limits<double>::infinity());
    double& failed = failed_radius_[s0];
    order_.clear();
    for (std::size_t k = 0; k < pool_.size(); ++k)
      if (pool_[k] < failed) order_.push_back(static_cast<int>(k));
    if (order_.empty()) return false;
    std::sort(order_.begin(), order_.end(), [&](int a, int b) { return pool_[a] > pool_[b] || (pool_[a] == pool_[b] && a < b); });
    // The largest radius tried sets V (a superset of every smaller radius' V).
    gather_neighbours(s0, c0, r0, pool_[order_[0]], P, res);
    std::size_t larger = order_.size();  // order_[0, larger) are tried largest first
    Vec<D> at_smallest;
    if (probe_smallest_ && order_.size() >= 2) {
      const double r = pool_[order_.back()];
      if (!find_position(r, s0, c0, r0, res, at_smallest)) {
        failed = std::min(failed, r);
        return false;
      }
      --larger;
    }
    for (std::size_t q = 0; q < larger; ++q) {
      const int k = order_[q];
      if (place_radius(static_cast<std::size_t>(k), s0, c0, r0, P, res)) return true;
      failed = std::min(failed, pool_[k]);
    }
    if (larger == order_.size()) return false;
    const double r = take_from_pool(static_cast<std::size_t>(order_.back()), res);
    add_particle(P, res, at_smallest, r);
    return true;
  }

  /// V = particles within r0 + r_s + 2r of c0 (paper's definition), plus walls within 2r.
  void gather_neighbours(int s0, const Vec<D>& c0, double r0, double r, const Packing<D>& P, PackResult<D>& res) {
    // Nearest first: the candidate overlap test stops earliest this way.
    front_parts::gather_v<D>(grid_, container_, opt_, s0, c0, r0, r, nb_, walls_, res.counters);
    // Overlap tests scan V nearest to s0 first.
    nb_c_.clear();
    nb_r_.clear();
    for (const Neighbour& n : nb_) {
      nb_c_.push_back(P.centers[n.id]);
      nb_r_.push_back(P.radii[n.id]);
    }
    // Pair enumeration: walls first (few, and they close the boundary gap), then V nearest first.
    bodies_.clear();
    for (const Wall<D>& w : walls_) bodies_.push_back(Body<D>::of_wall(w));
    // A closed particle (no longer in F) rarely has room left next to it: skipping it as a contact
    // body (it stays an obstacle in nb_) removes most pairs (experiments/front-levers).
    const bool front_only = opt_.contact_bodies == ContactBodies::Front;
    // The 3D pair scan is quadratic in the contact bodies. A mobile far larger than s0 (a wide
    // size distribution: a big radius tried next to small particles) has a V of thousands of
    // small neighbours; its pairs are limited to the kMaxContactBodies nearest (it stays checked
    // against all of V), which bounds the cost of each try. Narrow distributions have |V| < 80
    // (the counter max_neighbours; contact bodies are fewer) and never reach the limit. Measured in
    // experiments/extremes: a 99:1 mix of radii 100 (1000) times apart packs in 8.4 (9.4) s, not
    // in over 60 s; 64 leaves the named scenes bit for bit unchanged (32 does not: ratio7).
    std::size_t particles = 0;
    for (const Neighbour& n : nb_) {
      if (front_only && !in_front_[n.id]) continue;
      if (D == 3 && particles++ == kMaxContactBodies) {  // a 2D scan is linear: no cap
        ++res.counters.contact_bodies_capped;
        break;
      }
      bodies_.push_back(Body<D>::sphere(P.centers[n.id], P.radii[n.id], n.id));
    }
    last_blocker_ = 0;
  }

  /// Tries to place pool_[k] touching s0 and D-1 bodies of V; places it and returns true on success.
  bool place_radius(std::size_t k, int s0, const Vec<D>& c0, double r0, Packing<D>& P, PackResult<D>& res) {
    const double r = pool_[k];
    Vec<D> best;
    if (!find_position(r, s0, c0, r0, res, best)) return false;
    take_from_pool(k, res);
    add_particle(P, res, best, r);
    return true;
  }

  /// Step 2.2 for one radius: a position touching s0 and D-1 bodies of V, overlapping nothing,
  /// inside the container (the one kept by opt_.candidate). False if there is none.
  bool find_position(double r, int s0, const Vec<D>& c0, double r0, PackResult<D>& res, Vec<D>& best) {
    const bool keep_first = opt_.candidate == CandidateChoice::First;
    bool found = false;
    double best_d2 = 0;
    // Every candidate lies within r0 + r of c0: a lower bound for its distance to the seed.
    const double lower_bound_here = std::max(0.0, (c0 - seed_point_).norm() - r0 - r);
    const double lower_bound2 = lower_bound_here * lower_bound_here;

    session_.begin(Body<D>::sphere(c0, r0, s0), r, bodies_);
    std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> out;
    const int nb = static_cast<int>(bodies_.size());

    // Keeping the closest candidate, a candidate that touches a wall outranks one that does
    // not: the layer against the wall is laid first, instead of being approached by particles
    // nestled closer to the seed that leave sub-particle gaps at the wall (measured in
    // experiments/front-levers: ~7x more wall contacts and a denser boundary layer).
    int best_rank = 2;
    bool any_position = false;  // some pair had a solution (valid or not)
    // A candidate x touching s0 and bodies of the given rank (0: a wall among them): returns
    // true to end the scan.
    auto test = [&](const Vec<D>& x, int rank) -> bool {
      ++res.counters.candidates;
      double d2 = 0;
      if (!keep_first) {
        d2 = (x - seed_point_).squaredNorm();
        if (found && (rank > best_rank || (rank == best_rank && d2 >= best_d2))) return false;
      }
      if (overlaps_neighbour(x, r)) { ++res.counters.rejected_overlap; return false; }
      if (!container_.contains_ball(x, r, tol_)) { ++res.counters.rejected_container; return false; }
      // A mesh facet or polygon edge is offered as its whole plane (line): a position tangent
      // to the plane beyond the facet's edges does not touch the container at all.
      if (rank == 0 && !touches_boundary(x, r)) { ++res.counters.rejected_container; return false; }
      found = true;
      best = x;
      best_d2 = d2;
      best_rank = rank;
      return keep_first || (rank == 0 && best_d2 <= lower_bound2);
    };
    auto consider = [&](int i, int j) -> bool {  // returns true to end the scan
      ++res.counters.solves;
      const int m = session_.solve(i, j, std::span<Placement<D>>(out.data(), out.size()));
      const int rank = (bodies_[i].is_wall() || bodies_[j].is_wall()) ? 0 : 1;
      any_position |= m > 0;
      for (int q = 0; q < m; ++q) {
        if (test(out[q].position, rank)) return true;
      }
      return false;
    };
    if constexpr (D == 2) {
      for (int i = 0; i < nb; ++i) {
        ++res.counters.pairs_considered;
        if (consider(i, i)) break;
      }
    } else {
      bool stop = false;
      for (int j = 1; j < nb && !stop; ++j) {
        const Body<D>& bj = bodies_[j];
        for (int i = 0; i < j; ++i) {
          const Body<D>& bi = bodies_[i];
          ++res.counters.pairs_considered;
          if (!bi.is_wall() && !bj.is_wall()) {
            const double reach = bi.radius + bj.radius + 2 * r;
            if ((bi.center - bj.center).squaredNorm() > reach * reach) { ++res.counters.pairs_pruned; continue; }
          }
          if (consider(i, j)) { stop = true; break; }
        }
      }
      // No pair had any position: a container too narrow for three contacts (a needle, a
      // capillary). Positions touching s0 and one body keep the growth going along the wall.
      if (!any_position) {
        for (int b = 0; b < nb && !(found && keep_first); ++b) {
          two_contact_.clear();
          two_contact_positions(c0, r0, bodies_[b], r, kTwoContactSamples, two_contact_);
          for (const Vec<D>& x : two_contact_)
            if (test(x, bodies_[b].is_wall() ? 0 : 1)) break;
        }
        if (found) ++res.counters.two_contact_placements;
      }
    }
    return found;
  }

  /// Does the ball (x, r) overlap any particle of V by more than the contact tolerance?
  /// The neighbour that blocked the previous candidate is tried first: it usually blocks the next.
  bool overlaps_neighbour(const Vec<D>& x, double r) {
    const int n = static_cast<int>(nb_.size());
    auto blocks = [&](int q) {
      const double rk = nb_r_[q];
      const double lim = r + rk - tol_ * std::min(r, rk);
      return (nb_c_[q] - x).squaredNorm() < lim * lim;
    };
    if (last_blocker_ < n && blocks(last_blocker_)) return true;
    for (int q = 0; q < n; ++q)
      if (q != last_blocker_ && blocks(q)) { last_blocker_ = q; return true; }
    return false;
  }


  const Container<D>& container_;
  const RadiusDistribution& dist_;
  PackerOptions opt_;
  StopCriteria stop_;
  Rng rng_;
  NeighbourGrid<D> grid_;
  Solver solver_;
  Vec<D> seed_point_;
  double tol_ = 1e-9;
  bool probe_smallest_ = false;
  double measure_ = 0;  // container volume (area), cached: a mesh computes it from its facets

  std::priority_queue<FrontEntry> heap_;
  std::vector<int> list_;
  std::size_t fifo_head_ = 0;
  std::vector<double> pool_;
  std::vector<int> order_;
  std::vector<double> failed_radius_;  // per particle: smallest pooled radius that failed there
  std::vector<Neighbour> nb_;
  std::vector<Wall<D>> walls_;
  std::vector<Body<D>> bodies_;
  std::vector<Vec<D>> two_contact_;  // scratch: positions touching s0 and one body (3D fallback)
  static constexpr int kTwoContactSamples = 24;  // per body: about 15 degrees apart
  static constexpr std::size_t kMaxContactBodies = 64;  // particle bodies per pair scan (gather_neighbours)
  std::vector<Vec<D>> nb_c_;   // V's centres and radii, contiguous for the overlap test
  std::vector<double> nb_r_;
  int last_blocker_ = 0;
  std::vector<char> in_front_;  // per particle: still in F
  std::unordered_set<std::int64_t> voids_reopened_;  // lattice points of resume_at_voids() already reopened
  typename Solver::Session session_;
};

}  // namespace fp
