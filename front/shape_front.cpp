#include "front/shape_front.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <stdexcept>
#include <unordered_set>

#include "contact/narrow_phase.hpp"
#include "contact/shape_containment.hpp"
#include "contact/solver_registry.hpp"
#include "core/geometry/neighbour_grid.hpp"
#include "front/front_parts.hpp"

namespace fp {
namespace {

template <int D>
class ShapeFront {
 public:
  ShapeFront(const Container<D>& container, const std::vector<ShapeTemplate<D>>& templates, const PackerOptions& options,
             const StopCriteria& stop, std::uint64_t seed)
      : container_(container), templates_(templates), opt_(options), stop_(stop), rng_(seed),
        registry_(np_, options.minimisation, options.contact_solver == ContactSolverChoice::Auto), containment_(container, np_),
        r_min_(min_bounding(templates)), r_max_(max_bounding(templates)),
        grid_(grid_domain(container, r_max_), r_min_, r_max_, options.grid_cell_factor, options.hierarchical_grid_ratio) {
    if (templates_.empty()) throw std::invalid_argument("pack_shapes: no particle templates");
    if (opt_.radius_pool < 1) throw std::invalid_argument("radius_pool must be >= 1");
    seed_point_ = front_parts::local_seed_point<D>(container, opt_);
    tol_ = opt_.minimisation.gap_tolerance;
    measure_ = container.measure();
  }

  ShapePackResult<D> run(const ProgressFn& progress) {
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(clock::now() - t0).count(); };
    ShapePackResult<D> res;
    res.gap_tolerance = tol_;
    for (const auto& t : templates_) res.packing.template_names.push_back(t.family);
    res.packing.origin = container_.origin();
    for (int k = 0; k < opt_.radius_pool; ++k) pool_.push_back(draw(res));
    initialise(res);

    double next_progress = 0.5;
    res.stop = StopReason::FrontExhausted;
    while (!heap_.empty() || resume_at_voids(res)) {
      if (const auto reached = count_or_fraction_reached(res)) { res.stop = *reached; break; }
      // Every pick: one costs from microseconds (capsules) to a second (ellipsoids), and a
      // clock read is nothing beside it (a coarser check overshot a 15 s limit by 10 s).
      if (stop_.time_limit_seconds || progress) {
        const double t = elapsed();
        if (stop_.time_limit_seconds && t >= *stop_.time_limit_seconds) { res.stop = StopReason::TimeLimit; break; }
        if (progress && t >= next_progress) {
          progress(res.packing.size(), t, res.solid_measure / measure_);
          next_progress = t + 0.5;
        }
      }
      const int s0 = heap_.top().id;
      ++res.counters.front_picks;
      if (!try_place_around(s0, res)) {
        in_front_[static_cast<std::size_t>(s0)] = 0;
        heap_.pop();
        ++res.counters.front_removals;
      }
    }
    res.counters.radii_unplaced = pool_.size();
    res.minimisation = static_cast<const MinimisationSolver<D>&>(registry_.default_solver()).stats();
    res.fcl_queries = np_.fcl_queries();
    res.seconds = elapsed();
    return res;
  }

 private:
  using FrontEntry = front_parts::FrontEntry;
  using Neighbour = front_parts::Neighbour;
  static constexpr std::size_t kMaxWallBodies = 4;

  static double min_bounding(const std::vector<ShapeTemplate<D>>& ts) {
    double r = std::numeric_limits<double>::infinity();
    for (const auto& t : ts) r = std::min(r, t.bounding_min());
    return r;
  }
  static double max_bounding(const std::vector<ShapeTemplate<D>>& ts) {
    double r = 0;
    for (const auto& t : ts) r = std::max(r, t.bounding_max());
    return r;
  }
  static Aabb<D> grid_domain(const Container<D>& c, double r_max) {
    Aabb<D> b = c.bounds();
    b.lo.array() -= r_max;
    b.hi.array() += r_max;
    return b;
  }

