#include "fill/graded_stacking.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>

#include "contact/body.hpp"
#include "contact/sphere_contact_solver.hpp"
#include "contact/sphere_two_contact.hpp"
#include "core/geometry/neighbour_grid.hpp"
#include "core/sampling/random_unit.hpp"

namespace fp {
namespace {

template <int D>
class Stacker {
 public:
  Stacker(const Container<D>& container, double r_min, double r_max, const StackingOptions& o, std::uint64_t seed,
          double tol, Packing<D>& out)
      : C_(container), o_(o), rng_(seed), tol_(tol), P_(out),
        grid_(container.bounds(), r_min, r_max, 2.0, 4.0) {
    container.prepare_queries(r_max);
    for (std::size_t i = 0; i < P_.size(); ++i) add_to_state(static_cast<int>(i), false);
  }

  /// Places one sphere of radius r; which step placed it, or 0 if none did. The paper's order
  /// (5), (6), (7), (8); with `contacts` (8), (7), (6), (5).
  int place(double r, bool contacts) {
    if (r < reopen_below_) reopen(r);
    if (P_.size() == 0) {  // the first particle: at random, else where the container is deepest
      Vec<D> x;
      if (random_position(r, x) || fits(x = C_.interior_point(), r)) return add(x, r, 5, true);
      return 0;
    }
    Vec<D> x;
    if (contacts) {
      if (three_contact_any(r, x)) return add(x, r, D == 3 ? 8 : 7, false);
      for (int t = 0; t < o_.two_contact_tries; ++t)
        if (two_contact_random(nucleus_any(), r, x)) return add(x, r, 7, D == 3);
      if (near_position(r, x)) return add(x, r, 6, true);
      if (random_position(r, x)) return add(x, r, 5, true);
      return 0;
    }
    if (random_position(r, x)) return add(x, r, 5, true);
    if (near_position(r, x)) return add(x, r, 6, true);
    for (int t = 0; t < o_.two_contact_tries; ++t)  // (7) Eqs. 3-4
      if (two_contact_random(nucleus_any(), r, x)) return add(x, r, 7, D == 3);  // 2D: two contacts fix it
    if (three_contact_any(r, x)) return add(x, r, D == 3 ? 8 : 7, false);
    return 0;
  }

  /// (11): every loose particle moved to the position touching three of its neighbours (two in
  /// 2D) nearest to where it is. Returns the number moved. `r`: the radius that found no place
  /// (the largest still to come).
  std::uint64_t reshape(double r) {
    std::vector<std::pair<Vec<D>, double>> vacated;
    for (std::size_t i = 0; i < P_.size(); ++i) {
      if (!loose_[i]) continue;
      const int id = static_cast<int>(i);
      Vec<D> x;
      grid_.erase(id);
      if (resettle(id, x)) {
        vacated.push_back({P_.centers[i], P_.radii[i]});
        P_.centers[i] = x;
        loose_[i] = 0;
      }
      grid_.insert(id, P_.centers[i], P_.radii[i]);
    }
    reopen_around(vacated, r);
    return vacated.size();
  }

 private:
  /// Inside the container and overlapping no placed sphere (to the contact tolerance).
  bool fits(const Vec<D>& x, double r) const {
    if (!C_.contains_ball(x, r, tol_)) return false;
    bool clear = true;
    grid_.for_each_within(x, r, [&](int, const Vec<D>&, double rk, double d2) {
      const double lim = r + rk - tol_ * std::min(r, rk);
      if (d2 < lim * lim) clear = false;
    });
    return clear;
  }

  /// `loose`: fewer contacts than the dimension (a reshape candidate).
  int add(const Vec<D>& x, double r, int step, bool loose) {
    add_to_state(P_.add(x, r), loose);
    return step;
  }
  void add_to_state(int id, bool loose) {
    grid_.insert(id, P_.centers[id], P_.radii[id]);
    loose_.push_back(loose ? 1 : 0);
    in_open_.push_back(1);
    open_.push_back(id);
  }

  int nucleus_any() { return static_cast<int>(rng_.below(P_.size())); }

  /// The mobile sphere of radius r for the contact solver.
  static Mobile<D> ball(double r) {
    Mobile<D> m;
    m.radius = r;
    return m;
  }

