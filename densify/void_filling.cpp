#include "densify/void_filling.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "contact/sphere_contact_solver.hpp"
#include "contact/sphere_placement.hpp"
#include "contact/tangent_sphere.hpp"
#include "core/geometry/delaunay_cgal.hpp"
#include "core/geometry/neighbour_grid.hpp"
#include "core/geometry/tet_void.hpp"
#include "core/sampling/rng.hpp"

namespace fp {

const char* to_string(VoidFillingStop stop) {
  switch (stop) {
    case VoidFillingStop::NoVoidFits: return "no void fits a sphere";
    case VoidFillingStop::Rounds: return "round limit";
    case VoidFillingStop::VolumeFraction: return "volume fraction";
    case VoidFillingStop::ParticleCount: return "particle count";
  }
  return "?";
}

VoidFillingReport& VoidFillingReport::operator+=(const VoidFillingReport& o) {
  added += o.added;
  rounds += o.rounds;
  stop = o.stop;
  for (auto [mine, theirs] : {std::pair{&voids, &o.voids}, {&voids_open, &o.voids_open}, {&mirrored, &o.mirrored},
                              {&positions_tried, &o.positions_tried}, {&rejected_overlap, &o.rejected_overlap},
                              {&rejected_container, &o.rejected_container}, {&rejected_contacts, &o.rejected_contacts},
                              {&radii_drawn, &o.radii_drawn}, {&radii_unplaced, &o.radii_unplaced},
                              {&radii_reduced, &o.radii_reduced}, {&radii_capped, &o.radii_capped}})
    *mine += *theirs;
  solid_after = o.solid_after;
  max_overlap_over_r_min = std::max(max_overlap_over_r_min, o.max_overlap_over_r_min);
  seconds += o.seconds;
  triangulation_seconds += o.triangulation_seconds;
  return *this;
}

namespace {

/// The stage's own random stream: its draws do not depend on how many the packer made.
constexpr std::uint64_t kStream = 0x766f696466696c6cULL;  // "voidfill"
/// Distribution: the pooled radii tried in one void, largest first.
constexpr int kRadiiPerVoid = 3;
/// Mirrors are moved off their exact place by this fraction of their distance (see below).
constexpr double kMirrorJitter = 1e-6;
/// A void's room is compared with r_min within this relative slack (rounding of the fit).
constexpr double kRoomSlack = 1e-9;

template <int D>
class VoidFiller {
 public:
  using Simplex = typename GrowingDelaunay<D>::Simplex;

  VoidFiller(Packing<D>& packing, const Container<D>& container, const RadiusDistribution& dist, const DensifyOptions& o,
             std::uint64_t seed, double tol, const VoidRegion<D>* region)
      : P_(packing), C_(container), dist_(dist), o_(o), rng_(seed ^ kStream), region_(region),
        r_min_(dist.r_min()), r_max_(dist.r_max()), allowance_(o.overlap * dist.r_min()),
        z_min_(o.z_min > 0 ? o.z_min : D), measure_(region ? region->measure : container.measure()),
        grid_(container.bounds(), std::min(r_min_, smallest_radius(packing)), std::max(r_max_, largest_radius(packing))),
        place_(packing, grid_, &container, r_min_, tol, allowance_, z_min_) {
    for (std::size_t i = 0; i < P_.size(); ++i)
      if (!region_ || region_->contains(P_.centers[i])) solid_ += ball_measure<D>(P_.radii[i]);
    rep_.before = P_.size();
    rep_.solid_before = solid_;
    if (!o_.list.empty()) {
      pool_ = o_.list;
      std::sort(pool_.begin(), pool_.end(), std::greater<>());
    } else if (o_.radii == VoidRadii::Distribution) {
      // Auto: the unplaced draws shift the radii's empirical CDF by at most pool / N, kept at
      // half of 1 / sqrt(N), a third of the K-S test's critical 1.36 / sqrt(N) at 5 %.
      const std::size_t pool = o_.radius_pool > 0 ? static_cast<std::size_t>(o_.radius_pool)
                                                  : std::max<std::size_t>(4, static_cast<std::size_t>(std::ceil(
                                                                                 0.5 * std::sqrt(static_cast<double>(P_.size())))));
      while (pool_.size() < pool) draw();
    }
  }

