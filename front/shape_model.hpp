#pragma once
// The particle model of the advancing front for particles of any shape (front/advancing_front.hpp
// is the front; front/sphere_model.hpp the model of spheres and the list of what a model
// provides). Drafts are shapes at their size and fixed orientation; neighbourhoods use
// circumscribed radii (the grid is the broad phase), candidate tests the narrow phase, and each
// contact problem goes to the solver the registry picks for the kinds involved (paper 004:
// wrappers where registered, minimisation otherwise).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "contact/minimisation_solver.hpp"
#include "contact/narrow_phase.hpp"
#include "contact/shape_containment.hpp"
#include "contact/solver_registry.hpp"
#include "core/geometry/container.hpp"
#include "core/geometry/neighbour_grid.hpp"
#include "core/io/scene.hpp"
#include "core/sampling/random_unit.hpp"
#include "core/sampling/rng.hpp"
#include "front/front_parts.hpp"
#include "front/shape_front.hpp"
#include "front/shape_template.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/sphere_shape.hpp"

namespace fp {

template <int D>
class ShapeModel {
 public:
  using Input = std::vector<ShapeTemplate<D>>;
  using Draft = fp::Draft<D>;
  using Result = ShapePackResult<D>;
  static constexpr int kMaxPlacements = ContactSolver<D>::kMaxCandidates;
  static constexpr bool kTwoContactFallback = false;  ///< no solver for s0 and one body of any shape
  /// Void lattice spacing, in r_max: finer than the spheres' 2, since an elongated draft fits
  /// many a void its circumscribed sphere does not.
  static constexpr double kVoidSpacing = 1.0;
  static constexpr double kVoidPoints = double(1 << 20);
  /// A pick costs from microseconds (capsules) to a second (ellipsoids): the clock is read at
  /// every one.
  static constexpr std::uint64_t kClockEvery = 1;
  /// probe_smallest: auto is off: measured 1.5-2x faster but 1-4 % looser (2D polygons 0.727 ->
  /// 0.719, ellipses 0.746 -> 0.720, capsules 0.739 -> 0.709; capsules in the femur 0.487 -> 0.473).
  static constexpr bool kProbeSmallestByDefault = false;
  /// Drafts have an orientation the front may choose within their law (orientation_trials, roll).
  static constexpr bool kTurns = true;

  ShapeModel(const Container<D>& container, const Input& templates, const PackerOptions& options,
              const Aabb<D>& centres)
      : container_(container), templates_(check(templates)), tol_(options.minimisation.gap_tolerance),
        orientation_trials_(options.orientation_trials), pocket_trials_(options.pocket_trials), face_to_face_(options.face_to_face),
        registry_(np_, options.minimisation, options.contact_solver == ContactSolverChoice::Auto),
        containment_(container, np_), r_min_(min_bounding(templates)), r_max_(r_max_of(templates)),
        grid_(grid_domain(centres, r_max_), r_min_, r_max_, options.grid_cell_factor, options.hierarchical_grid_ratio) {}

  const NeighbourGrid<D>& grid() const { return grid_; }
  double r_min() const { return r_min_; }
  double r_max() const { return r_max_; }
  /// The largest circumscribed radius the templates can draw.
  static double r_max_of(const Input& ts) {
    double r = 0;
    for (const auto& t : ts) r = std::max(r, t.bounding_max());
    return r;
  }
  static double radius(const Draft& d) { return d.bounding_radius(); }

  void attach(Result& res, const StopCriteria&) {
    res_ = &res;
    res.contact_tolerance = tol_;
    for (const auto& t : templates_) res.packing.template_names.push_back(t.family);
    res.packing.origin = container_.origin();
  }
  void finish(Result& res) const {
    const MinimisationStats& m = static_cast<const MinimisationSolver<D>&>(registry_.default_solver()).stats();
    res.solver.minimisation_solves = m.solves;
    res.solver.minimisations = m.minimisations;
    res.solver.gap_evaluations = m.evaluations;
    res.solver.minima_rejected = m.rejected_gap;
    res.solver.fcl_queries = np_.fcl_queries();
  }

  Draft draw(Rng& rng) const { return draw_draft<D>(templates_, rng); }

