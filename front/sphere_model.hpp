#pragma once
// The particle model of the advancing front for spheres (3D) and disks (2D): centres and radii
// stored as arrays (SoA), the analytic contact solver inlined into the pair scan (`Solver` is a
// final class and a template parameter), overlap and containment tests on centres and radii only.
// It brings no FCL and no NLopt: a scene of spheres never touches the general-shape machinery.
// The front itself (F, the pool, the pair scan, voids, stops) is front/advancing_front.hpp.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
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
class SphereModel {
 public:
  using Input = RadiusDistribution;  ///< the size distribution of the radii
  using Draft = double;              ///< a drawn radius
  using Result = PackResult<D>;
  static constexpr int kMaxPlacements = ContactSolver<D>::kMaxSolutions;
  static constexpr bool kTwoContactFallback = D == 3;  ///< 3D: s0 and one body when no pair has a position
  static constexpr double kVoidSpacing = 2.0;          ///< void lattice spacing, in the sought draft's radius
  static constexpr double kVoidPoints = double(1 << 24);
  static constexpr std::uint64_t kClockEvery = 1024;   ///< picks between clock reads (a pick costs ~10 us)
  static constexpr bool kProbeSmallestByDefault = true;  ///< probe_smallest: auto (narrow ratios)
  static constexpr bool kTurns = false;                  ///< a ball has no orientation to choose

  SphereModel(const Container<D>& container, const RadiusDistribution& radii, const PackerOptions& options,
              const Aabb<D>& centres)
      : container_(container), dist_(radii), tol_(options.contact_tolerance),
        face_slack_(2 * std::sqrt(tol_ * (2 + tol_)) + 1e-12),
        grid_(grid_domain(centres, radii.r_max()), radii.r_min(), radii.r_max(), options.grid_cell_factor,
              options.hierarchical_grid_ratio) {}

  const NeighbourGrid<D>& grid() const { return grid_; }
  double r_min() const { return dist_.r_min(); }
  double r_max() const { return dist_.r_max(); }
  static double r_max_of(const Input& radii) { return radii.r_max(); }
  static double radius(Draft r) { return r; }

  void attach(Result& res, const StopCriteria& stop) {
    res_ = &res;
    res.contact_tolerance = tol_;
    res.packing.origin = container_.origin();
    if (stop.max_particles) res.packing.reserve(*stop.max_particles);
  }
  void finish(Result& res) const {
    res.grid_bytes = grid_.memory_bytes();
    res.grid_levels = grid_.levels();
  }

  Draft draw(Rng& rng) const { return dist_.sample(rng); }
  /// The law's share of radii at least r, by count.
  double share_at_least(double r) const { return 1.0 - dist_.cdf(std::nextafter(r, 0.0)); }