  VoidFillingReport run() {
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
      if (reached()) break;
      if (o_.rounds > 0 && rep_.rounds >= o_.rounds) {
        rep_.stop = VoidFillingStop::Rounds;
        break;
      }
      if (fill_round() == 0 && !reached()) {
        rep_.stop = VoidFillingStop::NoVoidFits;
        break;
      }
    }
    rep_.added = P_.size() - rep_.before;
    rep_.solid_after = solid_;
    rep_.radii_unplaced = pool_.size();
    const PlacementRejections& rej = place_.rejections();
    rep_.positions_tried = rej.tried;
    rep_.rejected_container = rej.container;
    rep_.rejected_overlap = rej.overlap;
    rep_.rejected_contacts = rej.contacts;
    rep_.radii_reduced = rej.reduced;
    rep_.max_overlap_over_r_min = place_.deepest_overlap() / r_min_;
    rep_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return rep_;
  }

 private:
  static double smallest_radius(const Packing<D>& p) {
    double r = std::numeric_limits<double>::infinity();
    for (double x : p.radii)
      if (x > 0) r = std::min(r, x);
    return r;
  }
  static double largest_radius(const Packing<D>& p) {
    double r = 0;
    for (double x : p.radii) r = std::max(r, x);
    return r;
  }

  void draw() {
    if (!o_.list.empty()) return;  // the list's radii only
    const double r = dist_.sample(rng_);
    pool_.insert(std::upper_bound(pool_.begin(), pool_.end(), r, std::greater<>()), r);  // largest first
    ++rep_.radii_drawn;
  }

  /// phi0 or N0 reached (recorded as the stop).
  bool reached() {
    if (o_.target_volume_fraction && solid_ / measure_ >= *o_.target_volume_fraction) {
      rep_.stop = VoidFillingStop::VolumeFraction;
      return true;
    }
    if ((o_.max_particles && P_.size() >= *o_.max_particles) || (!o_.list.empty() && pool_.empty())) {
      rep_.stop = VoidFillingStop::ParticleCount;
      return true;
    }
    return false;
  }

  /// The wall's distance to c (inside: positive) and c's mirror across it; false for a wall that
  /// has no mirror (a vertex, a centre on a curved wall's axis).
  static bool reflect(const Wall<D>& w, const Vec<D>& c, double& distance, Vec<D>& mirror, TangentBody<D>& plane) {
    switch (w.kind) {
      case WallKind::Plane:
        distance = w.normal.dot(c - w.point);
        mirror = c - 2.0 * distance * w.normal;
        plane = TangentBody<D>::wall(w.point, w.normal);
        return true;
      case WallKind::Sphere:
      case WallKind::Cylinder: {
        Vec<D> radial = c - w.point;
        if (w.kind == WallKind::Cylinder) radial -= radial.dot(w.axis) * w.axis;
        const double d = radial.norm();
        if (!(d > 0)) return false;
        const Vec<D> u = radial / d;
        distance = w.radius - d;
        mirror = c + 2.0 * distance * u;
        plane = TangentBody<D>::wall(c + distance * u, -u);  // the tangent plane at c's foot
        return true;
      }
      case WallKind::Vertex: return false;
    }
    return false;
  }