  /// (5): completely random positions in the container's bounds.
  bool random_position(double r, Vec<D>& x) {
    const Aabb<D> b = C_.bounds();
    for (int t = 0; t < o_.random_tries; ++t) {
      for (int k = 0; k < D; ++k) x[k] = rng_.uniform(b.lo[k], b.hi[k]);
      if (fits(x, r)) return true;
    }
    return false;
  }
  /// (6) Eq. 2: at r_b + r (1 + U) from a random nucleus's centre, in a random direction.
  bool near_position(double r, Vec<D>& x) {
    for (int t = 0; t < o_.near_tries; ++t) {
      const int b = nucleus_any();
      x = P_.centers[b] + (P_.radii[b] + r * (1 + rng_.uniform01())) * random_unit<D>(rng_);
      if (fits(x, r)) return true;
    }
    return false;
  }
  /// (8) Eq. 5 around up to `nuclei` open nuclei; a nucleus with no room for r is closed.
  bool three_contact_any(double r, Vec<D>& x) {
    for (int t = 0; t < o_.nuclei && !open_.empty(); ++t) {
      const std::size_t k = rng_.below(open_.size());
      const int b = open_[k];
      if (three_contact(b, r, x)) return true;
      closed_.push_back({r, b});  // no room for r around b: closed until the radii are 10 % smaller
      open_[k] = open_.back();
      open_.pop_back();
      in_open_[b] = 0;
    }
    return false;
  }

  /// The bodies around nucleus b for a sphere of radius r: its neighbours within reach (nearest
  /// surface first) and the container's walls within reach.
  void gather(int b, double r) {
    const Vec<D>& c = P_.centers[b];
    // A margin over the solver's rounding: acceptable() takes this list as every ball a
    // position touching b can overlap.
    const double rb = P_.radii[b], reach = rb + 2 * r * (1 + 1e-6);
    near_.clear();
    grid_.for_each_within(c, reach, [&](int id, const Vec<D>&, double rk, double d2) {
      if (id != b) near_.push_back({std::sqrt(d2) - rk, id});
    });
    std::sort(near_.begin(), near_.end());
    walls_.clear();
    C_.walls_near(c, reach, walls_);
    bodies_.clear();
    for (const Wall<D>& w : walls_) bodies_.push_back(Body<D>::of_wall(w));
    for (const auto& [gap, id] : near_) bodies_.push_back(Body<D>::sphere(P_.centers[id], P_.radii[id], id));
  }

  /// (7): a random point of the curve of positions touching b and a random neighbour (3D); in
  /// 2D the two points touching both.
  bool two_contact_random(int b, double r, Vec<D>& x) {
    gather(b, r);
    if (near_.empty()) return false;
    const int j = near_[rng_.below(near_.size())].second;
    const Body<D> bj = Body<D>::sphere(P_.centers[j], P_.radii[j], j);
    if constexpr (D == 3) {
      curve_.clear();
      two_contact_positions(P_.centers[b], P_.radii[b], bj, r, 16, curve_);
      if (curve_.empty()) return false;
      x = curve_[rng_.below(curve_.size())];
      return fits(x, r);
    } else {
      const std::array<Body<2>, 2> two{Body<2>::sphere(P_.centers[b], P_.radii[b], b), bj};
      std::array<Placement<2>, ContactSolver<2>::kMaxSolutions> out;
      const int m = solver_.solve(std::span<const Body<2>>(two.data(), 2), ball(r), out);
      if (m == 0) return false;
      x = out[rng_.below(static_cast<std::uint64_t>(m))].position;
      return fits(x, r);
    }
  }

  /// A position the solver gave for `fixed` that can be taken: over the face of every wall among
  /// them (a facet is solved as its whole plane), inside, overlapping nothing.
  /// `gathered`: y touches the nucleus of the last gather(b, r), whose list then holds every
  /// ball y can overlap (within r_b + 2 r of b's centre); they are checked nearest first and the
  /// first overlap ends the check (most positions tried around a full nucleus overlap its
  /// nearest neighbours), rather than by a query of the grid.
  bool acceptable(const std::array<Body<D>, D>& fixed, const Vec<D>& y, double r, bool gathered) const {
    for (const Body<D>& b : fixed)
      if (b.is_wall() && !b.wall->over_face(y, 2 * std::sqrt(2 * tol_) * r)) return false;
    if (!gathered) return fits(y, r);
    for (const auto& [gap, id] : near_) {
      const double rk = P_.radii[id], lim = r + rk - tol_ * std::min(r, rk);
      if ((P_.centers[id] - y).squaredNorm() < lim * lim) return false;
    }
    return C_.contains_ball(y, r, tol_);
  }