  Draft<D> draw(ShapePackResult<D>& res) {
    ++res.counters.radii_drawn;
    return draw_draft<D>(templates_, rng_);
  }

  std::optional<StopReason> count_or_fraction_reached(const ShapePackResult<D>& res) const {
    if (stop_.max_particles && res.packing.size() >= *stop_.max_particles) return StopReason::ParticleCount;
    if (stop_.target_volume_fraction && res.solid_measure >= *stop_.target_volume_fraction * measure_)
      return StopReason::VolumeFraction;
    return std::nullopt;
  }

  Particle<D> at(const Draft<D>& d, const Vec<D>& x) const {
    Particle<D> p;
    p.shape = d.shape;
    p.pose.position = x;
    p.pose.rotation = d.rotation;
    p.template_id = d.template_id;
    p.size = d.size;
    return p;
  }

  void add_particle(ShapePackResult<D>& res, Particle<D> p) {
    auto& P = res.packing.particles;
    const int id = static_cast<int>(P.size());
    const Vec<D> c = p.pose.position;
    const double r = p.bounding_radius();
    res.solid_measure += p.shape->measure();
    P.push_back(std::move(p));
    grid_.insert(id, c, r);
    if (in_front_.size() <= static_cast<std::size_t>(id)) in_front_.resize(static_cast<std::size_t>(id) + 1, 0);
    in_front_[static_cast<std::size_t>(id)] = 1;
    heap_.push({(c - seed_point_).squaredNorm(), id});
  }

  Draft<D> take_from_pool(std::size_t k, ShapePackResult<D>& res) {
    Draft<D> d = std::move(pool_[k]);
    pool_.erase(pool_.begin() + static_cast<std::ptrdiff_t>(k));
    pool_.push_back(draw(res));
    return d;
  }

  std::size_t largest_in_pool() const {
    std::size_t k = 0;
    for (std::size_t q = 1; q < pool_.size(); ++q)
      if (pool_[q].bounding_radius() > pool_[k].bounding_radius()) k = q;
    return k;
  }

  /// Every point of p inside the container (walls touching within the tolerance).
  bool inside_container(const Particle<D>& p) const { return containment_.inside(p, tol_); }

  /// p overlaps no placed particle (beyond the tolerance).
  bool free_of_overlap(const Particle<D>& p) const {
    bool free = true;
    const double r = p.bounding_radius();
    grid_.for_each_within(p.pose.position, r, [&](int id, const Vec<D>&, double rk, double) {
      if (!free) return;
      const Particle<D>& q = particles_->at(static_cast<std::size_t>(id));
      if (np_.overlap_beyond(q, p, tol_ * std::min(r, rk))) free = false;
    });
    return free;
  }

  /// Least gap between p and the placed particles near it (+inf if none is near).
  double min_gap(const Particle<D>& p) const {
    double g = std::numeric_limits<double>::infinity();
    grid_.for_each_within(p.pose.position, p.bounding_radius(), [&](int id, const Vec<D>&, double, double) {
      g = std::min(g, np_.gap(particles_->at(static_cast<std::size_t>(id)), p).value);
    });
    return g;
  }

  bool fits(const Particle<D>& p) const { return inside_container(p) && free_of_overlap(p); }

  Vec<D> random_unit() { return front_parts::random_unit<D>(rng_); }

  /// Step 1 of Pseudocode 1 for any shape: the largest pooled draft at the seed point (slid
  /// towards the interior point where it does not fit), then D-1 drafts brought along random
  /// rays from it until they touch what is placed (bisection on the gap).
  void initialise(ShapePackResult<D>& res) {
    particles_ = &res.packing.particles;
    start_cluster(res, seed_point_);
  }