  // ---- a result's particles, for the blocks of a decomposed container (front/block_front.hpp) ----
  static std::size_t size(const Result& res) { return res.packing.size(); }
  static Draft draft_of(const Result& res, std::size_t i) {
    const Particle<D>& p = res.packing.particles[i];
    return Draft{p.template_id, p.size, p.shape, p.pose.rotation};
  }
  static const Vec<D>& position_of(const Result& res, std::size_t i) { return res.packing.particles[i].pose.position; }
  static double measure_of(const Result& res, std::size_t i) { return res.packing.particles[i].shape->measure(); }
  /// Appends particle i of `from` to `to`.
  static void append(Result& to, const Result& from, std::size_t i) {
    to.packing.particles.push_back(from.packing.particles[i]);
    to.solid_measure += measure_of(from, i);
  }
  /// Keeps the particles i with keep(i), in order.
  template <class Keep>
  static void keep_only(Result& res, Keep&& keep) {
    auto& P = res.packing.particles;
    std::size_t n = 0;
    res.solid_measure = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (!keep(i)) continue;
      if (n != i) P[n] = std::move(P[i]);
      res.solid_measure += measure_of(res, n++);
    }
    P.resize(n);
  }

  const Particle<D>& particle(int id) const { return res_->packing.particles[static_cast<std::size_t>(id)]; }
  Vec<D> position(int id) const { return particle(id).pose.position; }
  double radius(int id) const { return particle(id).bounding_radius(); }
  std::size_t count() const { return res_->packing.size(); }

  int add(const Draft& d, const Vec<D>& x) {
    auto& P = res_->packing.particles;
    const int id = static_cast<int>(P.size());
    Particle<D> p = at(d, x);
    const double r = p.bounding_radius();
    res_->solid_measure += p.shape->measure();
    P.push_back(std::move(p));
    grid_.insert(id, x, r);
    return id;
  }

  bool fits(const Draft& d, const Vec<D>& x) const {
    const Particle<D> p = at(d, x);
    return containment_.inside(p, tol_) && free_of_overlap(p);
  }
  bool fits_strictly(const Draft& d, const Vec<D>& x) const { return fits(d, x); }

  /// Room to spare around the draft at x: the least gap to the placed particles and to the
  /// container boundary (what the thin-container searches maximise).
  double room(const Draft& d, const Vec<D>& x) const {
    const Particle<D> p = at(d, x);
    return std::min(min_gap(p), -containment_.protrusion(p));
  }