  /// The spheres added since the last round, and the mirrors of those near the walls (at most
  /// D walls each, nearest first), appended to the triangulation's points.
  void add_points() {
    const std::size_t first = points_.size();
    for (std::size_t i = first_new_; i < P_.size(); ++i) {
      points_.push_back(P_.centers[i]);
      point_radii_.push_back(P_.radii[i]);
      vertex_.push_back(static_cast<int>(i));
    }
    std::vector<Wall<D>> near;
    struct Near { double distance; Vec<D> mirror; TangentBody<D> plane; std::size_t k; };
    std::vector<Near> found;
    for (std::size_t i = first_new_; i < P_.size(); ++i) {
      const Vec<D>& c = P_.centers[i];
      const double reach = P_.radii[i] + 2.0 * r_max_;
      if (-C_.signed_distance(c) > reach) continue;
      near.clear();
      C_.walls_near(c, reach, near);
      found.clear();
      for (std::size_t k = 0; k < near.size(); ++k) {
        Near n{};
        n.k = k;
        if (!reflect(near[k], c, n.distance, n.mirror, n.plane) || n.distance > reach) continue;
        // A centre and its mirror, with another pair, lie on one circle: degenerate for the
        // triangulation's exact predicates, which then fall back to slow exact arithmetic. The
        // mirrors are only where voids are looked for (the walls themselves are what new spheres
        // touch), so each is moved off its exact place by a part in 10^6 of its distance.
        n.mirror += (n.mirror - c) * kMirrorJitter * (1.0 + static_cast<double>((i * 7 + k) % 13) / 13.0);
        found.push_back(n);
      }
      std::stable_sort(found.begin(), found.end(), [](const Near& a, const Near& b) { return a.distance < b.distance; });
      int kept = 0;
      const std::size_t mine = points_.size();
      for (const Near& n : found) {
        if (kept == D) break;
        bool again = false;  // coplanar facets of a mesh give the same mirror
        for (std::size_t q = mine; q < points_.size() && !again; ++q)
          again = (points_[q] - n.mirror).norm() <= 1e-9 * P_.radii[i];
        if (again) continue;
        vertex_.push_back(-1 - static_cast<int>(walls_.size()));
        walls_.push_back(near[n.k]);
        planes_.push_back(n.plane);
        points_.push_back(n.mirror);
        point_radii_.push_back(P_.radii[i]);
        ++kept;
      }
    }
    rep_.mirrored += points_.size() - first - (P_.size() - first_new_);
    first_new_ = P_.size();
    triangulated_ = first;
  }

  /// One round: the triangulation grown by what the previous round added, and a pass over its
  /// new voids (and, in distribution mode, the open voids a pooled radius may still fit),
  /// largest first; returns the spheres added.
  std::size_t fill_round() {
    const std::size_t before = P_.size();
    add_points();
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<Simplex> simplices = dt_.insert(points_, triangulated_);
    rep_.triangulation_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++rep_.rounds;
    simplices.insert(simplices.end(), waiting_.begin(), waiting_.end());
    waiting_.clear();

    struct Void { double measure; std::uint32_t simplex; };
    std::vector<Void> voids;
    voids.reserve(simplices.size());
    for (std::uint32_t s = 0; s < simplices.size(); ++s) {
      std::array<Vec<D>, D + 1> c;
      std::array<double, D + 1> r;
      bool real = false;
      for (int k = 0; k <= D; ++k) {
        const std::uint32_t v = simplices[s][static_cast<std::size_t>(k)];
        c[static_cast<std::size_t>(k)] = points_[v];
        r[static_cast<std::size_t>(k)] = point_radii_[v];
        real |= vertex_[v] >= 0;
      }
      if (!real) continue;
      const double m = simplex_void_measure<D>(c, r);
      if (std::isfinite(m)) voids.push_back({m, s});
    }
    rep_.voids += voids.size();
    std::sort(voids.begin(), voids.end(), [](const Void& a, const Void& b) {
      return a.measure != b.measure ? a.measure > b.measure : a.simplex < b.simplex;
    });
    for (const Void& v : voids) {
      if (fill(simplices[v.simplex]) == Outcome::Open && o_.radii == VoidRadii::Distribution)
        waiting_.push_back(simplices[v.simplex]);
      if (reached()) break;
    }
    return P_.size() - before;
  }

  /// What became of a void: filled, too small for r_min (or no sphere touches its bodies), or
  /// open (room for r_min, not filled).
  enum class Outcome { Filled, Closed, Open };