  bool start_cluster(ShapePackResult<D>& res, const Vec<D>& where, std::optional<std::size_t> draft = std::nullopt) {
    const std::size_t k1 = draft ? *draft : largest_in_pool();
    std::optional<Vec<D>> c1 = first_centre(pool_[k1], where);
    if (!c1) {
      if (res.packing.empty())
        throw std::runtime_error("the container cannot hold a first particle (circumscribed radius " +
                                 std::to_string(pool_[k1].bounding_radius()) + ") near its interior point");
      return false;
    }
    const int first = static_cast<int>(res.packing.size());
    add_particle(res, at(take_from_pool(k1, res), *c1));
    for (int placed = 1; placed < D && !count_or_fraction_reached(res); ++placed) {
      for (int attempt = 0; attempt < 64; ++attempt) {
        const std::size_t k = largest_in_pool();
        const Vec<D> u = random_unit();
        const Vec<D> c0 = res.packing.particles[static_cast<std::size_t>(first)].pose.position;
        Particle<D> p = at(pool_[k], c0);
        // From c0 outwards: overlapping at t = 0, apart beyond the two circumscribed radii.
        double lo = 0, hi = res.packing.particles[static_cast<std::size_t>(first)].bounding_radius() + p.bounding_radius();
        hi *= 1 + 1e-9;
        for (int it = 0; it < 80; ++it) {
          const double mid = 0.5 * (lo + hi);
          p.pose.position = c0 + mid * u;
          (min_gap(p) >= 0 ? hi : lo) = mid;
        }
        p.pose.position = c0 + hi * u;
        if (!fits(p)) continue;
        take_from_pool(k, res);
        add_particle(res, std::move(p));
        break;
      }
    }
    return true;
  }

  /// `where` if the draft fits there; else the point nearest to it on the segment to the
  /// container's interior point where it does.
  std::optional<Vec<D>> first_centre(const Draft<D>& d, const Vec<D>& where) const {
    if (fits(at(d, where))) return where;
    const Vec<D> deep = container_.interior_point();
    if (!fits(at(d, deep))) return std::nullopt;
    double lo = 0, hi = 1;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (fits(at(d, where + mid * (deep - where))) ? hi : lo) = mid;
    }
    return where + hi * (deep - where);
  }

  /// F ran empty: the lattice points (spacing ~r_max) where some pooled draft fits (the real
  /// test: an elongated draft fits many a void its circumscribed sphere does not); the particles
  /// around them go back into F once; then one new cluster in the void closest to the seed
  /// point. False when there is no void left.
  bool resume_at_voids(ShapePackResult<D>& res) {
    const Aabb<D> box = container_.bounds();
    bool reopened = false, found = false;
    Vec<D> best;
    std::size_t best_k = 0;
    double best_d2 = std::numeric_limits<double>::infinity();
    if (failed_radius_.size() < res.packing.size()) failed_radius_.resize(res.packing.size(), std::numeric_limits<double>::infinity());
    front_parts::for_each_lattice_point<D>(box, r_max_, double(1 << 20), [&](std::int64_t flat, const Vec<D>& p) {
      if (!(container_.signed_distance(p) < 0)) return;
      std::size_t k = pool_.size();
      for (std::size_t q = 0; q < pool_.size() && k == pool_.size(); ++q)
        if (fits(at(pool_[q], p))) k = q;
      if (k == pool_.size()) return;
      if (voids_reopened_.insert(flat).second) {
        grid_.for_each_within(p, 3 * pool_[k].bounding_radius(), [&](int id, const Vec<D>& c, double, double) {
          failed_radius_[static_cast<std::size_t>(id)] = std::numeric_limits<double>::infinity();
          if (in_front_[static_cast<std::size_t>(id)]) return;
          in_front_[static_cast<std::size_t>(id)] = 1;
          heap_.push({(c - seed_point_).squaredNorm(), id});
          reopened = true;
        });
      }
      const double d2 = (p - seed_point_).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = p, best_k = k, found = true;
    });
    if (reopened) {
      ++res.counters.voids_reopened;
      return true;
    }
    if (!found) return false;
    ++res.counters.voids_seeded;
    return start_cluster(res, best, best_k);
  }