  /// The draft brought from particle `id`'s reference point along u until it touches what is
  /// placed (bisection on the gap: overlapping at 0, apart beyond the two circumscribed radii).
  Vec<D> touching(int id, const Draft& d, const Vec<D>& u) const {
    const Vec<D> c0 = position(id);
    Particle<D> p = at(d, c0);
    double lo = 0, hi = (radius(id) + p.bounding_radius()) * (1 + 1e-9);
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      p.pose.position = c0 + mid * u;
      (min_gap(p) >= 0 ? hi : lo) = mid;
    }
    return c0 + hi * u;
  }

  /// 3D: the draft brought from particle a along the direction at angle phi around the axis
  /// a -> b, 60 degrees off it (where equal spheres touching both lie), until it touches.
  Vec<D> touching_both(int ia, int ib, const Draft& d, double phi) const { return touching(ia, d, off_axis(ia, ib, phi)); }

  /// Where the thin-container searches evaluate the room (thousands of directions): the
  /// circumscribed spheres touching, not the bisection of `touching` (80 gap queries each).
  Vec<D> beside(int id, const Draft& d, const Vec<D>& u) const { return position(id) + (radius(id) + radius(d)) * u; }
  Vec<D> beside_both(int ia, int ib, const Draft& d, double phi) const { return beside(ia, d, off_axis(ia, ib, phi)); }

  /// After the front ran empty: the first pooled draft that fits at lattice point p (the real
  /// test: an elongated draft fits many a void its circumscribed sphere does not).
  std::optional<std::size_t> void_draft(const std::vector<Draft>& pool, std::size_t, const Vec<D>& p) const {
    if (!(container_.signed_distance(p) < 0)) return std::nullopt;
    for (std::size_t q = 0; q < pool.size(); ++q)
      if (fits(pool[q], p)) return q;
    return std::nullopt;
  }

  // ---- the pair scan around s0 ----

  /// Walls near s0 offered as contact bodies: those whose true gap to s0 a mobile of radius R
  /// can bridge, nearest first, at most kMaxWallBodies (a box corner needs 3; a fine mesh offers
  /// dozens of facets near s0). Each draft then keeps only the facets whose face it can reach
  /// (find_wall_feet), and a position tangent to a facet's plane beyond its face is dropped
  /// before it is tested (over_face). (Before the faces, planes within 18 degrees of a kept one
  /// were dropped and 4 kept: on the femur 28 of 1,987 capsules touched the surface; now 185 of
  /// 2,001 at the same speed: experiments/mesh-speed/RESULTS.md.)
  void add_wall_bodies(int s0, double R, const std::vector<Wall<D>>& walls, std::vector<Body<D>>& bodies) {
    const Particle<D>& p0 = particle(s0);
    wall_order_.clear();
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const double g = np_.gap(walls[k], p0).value;
      if (g <= 2 * R) wall_order_.push_back({g, static_cast<int>(k)});
    }
    std::sort(wall_order_.begin(), wall_order_.end(), [](const front_parts::Neighbour& a, const front_parts::Neighbour& b) {
      return a.gap < b.gap || (a.gap == b.gap && a.id < b.id);
    });
    if (wall_order_.size() > kMaxWallBodies) wall_order_.resize(kMaxWallBodies);
    for (const front_parts::Neighbour& n : wall_order_) bodies.push_back(Body<D>::of_wall(walls[static_cast<std::size_t>(n.id)]));
  }
  /// Only neighbours whose true gap to s0 a mobile of diameter 2R can bridge (the
  /// circumscribed-sphere test of V is loose for elongated shapes).
  bool may_pair_with_s0(int s0, int id, double R) const { return !np_.gap_exceeds(particle(s0), particle(id), 2 * R); }
  Body<D> body(int id) const { return Body<D>::of_particle(particle(id), id); }

  void neighbours_ready(const std::vector<front_parts::Neighbour>& nb) {
    nb_ = &nb;
    last_blocker_ = 0;
  }

  void begin_placement(int s0, const Draft& d, std::span<const Body<D>> bodies) {
    bodies_ = bodies;
    mobile_ = Mobile<D>::of_shape(d.shape, d.rotation);
    trial_ = at(d, position(s0));
    c0_ = position(s0);
    r0_ = radius(s0);
    R_ = radius(d);
    fixed_[0] = Body<D>::of_particle(particle(s0), s0);
    // V: the solvers may leave out positions that overlap it (the front would reject them).
    obstacles_.clear();
    for (const front_parts::Neighbour& n : *nb_) obstacles_.push_back(&particle(n.id));
    registry_.set_obstacles(obstacles_, tol_);
    find_wall_feet(d, bodies);
  }
  /// A wall (walls_near limited them to r0 + 2R) or a particle a mobile touching s0 can reach.
  bool reachable(int j) const {
    const Body<D>& b = bodies_[static_cast<std::size_t>(j)];
    if (b.is_wall()) return feet_[static_cast<std::size_t>(j)].reachable;
    const double reach = r0_ + b.radius + 2 * R_;
    return (b.center - c0_).squaredNorm() <= reach * reach;
  }
  /// Can one mobile of circumscribed radius R touch both bodies? Their true gap must be <= 2R.
  bool bridgeable(int i, int j, const Draft&) const {
    const Body<D>& a = bodies_[static_cast<std::size_t>(i)];
    const Body<D>& b = bodies_[static_cast<std::size_t>(j)];
    if (!feet_[static_cast<std::size_t>(i)].reachable || !feet_[static_cast<std::size_t>(j)].reachable) return false;
    if (a.is_wall() && b.is_wall()) return true;
    if (a.is_wall()) return np_.gap(*a.wall, *b.shaped).value <= 2 * R_;
    if (b.is_wall()) return np_.gap(*b.wall, *a.shaped).value <= 2 * R_;
    const double reach = a.radius + b.radius + 2 * R_;
    if ((a.center - b.center).squaredNorm() > reach * reach) return false;
    return !np_.gap_exceeds(*a.shaped, *b.shaped, 2 * R_);
  }
  int solve(int i, int j, std::span<Placement<D>> out) {
    fixed_[1] = bodies_[static_cast<std::size_t>(i)];
    if constexpr (D == 3) fixed_[2] = bodies_[static_cast<std::size_t>(j)];
    const std::span<const Body<D>> f(fixed_.data(), D);
    const ContactSolver<D>& solver = registry_.pick(f, mobile_);
    if (&solver != &registry_.default_solver()) ++res_->solver.analytic_solves;
    return solver.solve(f, mobile_, out);
  }
  void two_contact(int, int, const Draft&, std::vector<Vec<D>>&) const {}

  // ---- the orientation of a draft (front/advancing_front.hpp: orientation trials and the roll) ----

  /// Orientations tried per placement: the packer's orientation_trials; 1 for a fixed law, and
  /// for a ball (every orientation of it is the same body).
  int orientation_trials(const Draft& d) const {
    return law_of(d).kind() == OrientationKind::Fixed || is_ball(d) ? 1 : orientation_trials_;
  }
  /// Orientations the pocket trials draw: the packer's pocket_trials under an isotropic law; none
  /// for a ball (one orientation is all of them), and none for any other law: choosing among its
  /// draws by what fits the pocket biases it (capsules under a Watson law of order 0.71 came out
  /// at 0.64, polar angle p = 2e-5, with 32). Under the isotropic law the marginal law is kept;
  /// the relation to the radius from the seed only in the radial frame (front/radial_frame.hpp).
  int pocket_trials(const Draft& d) const { return isotropic(d) ? pocket_trials_ : 0; }
  /// Whether the draft's law is isotropic (and it is no ball): the radial frame applies.
  bool isotropic(const Draft& d) const { return law_of(d).kind() == OrientationKind::Isotropic && !is_ball(d); }
  /// Whether the draft may turn after it is positioned without leaving its law: any turn keeps an
  /// isotropic law isotropic in law, a turn about the body axis keeps a 3D law about an axis
  /// (its spin is uniform); a fixed law and a 2D law about an axis allow none.
  bool may_roll(const Draft& d) const {
    const OrientationLaw<D>& law = law_of(d);
    return !is_ball(d) && (law.kind() == OrientationKind::Isotropic || law.free_spin());
  }
  const Mat<D>& orientation(const Draft& d) const { return d.rotation; }
  void set_orientation(Draft& d, const Mat<D>& r) const { d.rotation = r; }
  /// Another trial orientation for the draft about to be placed against s0 (begin_placement):
  /// from its law; with face_to_face, for a polytope against a polytope s0 under an isotropic
  /// law, one of its faces turned against one of s0's (both drawn at random) and spun at random
  /// about their common normal (3D): angular particles pack by face contacts. If s0's
  /// orientation is a sample of the isotropic law, so is this one (s0's rotation times an
  /// independent random rotation).
  void redraw_orientation(Draft& d, Rng& rng) const {
    const auto* mine = dynamic_cast<const ConvexPolytopeShape<D>*>(d.shape.get());
    const Particle<D>& p0 = *fixed_[0].shaped;
    const auto* theirs = dynamic_cast<const ConvexPolytopeShape<D>*>(p0.shape.get());
    if (!face_to_face_ || !mine || !theirs || law_of(d).kind() != OrientationKind::Isotropic) {
      d.rotation = law_of(d).draw(rng);
      return;
    }
    const auto& m = mine->plane_normals();
    const auto& f = theirs->plane_normals();
    const Vec<D> own = m[static_cast<std::size_t>(rng.below(m.size()))];
    const Vec<D> against = -(p0.pose.rotation * f[static_cast<std::size_t>(rng.below(f.size()))]);
    if constexpr (D == 2) {
      d.rotation = rotation_about<2>(Vec2::Zero(), std::atan2(against.y(), against.x()) - std::atan2(own.y(), own.x()));
    } else {
      const Mat<3> align = Eigen::Quaterniond::FromTwoVectors(own, against).toRotationMatrix();
      d.rotation = rotation_about<3>(against, 2 * kPi * rng.uniform01()) * align;
    }
  }
  /// Turns the draft by an angle uniform in [-angle, angle]: about a random axis (isotropic law),
  /// about its own body axis (a law about an axis), in the plane (2D).
  void turn(Draft& d, double angle, Rng& rng) const {
    const double theta = angle * rng.uniform(-1.0, 1.0);
    if constexpr (D == 2) {
      d.rotation = rotation_about<2>(Vec2::Zero(), theta) * d.rotation;
    } else {
      const Vec3 axis = law_of(d).kind() == OrientationKind::Isotropic ? random_unit<3>(rng) : Vec3(d.rotation.col(0));
      d.rotation = rotation_about<3>(axis, theta) * d.rotation;
    }
  }
  /// The roll begins: its solves need no obstacles (the front checks V), and a solver that keeps
  /// per-orientation work for them (the ball wrapper's loci of V) would redo it at every turn.
  void begin_roll() { registry_.set_obstacles({}, tol_); }
  /// The placement in progress (begin_placement) takes the draft's current orientation.
  void orient(const Draft& d) {
    mobile_ = Mobile<D>::of_shape(d.shape, d.rotation);
    trial_.pose.rotation = d.rotation;
    find_wall_feet(d, bodies_);
  }

  /// Does the draft at x overlap a particle of V beyond `allowance` x the tolerance? The last
  /// blocker first.
  bool overlaps_neighbour(const Draft&, const Vec<D>& x, double allowance = 1.0) {
    trial_.pose.position = x;
    const double r = R_, tol = tol_ * allowance;
    const int n = static_cast<int>(nb_->size());
    auto blocks = [&](int q) {
      const Particle<D>& other = particle((*nb_)[static_cast<std::size_t>(q)].id);
      const double rk = other.bounding_radius();
      const double reach = r + rk;
      if ((other.pose.position - x).squaredNorm() >= reach * reach) return false;
      return np_.overlap_beyond(other, trial_, tol * std::min(r, rk));
    };
    if (last_blocker_ < n && blocks(last_blocker_)) return true;
    for (int q = 0; q < n; ++q)
      if (q != last_blocker_ && blocks(q)) { last_blocker_ = q; return true; }
    return false;
  }
  /// Whether the draft at x, tangent to body b's plane if b is a wall with a face, touches it over
  /// the face: its lowest point toward the plane (begin_placement) has its foot over the face,
  /// within a thousandth of its size. A shape that touches the plane along an edge or a face of
  /// its own (several lowest points), or has no rounded cores, is not filtered.
  bool over_face(int b, const Draft&, const Vec<D>& x) const {
    const WallFoot& f = feet_[static_cast<std::size_t>(b)];
    return !f.single || bodies_[static_cast<std::size_t>(b)].wall->over_face(x + f.lowest, kFaceSlack * R_);
  }
  bool inside(const Draft&, const Vec<D>& x) {
    trial_.pose.position = x;
    last_protrusion_ = containment_.protrusion(trial_);
    return last_protrusion_ <= tol_ * R_;
  }
  /// After inside() at the same x: the draft reaches the boundary within the tolerance. A mesh
  /// facet or polygon edge is offered as its whole plane (line): a position tangent to the plane
  /// beyond the facet's edges does not touch the container and must not rank as a wall contact.
  bool touches_boundary(const Draft&, const Vec<D>&) const { return last_protrusion_ >= -tol_ * R_; }

 private:
  static constexpr std::size_t kMaxWallBodies = 12;
  static constexpr double kFaceSlack = 1e-3;  ///< over_face's slack, relative to the mobile's circumscribed radius

  /// Per body of the placement: for a wall with a face, where the mobile touches its plane.
  struct WallFoot {
    bool reachable = true;          ///< a mobile touching s0 can touch the face (conservative)
    bool single = false;            ///< one lowest point toward the plane (over_face can tell)
    Vec<D> lowest = Vec<D>::Zero(); ///< its offset from the reference point (world axes), on the plane when touching
  };

  /// The mobile's rounded cores give its lowest points toward each faced wall's plane: the
  /// reference point is then at height `support` over the plane, and the contact's foot is the
  /// lowest point's. A mobile touching s0 has its reference point within r0 + R of c0 (the
  /// circumscribed balls meet): its feet lie in a disk around c0's foot, and the face must come
  /// within that disk's radius (plus the spread of the lowest points) of the contact's foot.
  void find_wall_feet(const Draft& d, std::span<const Body<D>> bodies) {
    feet_.assign(bodies.size(), WallFoot{});
    d.shape->rounded_cores(cores_);
    if (cores_.empty()) return;
    const double reach = r0_ + R_, tie = 1e-9 * R_;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const Wall<D>* w = bodies[b].wall;
      if (w == nullptr || w->kind != WallKind::Plane || w->face_edges == 0) continue;
      double low = std::numeric_limits<double>::infinity();
      for (const RoundedCore<D>& core : cores_)
        for (const Vec<D>& v : core.points) low = std::min(low, w->normal.dot(d.rotation * v) - core.radius);
      WallFoot& f = feet_[b];
      double spread = 0.0;
      int count = 0;
      for (const RoundedCore<D>& core : cores_)
        for (const Vec<D>& v : core.points) {
          const Vec<D> o = d.rotation * v;
          if (w->normal.dot(o) - core.radius > low + tie) continue;
          const Vec<D> along = o - w->normal.dot(o) * w->normal;  // its offset along the plane
          if (count++ == 0) f.lowest = along;
          else spread = std::max(spread, (along - f.lowest).norm());
        }
      f.single = count == 1;
      const double feet = w->feet_radius(c0_, -low, reach);  // the reference point's height is -low
      const double rho = feet + spread + 1e-6 * reach;
      f.reachable = feet >= 0.0 && w->face_distance2(Vec<D>(w->foot(c0_) + f.lowest)) <= rho * rho;
    }
  }

  static bool is_ball(const Draft& d) { return d.shape->kind() == SphereShape<D>::kKind; }
  const OrientationLaw<D>& law_of(const Draft& d) const { return templates_[static_cast<std::size_t>(d.template_id)].orientation_law; }

  static const Input& check(const Input& ts) {
    if (ts.empty()) throw std::invalid_argument("pack_shapes: no particle templates");
    return ts;
  }
  static double min_bounding(const Input& ts) {
    double r = std::numeric_limits<double>::infinity();
    for (const auto& t : ts) r = std::min(r, t.bounding_min());
    return r;
  }
  /// `centres`: where the centres can be (the container, or a block and its halo).
  static Aabb<D> grid_domain(Aabb<D> b, double r_max) {
    b.lo.array() -= r_max;
    b.hi.array() += r_max;
    return b;
  }

  /// 3D: the unit direction at angle phi around the axis a -> b, 60 degrees off it.
  Vec<D> off_axis(int ia, int ib, double phi) const {
    static_assert(D == 3);
    const Vec3 k = (position(ib) - position(ia)).normalized();
    const Vec3 e1 = (std::abs(k.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY()).cross(k).normalized();
    const Vec3 e2 = k.cross(e1);
    return 0.5 * k + (std::sqrt(3.0) / 2) * (std::cos(phi) * e1 + std::sin(phi) * e2);
  }

  Particle<D> at(const Draft& d, const Vec<D>& x) const {
    Particle<D> p;
    p.shape = d.shape;
    p.pose.position = x;
    p.pose.rotation = d.rotation;
    p.template_id = d.template_id;
    p.size = d.size;
    return p;
  }

  /// p overlaps no placed particle (beyond the tolerance).
  bool free_of_overlap(const Particle<D>& p) const {
    bool free = true;
    const double r = p.bounding_radius();
    grid_.for_each_within(p.pose.position, r, [&](int id, const Vec<D>&, double rk, double) {
      if (free && np_.overlap_beyond(particle(id), p, tol_ * std::min(r, rk))) free = false;
    });
    return free;
  }

  /// Least gap between p and the placed particles near it (+inf if none is near).
  double min_gap(const Particle<D>& p) const {
    double g = std::numeric_limits<double>::infinity();
    grid_.for_each_within(p.pose.position, p.bounding_radius(), [&](int id, const Vec<D>&, double, double) {
      g = std::min(g, np_.gap(particle(id), p).value);
    });
    return g;
  }

  const Container<D>& container_;
  const Input& templates_;
  double tol_;
  int orientation_trials_;
  int pocket_trials_;
  bool face_to_face_;
  NarrowPhase<D> np_;
  SolverRegistry<D> registry_;
  ShapeContainment<D> containment_;
  double r_min_, r_max_;
  NeighbourGrid<D> grid_;
  Result* res_ = nullptr;
  std::vector<const Particle<D>*> obstacles_;  ///< V of the placement in progress

  // The placement in progress (begin_placement).
  std::span<const Body<D>> bodies_;
  std::array<Body<D>, D> fixed_;
  Mobile<D> mobile_;
  Particle<D> trial_;
  Vec<D> c0_ = Vec<D>::Zero();
  double r0_ = 0, R_ = 0;
  const std::vector<front_parts::Neighbour>* nb_ = nullptr;
  int last_blocker_ = 0;
  double last_protrusion_ = 0;  ///< of the last candidate tested by inside()
  std::vector<front_parts::Neighbour> wall_order_;
  std::vector<WallFoot> feet_;             ///< per body of the placement (find_wall_feet)
  std::vector<RoundedCore<D>> cores_;      ///< the draft's rounded cores (scratch)
};

}  // namespace fp