  /// (8): the first position touching b and D - 1 bodies around it (pairs nearest first) that
  /// can be taken.
  bool three_contact(int b, double r, Vec<D>& x) {
    gather(b, r);
    const int n = static_cast<int>(bodies_.size());
    std::array<Body<D>, D> fixed;
    fixed[0] = Body<D>::sphere(P_.centers[b], P_.radii[b], b);
    std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> out;
    int tried = 0;
    auto consider = [&](int m) {
      for (int q = 0; q < m; ++q)
        if (acceptable(fixed, out[q].position, r, true)) {
          x = out[q].position;
          return true;
        }
      return false;
    };
    if constexpr (D == 2) {
      for (int i = 0; i < n && tried < o_.pairs_per_nucleus; ++i, ++tried) {
        fixed[1] = bodies_[i];
        if (consider(solver_.solve(std::span<const Body<2>>(fixed.data(), 2), ball(r), out))) return true;
      }
    } else {
      for (int j = 1; j < n && tried < o_.pairs_per_nucleus; ++j)
        for (int i = 0; i < j && tried < o_.pairs_per_nucleus; ++i) {
          // Two particles farther apart than a diameter of the new one cannot both touch it.
          if (!bodies_[i].is_wall() && !bodies_[j].is_wall()) {
            const double reach = bodies_[i].radius + bodies_[j].radius + 2 * r;
            if ((bodies_[i].center - bodies_[j].center).squaredNorm() > reach * reach) continue;
          }
          ++tried;
          fixed[1] = bodies_[i];
          fixed[2] = bodies_[j];
          if (consider(solver_.solve(std::span<const Body<3>>(fixed.data(), 3), ball(r), out))) return true;
        }
    }
    return false;
  }

  /// (11) for particle i (out of the grid): the position touching D of its neighbours (walls
  /// count) nearest to where it is, overlapping nothing, among the neighbours within a diameter
  /// of its surface; false if none.
  bool resettle(int i, Vec<D>& x) {
    const Vec<D> c = P_.centers[i];
    const double r = P_.radii[i];
    near_.clear();
    grid_.for_each_within(c, 2 * r, [&](int id, const Vec<D>&, double rk, double d2) { near_.push_back({std::sqrt(d2) - rk, id}); });
    std::sort(near_.begin(), near_.end());
    walls_.clear();
    C_.walls_near(c, 2 * r, walls_);
    bodies_.clear();
    for (const Wall<D>& w : walls_) bodies_.push_back(Body<D>::of_wall(w));
    for (const auto& [gap, id] : near_) bodies_.push_back(Body<D>::sphere(P_.centers[id], P_.radii[id], id));
    const int n = std::min<int>(static_cast<int>(bodies_.size()), 12);  // the nearest: a small move
    std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> out;
    std::array<Body<D>, D> fixed;
    bool found = false;
    double best = std::numeric_limits<double>::infinity();
    auto consider = [&](int m) {
      for (int q = 0; q < m; ++q) {
        const Vec<D>& y = out[q].position;
        const double key = (y - c).squaredNorm();
        if (key < best && acceptable(fixed, y, r, false)) x = y, best = key, found = true;
      }
    };
    if constexpr (D == 2) {
      for (int j = 1; j < n; ++j)
        for (int a = 0; a < j; ++a) {
          fixed = {bodies_[a], bodies_[j]};
          consider(solver_.solve(std::span<const Body<2>>(fixed.data(), 2), ball(r), out));
        }
    } else {
      for (int k = 2; k < n; ++k)
        for (int j = 1; j < k; ++j)
          for (int a = 0; a < j; ++a) {
            fixed = {bodies_[a], bodies_[j], bodies_[k]};
            consider(solver_.solve(std::span<const Body<3>>(fixed.data(), 3), ball(r), out));
          }
    }
    return found;
  }

  /// The closed balls that a ball of radius up to r touching them could now reach a vacated place
  /// from (its centre within r_b + 2 r + r_i of the place) come back as nuclei: reopening every
  /// ball after a reshape that moved a few made each fail again, 8 passes x N failures (3D R = 2,
  /// 28,734 spheres: 62,384 failed nuclei).
  void reopen_around(const std::vector<std::pair<Vec<D>, double>>& vacated, double r) {
    if (vacated.empty()) return;
    std::vector<char> near(P_.size(), 0);
    for (const auto& [c, ri] : vacated)
      grid_.for_each_within(c, ri + 2 * r, [&](int id, const Vec<D>&, double, double) { near[id] = 1; });
    std::vector<std::pair<double, int>> still;
    for (const auto& [failed, id] : closed_)
      if (near[id]) {
        if (!in_open_[id]) open_.push_back(id), in_open_[id] = 1;
      } else {
        still.push_back({failed, id});
      }
    closed_ = std::move(still);
  }