  // ---- a result's particles, for the blocks of a decomposed container (front/block_front.hpp) ----
  static std::size_t size(const Result& res) { return res.packing.size(); }
  static Draft draft_of(const Result& res, std::size_t i) { return res.packing.radii[i]; }
  static const Vec<D>& position_of(const Result& res, std::size_t i) { return res.packing.centers[i]; }
  static double measure_of(const Result& res, std::size_t i) { return ball_measure<D>(res.packing.radii[i]); }
  /// Appends particle i of `from` to `to`.
  static void append(Result& to, const Result& from, std::size_t i) {
    to.packing.add(from.packing.centers[i], from.packing.radii[i]);
    to.solid_measure += measure_of(from, i);
  }
  /// The particles as doubles, to send to another process (front/block_exchange.hpp): per
  /// particle its centre's D coordinates and its radius.
  static void append_data(const Result& res, std::vector<double>& out) {
    for (std::size_t i = 0; i < res.packing.size(); ++i) {
      for (int a = 0; a < D; ++a) out.push_back(res.packing.centers[i][a]);
      out.push_back(res.packing.radii[i]);
    }
  }
  /// Adds the particles of append_data()'s doubles.
  static void add_data(Result& res, const double* data, std::size_t doubles) {
    for (std::size_t k = 0; k + D < doubles; k += D + 1) {
      Vec<D> c;
      for (int a = 0; a < D; ++a) c[a] = data[k + a];
      res.packing.add(c, data[k + D]);
      res.solid_measure += ball_measure<D>(data[k + D]);
    }
  }
  /// Keeps the particles i with keep(i), in order.
  template <class Keep>
  static void keep_only(Result& res, Keep&& keep) {
    auto& P = res.packing;
    std::size_t n = 0;
    res.solid_measure = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (!keep(i)) continue;
      P.centers[n] = P.centers[i];
      P.radii[n] = P.radii[i];
      res.solid_measure += measure_of(res, n++);
    }
    P.centers.resize(n);
    P.radii.resize(n);
  }

  Vec<D> position(int id) const { return res_->packing.centers[id]; }
  double radius(int id) const { return res_->packing.radii[id]; }
  std::size_t count() const { return res_->packing.size(); }

  int add(Draft r, const Vec<D>& c) {
    const int id = res_->packing.add(c, r);
    grid_.insert(id, c, r);
    res_->solid_measure += ball_measure<D>(r);
    return id;
  }

  /// Inside the container and overlapping no placed particle (beyond the contact tolerance).
  bool fits(Draft r, const Vec<D>& c) const { return container_.contains_ball(c, r, tol_) && free_of_overlap(r, c); }

  /// The first particle of a cluster: strictly inside (no tolerance): a slide towards the interior
  /// would otherwise stop exactly at the tolerance, where any other rounding of the same distance
  /// (the validator's) sees the ball stick out.
  bool fits_strictly(Draft r, const Vec<D>& c) const { return container_.contains_ball(c, r, 0.0) && free_of_overlap(r, c); }

  /// How far the ball (x, r) is from touching the container boundary or a placed particle
  /// (> 0: it fits with that much to spare): what the thin-container searches maximise.
  double room(Draft r, const Vec<D>& x) const {
    double g = -container_.signed_distance(x) - r;
    grid_.for_each_within(x, r, [&](int, const Vec<D>&, double rk, double d2) { g = std::min(g, std::sqrt(d2) - rk - r); });
    return g;
  }

  /// The position of a particle of radius r touching particle `id` in direction u.
  Vec<D> touching(int id, Draft r, const Vec<D>& u) const { return position(id) + (radius(id) + r) * u; }

  /// Where the thin-container searches evaluate the room: exactly touching, for spheres.
  Vec<D> beside(int id, Draft r, const Vec<D>& u) const { return touching(id, r, u); }
  Vec<D> beside_both(int ia, int ib, Draft r, double phi) const { return touching_both(ia, ib, r, phi); }

  /// 3D: the point at angle phi of the circle of centres touching particles a and b.
  Vec<D> touching_both(int ia, int ib, Draft r, double phi) const {
    static_assert(D == 3);
    const Vec3 a = position(ia), b = position(ib);
    const double ra = radius(ia) + r, rb = radius(ib) + r;
    const Vec3 ab = b - a;
    const double d = ab.norm();
    const Vec3 k = ab / d;
    const double x = (d * d + ra * ra - rb * rb) / (2 * d);
    const double h = std::sqrt(std::max(0.0, ra * ra - x * x));
    const Vec3 e1 = (std::abs(k.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY()).cross(k).normalized();
    const Vec3 e2 = k.cross(e1);
    return a + x * k + h * (std::cos(phi) * e1 + std::sin(phi) * e2);
  }

  /// After the front ran empty: the pooled radius to seed at lattice point p, if any — the
  /// largest one, when a ball of that radius centred there is in the container and touches nothing.
  std::optional<std::size_t> void_draft(const std::vector<Draft>& pool, std::size_t largest, const Vec<D>& p) const {
    const double r = pool[largest];
    if (!container_.contains_ball(p, r, tol_)) return std::nullopt;
    bool empty = true;
    grid_.for_each_within(p, r, [&](int, const Vec<D>&, double, double) { empty = false; });
    if (!empty) return std::nullopt;
    return largest;
  }

  // ---- the pair scan around s0 ----

  /// Walls near s0 offered as contact bodies: every one gather_v found.
  void add_wall_bodies(int, double, const std::vector<Wall<D>>& walls, std::vector<Body<D>>& bodies) const {
    for (const Wall<D>& w : walls) bodies.push_back(Body<D>::of_wall(w));
  }
  /// A neighbour of s0 a mobile of radius r can touch together with s0: every one in V.
  bool may_pair_with_s0(int, int, double) const { return true; }
  Body<D> body(int id) const { return Body<D>::sphere(position(id), radius(id), id); }

  /// V is final for this s0: its centres and radii are copied contiguous for the overlap test,
  /// scanned nearest to s0 first.
  void neighbours_ready(const std::vector<front_parts::Neighbour>& nb) {
    nb_c_.clear();
    nb_r_.clear();
    for (const front_parts::Neighbour& n : nb) {
      nb_c_.push_back(position(n.id));
      nb_r_.push_back(radius(n.id));
    }
    last_blocker_ = 0;
  }

  void begin_placement(int s0, Draft r, std::span<const Body<D>> bodies) {
    session_.begin(Body<D>::sphere(position(s0), radius(s0), s0), r, bodies);
    bodies_ = bodies;
    // A wall with a face (a mesh facet, a polygon edge) can be touched with s0 only where the
    // mobile's centre, on the sphere of radius r0 + r around c0 and at height r over the plane,
    // has its foot over the face: on the circle of centres' feet. Facets a fine mesh offers
    // around s0 mostly fail this (the circle passes around them), and each would cost a scan of
    // pairs whose every position over_face() drops.
    const Vec<D> c0 = position(s0);
    const double reach = radius(s0) + r, slack = 1e-6 * reach + face_slack_ * r;
    reachable_.assign(bodies.size(), 1);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const Wall<D>* w = bodies[b].wall;
      if (w == nullptr || w->kind != WallKind::Plane || w->face_edges == 0) continue;
      const double rho = w->feet_radius(c0, r, reach);
      reachable_[b] = rho >= 0.0 && w->face_reaches(w->foot(c0), rho, slack);
    }
  }
  /// Whether body j (3D: the outer loop of the pair scan) can touch the mobile with s0.
  bool reachable(int j) const { return reachable_[j] != 0; }
  /// Whether bodies i and j can both touch one mobile of radius r (two particles farther apart
  /// than r_i + r_j + 2r cannot).
  bool bridgeable(int i, int j, Draft r) const {
    if (!reachable_[i]) return false;
    const Body<D>& bi = bodies_[i];
    const Body<D>& bj = bodies_[j];
    if (bi.is_wall() || bj.is_wall()) return true;
    const double reach = bi.radius + bj.radius + 2 * r;
    return (bi.center - bj.center).squaredNorm() <= reach * reach;
  }
  int solve(int i, int j, std::span<Placement<D>> out) { return session_.solve(i, j, out); }

  /// 3D, when no pair had any position: positions touching s0 and body b only.
  void two_contact(int s0, int b, Draft r, std::vector<Vec<D>>& out) const {
    if constexpr (D == 3) two_contact_positions(position(s0), radius(s0), bodies_[b], r, kTwoContactSamples, out);
  }

  /// Does the ball (x, r) overlap any particle of V by more than `allowance` x the contact
  /// tolerance? The neighbour that blocked the previous candidate is tried first: it usually
  /// blocks the next.
  bool overlaps_neighbour(Draft r, const Vec<D>& x, double allowance = 1.0) {
    const int n = static_cast<int>(nb_c_.size());
    const double tol = tol_ * allowance;
    auto blocks = [&](int q) {
      const double rk = nb_r_[q];
      const double lim = r + rk - tol * std::min(r, rk);
      return (nb_c_[q] - x).squaredNorm() < lim * lim;
    };
    if (last_blocker_ < n && blocks(last_blocker_)) return true;
    for (int q = 0; q < n; ++q)
      if (q != last_blocker_ && blocks(q)) { last_blocker_ = q; return true; }
    return false;
  }
  /// Whether the ball (x, r), tangent to body b's plane if b is a wall, touches it over its face:
  /// its centre's foot within the slack where the distance to the face's edge is still within the
  /// contact tolerance (r sqrt(2 tol), doubled against rounding).
  bool over_face(int b, Draft r, const Vec<D>& x) const {
    return !bodies_[b].is_wall() || bodies_[b].wall->over_face(x, face_slack_ * r);
  }
  bool inside(Draft r, const Vec<D>& x) const { return container_.contains_ball(x, r, tol_); }
  /// A mesh facet or polygon edge is offered as its whole plane (line): a position tangent to the
  /// plane beyond the facet's edges does not touch the container at all.
  bool touches_boundary(Draft r, const Vec<D>& x) const { return container_.signed_distance(x) >= -r - tol_ * r; }

 private:
  /// `centres`: where the centres can be (the container, or a block and its halo).
  static Aabb<D> grid_domain(Aabb<D> b, double r_max) {
    b.lo.array() -= r_max;
    b.hi.array() += r_max;
    return b;
  }

  bool free_of_overlap(double r, const Vec<D>& c) const {
    bool free = true;
    grid_.for_each_within(c, r, [&](int, const Vec<D>&, double rk, double d2) {
      const double lim = r + rk - tol_ * std::min(r, rk);
      if (d2 < lim * lim) free = false;
    });
    return free;
  }

  static constexpr int kTwoContactSamples = 24;  // per body: about 15 degrees apart

  const Container<D>& container_;
  const RadiusDistribution& dist_;
  double tol_;
  double face_slack_;  ///< over_face's slack, relative to the radius
  NeighbourGrid<D> grid_;
  Result* res_ = nullptr;
  typename Solver::Session session_;
  std::span<const Body<D>> bodies_;
  std::vector<char> reachable_;  // per body of the placement: can touch a mobile with s0 (begin_placement)
  std::vector<Vec<D>> nb_c_;  // V's centres and radii, contiguous for the overlap test
  std::vector<double> nb_r_;
  int last_blocker_ = 0;
};

}  // namespace fp