  /// Tries to put one sphere into the void of simplex `s`.
  Outcome fill(const Simplex& s) {
    // Its bodies: the spheres at its vertices, the walls of its mirror vertices (once each).
    std::array<Body<D>, D + 1> bodies;
    std::array<TangentBody<D>, D + 1> exact, estimate;
    std::array<int, D + 1> wall_of;
    int nb = 0, walls = 0;
    Vec<D> centroid = Vec<D>::Zero();
    for (int k = 0; k <= D; ++k) {
      const std::uint32_t v = s[static_cast<std::size_t>(k)];
      centroid += points_[v] / (D + 1.0);
      estimate[static_cast<std::size_t>(k)] = TangentBody<D>::sphere(points_[v], point_radii_[v]);
      if (vertex_[v] >= 0) {
        bodies[static_cast<std::size_t>(nb)] = Body<D>::sphere(points_[v], point_radii_[v], vertex_[v]);
        exact[static_cast<std::size_t>(nb++)] = estimate[static_cast<std::size_t>(k)];
        continue;
      }
      const int w = -1 - vertex_[v];
      if (std::find(wall_of.begin(), wall_of.begin() + walls, w) != wall_of.begin() + walls) continue;
      wall_of[static_cast<std::size_t>(walls++)] = w;
      bodies[static_cast<std::size_t>(nb)] = Body<D>::of_wall(walls_[static_cast<std::size_t>(w)]);
      exact[static_cast<std::size_t>(nb++)] = planes_[static_cast<std::size_t>(w)];
    }
    // The void's room: the sphere touching its D + 1 bodies (Eqs. 1-9), or, with fewer distinct
    // bodies (two mirrors of one wall), the one touching the mirrors as spheres: an estimate.
    const bool determined = nb == D + 1;
    const TangentSpheres<D> fits = spheres_tangent_to<D>(determined ? exact : estimate, o_.radii == VoidRadii::Fit);
    int best = -1;
    for (int k = 0; k < fits.count; ++k)
      if (best < 0 || (fits.at[static_cast<std::size_t>(k)].centre - centroid).squaredNorm() <
                          (fits.at[static_cast<std::size_t>(best)].centre - centroid).squaredNorm())
        best = k;
    if (best < 0) return Outcome::Closed;
    const TangentSphere<D> room = fits.at[static_cast<std::size_t>(best)];
    if (room.radius < r_min_ * (1 - kRoomSlack)) return Outcome::Closed;
    if (region_ && !region_->contains(room.centre)) return Outcome::Closed;
    // Distribution: the room's centre may be blocked by a sphere of another void; the ball free
    // around it must take r_min too (most voids of a dense packing fail here, before up to
    // 3 x 2(D + 1) positions are tried: Fuller R = 7, 4.9 s -> 0.7 s, VF 0.668 -> 0.667). The
    // fit mode tries the room's centre first anyway, and its other positions find more.
    if (o_.radii == VoidRadii::Distribution && place_.free_radius(room.centre, room.radius) < r_min_ * (1 - kRoomSlack))
      return Outcome::Closed;
    ++rep_.voids_open;

    if (o_.radii == VoidRadii::Fit) {
      bool filled = false;
      if (determined && room.radius <= r_max_) {
        double r = room.radius;
        filled = try_place(room.centre, r, true);
        // A curved wall stood as its tangent plane: that radius touching D of the bodies, the
        // wall itself among them.
        if (!filled && walls > 0) filled = place_touching(bodies, nb, room.radius, room.centre, true);
      } else {
        if (room.radius > r_max_) ++rep_.radii_capped;
        filled = place_touching(bodies, nb, std::min(room.radius, r_max_), room.centre, true);
      }
      // Beyond the paper: a void whose own sphere does not go in takes one of r_min touching D of
      // its bodies (R = 7 in a meshed cube: phi in the probe 0.689 -> 0.737, 2.7 times the spheres,
      // most of r_min; experiments/jerier2010).
      if (!filled && o_.fallback_r_min) filled = place_touching(bodies, nb, r_min_, room.centre, false);
      return filled ? Outcome::Filled : Outcome::Open;
    }
    // Distribution: the largest pooled radii that the room can take.
    int tried = 0;
    double last = -1;
    for (std::size_t p = 0; p < pool_.size() && tried < kRadiiPerVoid; ++p) {
      const double r = pool_[p];
      if (r > room.radius * (1 + kRoomSlack) || r == last) continue;
      last = r;
      ++tried;
      if (place_touching(bodies, nb, r, room.centre, false)) {
        pool_.erase(pool_.begin() + static_cast<std::ptrdiff_t>(p));
        draw();
        return Outcome::Filled;
      }
    }
    return Outcome::Open;
  }