  /// Step 2.1-2.2 for one s0: the pooled drafts from the largest down; a draft at least as large
  /// as one that already failed at s0 is not tried there again.
  bool try_place_around(int s0, ShapePackResult<D>& res) {
    if (failed_radius_.size() < res.packing.size()) failed_radius_.resize(res.packing.size(), std::numeric_limits<double>::infinity());
    double& failed = failed_radius_[static_cast<std::size_t>(s0)];
    order_.clear();
    for (std::size_t k = 0; k < pool_.size(); ++k)
      if (pool_[k].bounding_radius() < failed) order_.push_back(static_cast<int>(k));
    if (order_.empty()) return false;
    std::sort(order_.begin(), order_.end(), [&](int a, int b) {
      const double ra = pool_[static_cast<std::size_t>(a)].bounding_radius(), rb = pool_[static_cast<std::size_t>(b)].bounding_radius();
      return ra > rb || (ra == rb && a < b);
    });
    gather_neighbours(s0, pool_[static_cast<std::size_t>(order_[0])].bounding_radius(), res);
    for (int k : order_) {
      Vec<D> best;
      const Draft<D>& d = pool_[static_cast<std::size_t>(k)];
      if (find_position(d, s0, res, best)) {
        add_particle(res, at(take_from_pool(static_cast<std::size_t>(k), res), best));
        return true;
      }
      failed = std::min(failed, d.bounding_radius());
    }
    return false;
  }

  /// V = particles whose circumscribed spheres come within 2R of s0's, walls within reach.
  void gather_neighbours(int s0, double R, ShapePackResult<D>& res) {
    const Particle<D>& p0 = res.packing.particles[static_cast<std::size_t>(s0)];
    const Vec<D> c0 = p0.pose.position;
    const double r0 = p0.bounding_radius();
    front_parts::gather_v<D>(grid_, container_, opt_, s0, c0, r0, R, nb_, walls_, res.counters);
    // Contact bodies: only those whose true gap to s0 a mobile of diameter 2R can bridge (the
    // circumscribed-sphere test above is loose for elongated shapes).
    // A fine mesh offers many nearly coplanar facets near s0: each would add its own pairs and
    // solves for almost the same position (measured on the femur: 5,500 solves per capsule).
    // Nearest first, a plane within ~18 degrees of one already kept is dropped (paired with the
    // kept one it would give a degenerate problem), and at most kMaxWallBodies are kept (a box
    // corner needs 3).
    bodies_.clear();
    wall_order_.clear();
    for (std::size_t k = 0; k < walls_.size(); ++k) {
      const double g = np_.gap(walls_[k], p0).value;
      if (g <= 2 * R) wall_order_.push_back({g, static_cast<int>(k)});
    }
    std::sort(wall_order_.begin(), wall_order_.end(), [](const Neighbour& a, const Neighbour& b) { return a.gap < b.gap || (a.gap == b.gap && a.id < b.id); });
    for (const Neighbour& n : wall_order_) {
      const Wall<D>& w = walls_[static_cast<std::size_t>(n.id)];
      bool redundant = false;
      if (w.kind == WallKind::Plane)
        for (const Body<D>& kept : bodies_)
          redundant |= kept.wall->kind == WallKind::Plane && kept.wall->normal.dot(w.normal) > 0.95;
      if (!redundant && bodies_.size() < kMaxWallBodies) bodies_.push_back(Body<D>::of_wall(w));
    }
    const bool front_only = opt_.contact_bodies == ContactBodies::Front;
    for (const Neighbour& n : nb_) {
      if (front_only && !in_front_[static_cast<std::size_t>(n.id)]) continue;
      const Particle<D>& q = res.packing.particles[static_cast<std::size_t>(n.id)];
      if (!np_.gap_exceeds(p0, q, 2 * R)) bodies_.push_back(Body<D>::of_particle(q, n.id));
    }
  }