  /// Balls closed for radii at least kReopen of the present one come back as nuclei.
  static constexpr double kReopen = 0.9;
  void reopen(double r) {
    std::vector<std::pair<double, int>> still;
    for (const auto& [failed, id] : closed_)
      if (r <= failed * kReopen) {
        if (!in_open_[id]) open_.push_back(id), in_open_[id] = 1;
      } else {
        still.push_back({failed, id});
      }
    closed_ = std::move(still);
    reopen_below_ = r * kReopen;
  }

  const Container<D>& C_;
  StackingOptions o_;
  Rng rng_;
  double tol_;
  Packing<D>& P_;
  NeighbourGrid<D> grid_;
  SphereContactSolver<D> solver_;
  std::vector<char> loose_, in_open_;
  std::vector<int> open_;
  std::vector<std::pair<double, int>> closed_;  // (the radius that failed, ball)
  double reopen_below_ = std::numeric_limits<double>::infinity();
  std::vector<std::pair<double, int>> near_;
  std::vector<Wall<D>> walls_;
  std::vector<Body<D>> bodies_;
  std::vector<Vec3> curve_;
};

}  // namespace

template <int D>
StackingReport stack_graded(const Container<D>& container, std::vector<double> radii, const StackingOptions& options,
                            std::uint64_t seed, double tol, Packing<D>& out) {
  const auto t0 = std::chrono::steady_clock::now();
  StackingReport rep;
  rep.asked = radii.size();
  if (radii.empty()) return rep;
  std::sort(radii.begin(), radii.end(), std::greater<>());
  for (const double r : radii) {
    if (!(r > 0.0) || !std::isfinite(r)) throw std::invalid_argument("stack_graded: radii must be positive and finite");
    rep.solid_asked += ball_measure<D>(r);
  }
  double r_min = radii.back(), r_max = radii.front();
  for (const double r : out.radii) r_min = std::min(r_min, r), r_max = std::max(r_max, r);
  Stacker<D> s(container, r_min, r_max, options, seed, tol, out);
  double solid_seen = 0.0;
  for (const double r : radii) {
    const bool contacts = options.contacts_first && solid_seen >= options.random_share * rep.solid_asked;
    solid_seen += ball_measure<D>(r);
    int step = s.place(r, contacts);
    if (step == 0 && rep.reshape_passes < static_cast<std::uint64_t>(options.reshapes)) {
      ++rep.reshape_passes;
      rep.reshape_moves += s.reshape(r);
      step = s.place(r, contacts);
    }
    switch (step) {
      case 5: ++rep.by_random; break;
      case 6: ++rep.by_near; break;
      case 7: ++rep.by_two_contact; break;
      case 8: ++rep.by_three_contact; break;
      default:
        ++rep.unplaced;
        rep.left_out.push_back(r);
        continue;
    }
    ++rep.placed;
    rep.solid_placed += ball_measure<D>(r);
  }
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return rep;
}

template <int D>
std::vector<double> radii_for_measure(const RadiusDistribution& law, double measure, Rng& rng) {
  std::vector<double> radii;
  double sum = 0.0;
  while (sum < measure) {
    const double r = law.sample(rng);
    const double m = ball_measure<D>(r);
    if (sum + m - measure > measure - sum) break;  // the last one only if it brings the sum closer
    radii.push_back(r);
    sum += m;
  }
  std::sort(radii.begin(), radii.end(), std::greater<>());
  return radii;
}

template StackingReport stack_graded<2>(const Container<2>&, std::vector<double>, const StackingOptions&, std::uint64_t,
                                        double, Packing<2>&);
template StackingReport stack_graded<3>(const Container<3>&, std::vector<double>, const StackingOptions&, std::uint64_t,
                                        double, Packing<3>&);
template std::vector<double> radii_for_measure<2>(const RadiusDistribution&, double, Rng&);
template std::vector<double> radii_for_measure<3>(const RadiusDistribution&, double, Rng&);

}  // namespace fp