  /// Places a sphere of radius r touching D of the `nb` bodies, at the valid position nearest
  /// `target`; in fit mode its radius may be reduced to cancel an overlap.
  bool place_touching(const std::array<Body<D>, D + 1>& bodies, int nb, double r, const Vec<D>& target, bool may_reduce) {
    if (nb < D) return false;
    std::array<Placement<D>, 2 * (D + 1)> found;
    int n = 0;
    Mobile<D> mobile;
    mobile.radius = r;
    std::array<Body<D>, D> subset;
    for (int skip = nb == D ? -1 : 0; skip < nb && skip < D + 1; ++skip) {
      int q = 0;
      for (int k = 0; k < nb; ++k)
        if (k != skip) subset[static_cast<std::size_t>(q++)] = bodies[static_cast<std::size_t>(k)];
      std::array<Placement<D>, 2> out;
      const int m = solver_.solve(std::span<const Body<D>>(subset.data(), D), mobile, out);
      for (int k = 0; k < m; ++k) found[static_cast<std::size_t>(n++)] = out[static_cast<std::size_t>(k)];
      if (nb == D) break;
    }
    std::stable_sort(found.begin(), found.begin() + n, [&](const Placement<D>& a, const Placement<D>& b) {
      return (a.position - target).squaredNorm() < (b.position - target).squaredNorm();
    });
    for (int k = 0; k < n; ++k) {
      double rr = r;
      if (try_place(found[static_cast<std::size_t>(k)].position, rr, may_reduce)) return true;
    }
    return false;
  }

  bool try_place(const Vec<D>& x, double& r, bool may_reduce) {
    if (region_ && !region_->contains(x)) return false;  // a sphere of the region is centred in it
    if (!place_.try_place(x, r, may_reduce)) return false;
    solid_ += ball_measure<D>(r);
    return true;
  }

  Packing<D>& P_;
  const Container<D>& C_;
  const RadiusDistribution& dist_;
  const DensifyOptions& o_;
  Rng rng_;
  const VoidRegion<D>* region_;
  double r_min_, r_max_, allowance_;
  int z_min_;
  double measure_;
  NeighbourGrid<D> grid_;
  SpherePlacement<D> place_;
  SphereContactSolver<D> solver_;
  double solid_ = 0.0;
  std::vector<double> pool_;  ///< distribution: radii drawn ahead, largest first
  // The triangulation and its points: the centres and their mirrors, in the order inserted.
  GrowingDelaunay<D> dt_;
  std::vector<Vec<D>> points_;
  std::vector<double> point_radii_;       ///< a mirror: its sphere's radius
  std::vector<int> vertex_;               ///< per point: its sphere, or -1 - its wall (a mirror)
  std::size_t first_new_ = 0;             ///< spheres before it are in the triangulation
  std::size_t triangulated_ = 0;          ///< points before it are in the triangulation
  std::vector<Wall<D>> walls_;            ///< per mirror: the wall it stands for
  std::vector<TangentBody<D>> planes_;    ///< and the wall as a plane (curved: tangent at the mirrored centre's foot)
  std::vector<Simplex> waiting_;          ///< distribution: open voids to try again next round
  VoidFillingReport rep_;
};

}  // namespace

template <int D>
VoidFillingReport fill_voids(Packing<D>& packing, const Container<D>& container, const RadiusDistribution& dist,
                             const DensifyOptions& options, std::uint64_t seed, double contact_tolerance,
                             const VoidRegion<D>* region) {
  return VoidFiller<D>(packing, container, dist, options, seed, contact_tolerance, region).run();
}

template VoidFillingReport fill_voids<2>(Packing<2>&, const Container<2>&, const RadiusDistribution&, const DensifyOptions&,
                                         std::uint64_t, double, const VoidRegion<2>*);
template VoidFillingReport fill_voids<3>(Packing<3>&, const Container<3>&, const RadiusDistribution&, const DensifyOptions&,
                                         std::uint64_t, double, const VoidRegion<3>*);

}  // namespace fp