  /// Can one mobile of circumscribed radius R touch both bodies? Their true gap must be <= 2R.
  bool bridgeable(const Body<D>& a, const Body<D>& b, double R) const {
    if (a.is_wall() && b.is_wall()) return true;
    if (a.is_wall()) return np_.gap(*a.wall, *b.shaped).value <= 2 * R;
    if (b.is_wall()) return np_.gap(*b.wall, *a.shaped).value <= 2 * R;
    const double reach = a.radius + b.radius + 2 * R;
    if ((a.center - b.center).squaredNorm() > reach * reach) return false;
    return !np_.gap_exceeds(*a.shaped, *b.shaped, 2 * R);
  }

  /// Does p overlap a particle of V beyond the tolerance? The last blocker is tried first.
  bool overlaps_neighbour(const Particle<D>& p, const ShapePackResult<D>& res) {
    const double r = p.bounding_radius();
    const int n = static_cast<int>(nb_.size());
    auto blocks = [&](int q) {
      const Particle<D>& other = res.packing.particles[static_cast<std::size_t>(nb_[static_cast<std::size_t>(q)].id)];
      const double rk = other.bounding_radius();
      const double reach = r + rk;
      if ((other.pose.position - p.pose.position).squaredNorm() >= reach * reach) return false;
      return np_.overlap_beyond(other, p, tol_ * std::min(r, rk));
    };
    if (last_blocker_ < n && blocks(last_blocker_)) return true;
    for (int q = 0; q < n; ++q)
      if (q != last_blocker_ && blocks(q)) { last_blocker_ = q; return true; }
    return false;
  }

  /// Step 2.2 for one draft: a position touching s0 and D-1 bodies, overlapping nothing, inside.
  bool find_position(const Draft<D>& d, int s0, ShapePackResult<D>& res, Vec<D>& best) {
    const Particle<D>& p0 = res.packing.particles[static_cast<std::size_t>(s0)];
    const Vec<D> c0 = p0.pose.position;
    const double r0 = p0.bounding_radius(), R = d.bounding_radius();
    const bool keep_first = opt_.candidate == CandidateChoice::First;
    const Mobile<D> mobile = Mobile<D>::of_shape(d.shape, d.rotation);
    Particle<D> trial = at(d, c0);
    const double lower_bound_here = std::max(0.0, (c0 - seed_point_).norm() - r0 - R);
    const double lower_bound2 = lower_bound_here * lower_bound_here;
    bool found = false;
    double best_d2 = 0;
    int best_rank = 2;
    std::array<Body<D>, D> fixed;
    fixed[0] = Body<D>::of_particle(p0, s0);
    std::array<Placement<D>, ContactSolver<D>::kMaxCandidates> out;
    const ContactSolver<D>& fallback = registry_.default_solver();

    auto consider = [&](int i, int j) -> bool {
      fixed[1] = bodies_[static_cast<std::size_t>(i)];
      if constexpr (D == 3) fixed[2] = bodies_[static_cast<std::size_t>(j)];
      const std::span<const Body<D>> f(fixed.data(), D);
      const ContactSolver<D>& solver = registry_.pick(f, mobile);
      if (&solver != &fallback) ++res.analytic_solves;
      ++res.counters.solves;
      const int m = solver.solve(f, mobile, std::span<Placement<D>>(out.data(), out.size()));
      bool touches_wall = false;
      for (int q = 1; q < D; ++q) touches_wall |= fixed[static_cast<std::size_t>(q)].is_wall();
      const int rank = touches_wall ? 0 : 1;
      for (int q = 0; q < m; ++q) {
        const Vec<D>& x = out[static_cast<std::size_t>(q)].position;
        ++res.counters.candidates;
        double d2 = 0;
        if (!keep_first) {
          d2 = (x - seed_point_).squaredNorm();
          if (found && (rank > best_rank || (rank == best_rank && d2 >= best_d2))) continue;
        }
        trial.pose.position = x;
        if (overlaps_neighbour(trial, res)) { ++res.counters.rejected_overlap; continue; }
        if (!inside_container(trial)) { ++res.counters.rejected_container; continue; }
        found = true;
        best = x;
        best_d2 = d2;
        best_rank = rank;
        if (keep_first || (rank == 0 && best_d2 <= lower_bound2)) return true;
      }
      return false;
    };

    const int nb = static_cast<int>(bodies_.size());
    if constexpr (D == 2) {
      for (int i = 0; i < nb; ++i) {
        ++res.counters.pairs_considered;
        if (!reachable(bodies_[static_cast<std::size_t>(i)], c0, r0, R)) { ++res.counters.pairs_pruned; continue; }
        if (consider(i, i)) break;
      }
    } else {
      bool stop = false;
      for (int j = 1; j < nb && !stop; ++j) {
        const Body<D>& bj = bodies_[static_cast<std::size_t>(j)];
        if (!reachable(bj, c0, r0, R)) continue;
        for (int i = 0; i < j; ++i) {
          const Body<D>& bi = bodies_[static_cast<std::size_t>(i)];
          ++res.counters.pairs_considered;
          if (!bridgeable(bi, bj, R)) { ++res.counters.pairs_pruned; continue; }
          if (consider(i, j)) { stop = true; break; }
        }
      }
    }
    last_blocker_ = 0;
    return found;
  }

  /// A wall or particle a mobile of circumscribed radius R touching s0 can reach.
  bool reachable(const Body<D>& b, const Vec<D>& c0, double r0, double R) const {
    if (b.is_wall()) return true;  // walls_near already limited them to r0 + 2R
    const double reach = r0 + b.radius + 2 * R;
    return (b.center - c0).squaredNorm() <= reach * reach;
  }

  const Container<D>& container_;
  const std::vector<ShapeTemplate<D>>& templates_;
  PackerOptions opt_;
  StopCriteria stop_;
  Rng rng_;
  NarrowPhase<D> np_;
  SolverRegistry<D> registry_;
  ShapeContainment<D> containment_;
  double r_min_, r_max_;
  NeighbourGrid<D> grid_;
  Vec<D> seed_point_;
  double tol_ = 1e-6;
  double measure_ = 0;
  const std::vector<Particle<D>>* particles_ = nullptr;

  std::priority_queue<FrontEntry> heap_;
  std::vector<char> in_front_;
  std::vector<double> failed_radius_;
  std::vector<Draft<D>> pool_;
  std::vector<int> order_;
  std::vector<Neighbour> nb_;
  std::vector<Wall<D>> walls_;
  std::vector<Body<D>> bodies_;
  std::vector<Neighbour> wall_order_;
  int last_blocker_ = 0;
  std::unordered_set<std::int64_t> voids_reopened_;
};

}  // namespace

template <int D>
ShapePackResult<D> pack_shapes(const Container<D>& container, const std::vector<ShapeTemplate<D>>& templates,
                               const PackerOptions& options, const StopCriteria& stop, std::uint64_t seed,
                               const ProgressFn& progress) {
  ShapeFront<D> front(container, templates, options, stop, seed);
  return front.run(progress);
}

template ShapePackResult<2> pack_shapes<2>(const Container<2>&, const std::vector<ShapeTemplate<2>>&, const PackerOptions&,
                                           const StopCriteria&, std::uint64_t, const ProgressFn&);
template ShapePackResult<3> pack_shapes<3>(const Container<3>&, const std::vector<ShapeTemplate<3>>&, const PackerOptions&,
                                           const StopCriteria&, std::uint64_t, const ProgressFn&);

}  // namespace fp
