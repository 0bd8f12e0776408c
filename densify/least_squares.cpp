#include "densify/least_squares.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>  // and glibc's sincos
#include <limits>
#include <utility>
#include <vector>

#include "core/geometry/delaunay_cgal.hpp"
#include "core/geometry/hilbert_curve.hpp"
#include "core/geometry/neighbour_grid.hpp"
#include "core/geometry/wall.hpp"
#include "densify/lbfgs.hpp"

namespace fp {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// Centres relative to the packing's mean, in units of its mean radius: the minimiser's numbers
/// are then of order one whatever the scene's scale and place.
template <int D>
struct UnitFrame {
  Vec<D> centre = Vec<D>::Zero();
  double scale = 1.0;
  Vec<D> in(const Vec<D>& x) const { return (x - centre) / scale; }
  Vec<D> out(const Vec<D>& u) const { return centre + scale * u; }
  Wall<D> in(Wall<D> w) const {
    w.point = in(w.point);
    w.radius /= scale;
    w.face = nullptr;  // the objective needs the wall's surface only
    w.face_edges = 0;
    return w;
  }
};

/// The gradient of w.gap(c, 0) (the signed distance to the wall, positive on the container's
/// side) with respect to c; zero where it has none (a centre on a sphere wall's centre).
template <int D>
Vec<D> gap_gradient(const Wall<D>& w, const Vec<D>& c) {
  Vec<D> v = Vec<D>::Zero();
  switch (w.kind) {
    case WallKind::Plane: return w.normal;
    case WallKind::Sphere: v = w.point - c; break;
    case WallKind::Cylinder: {
      const Vec<D> d = c - w.point;
      v = -(d - d.dot(w.axis) * w.axis);
      break;
    }
    case WallKind::Vertex: v = c - w.point; break;
  }
  const double n = v.norm();
  return n > 0 ? Vec<D>(v / n) : Vec<D>::Zero();
}

struct Edge {
  std::uint32_t i, j;
  double weight;
};

template <int D>
struct BoundaryTerm {
  std::uint32_t i;
  Wall<D> wall;  ///< in the unit frame
  double weight;
};

/// The walls a ball (c, r) in the local frame is near: within `reach` of its surface; a bounded
/// plane only where the centre's foot lies over its face (within `slack`), a reflex vertex only
/// when `vertices`.
template <int D>
void walls_of(const Container<D>& container, const Vec<D>& c, double r, double reach, double slack, bool vertices,
              std::vector<Wall<D>>& scratch, std::vector<Wall<D>>& out) {
  scratch.clear();
  container.walls_near(c, r + reach, scratch);
  for (const Wall<D>& w : scratch) {
    if (w.kind == WallKind::Vertex && !vertices) continue;
    if (w.kind == WallKind::Plane && w.face && !w.over_face(c, slack)) continue;
    if (w.gap(c, r) <= reach) out.push_back(w);
  }
}

/// The gradient of pair terms read in order of their first particle i (the edges and pairs are
/// sorted by (i, j)): g_i += k delta and (Range) its radius's += kr summed in registers and
/// written once per i, g_j -= k delta and its radius's += kr scattered.
template <int D>
struct RowGradient {
  double* g;
  std::size_t n;
  bool range;
  std::uint32_t row = std::numeric_limits<std::uint32_t>::max();
  Vec<D> gi = Vec<D>::Zero();
  double gri = 0;

  void add(std::uint32_t i, std::uint32_t j, double k, const Vec<D>& delta, double kr) {
    if (i != row) {
      flush();
      row = i;
    }
    gi += k * delta;
    gri += kr;
    Eigen::Map<Vec<D>>(g + D * j) -= k * delta;
    if (range) g[D * n + j] += kr;
  }
  void flush() {
    if (row == std::numeric_limits<std::uint32_t>::max()) return;
    Eigen::Map<Vec<D>>(g + D * row) += gi;
    if (range) g[D * n + row] += gri;
    gi.setZero();
    gri = 0;
  }
};

/// Eq. 4 (normalised, see the header) and its gradient over the unit frame's centres u (and
/// radii rho with Range): the variables are u (D per particle) followed by rho.
template <int D>
struct LeastSquaresObjective {
  const std::vector<Edge>* edges;
  const std::vector<BoundaryTerm<D>>* boundary;
  const std::vector<double>* fixed_rho;  ///< Fixed: the radii; Range: null (rho are variables)
  std::size_t n;
  int evaluations = 0;

  const double* radii(const double* v) const { return fixed_rho ? fixed_rho->data() : v + D * n; }
  std::size_t variables() const { return D * n + (fixed_rho ? 0 : n); }

  double operator()(const double* v, double* g) {
    ++evaluations;
    if (g) std::fill(g, g + variables(), 0.0);
    const double* rho = radii(v);
    double f = 0;
    RowGradient<D> rows{g, n, !fixed_rho};
    for (const Edge& e : *edges) {
      const Vec<D> delta = Eigen::Map<const Vec<D>>(v + D * e.i) - Eigen::Map<const Vec<D>>(v + D * e.j);
      const double s = rho[e.i] + rho[e.j];
      const double d = delta.squaredNorm() - s * s;  // Eq. 1
      f += e.weight * d * d;
      if (g) rows.add(e.i, e.j, 4 * e.weight * d, delta, -4 * e.weight * d * s);
    }
    if (g) rows.flush();
    return f + boundary_part(v, g);
  }

  /// Eq. 4's wall terms (Eq. 3, signed), added to g.
  double boundary_part(const double* v, double* g) const {
    const double* rho = radii(v);
    double f = 0;
    for (const BoundaryTerm<D>& b : *boundary) {
      const Eigen::Map<const Vec<D>> u(v + D * b.i);
      const double h = b.wall.gap(Vec<D>(u), 0.0);
      const double R = h * std::abs(h) - rho[b.i] * rho[b.i];  // Eq. 3, signed
      f += b.weight * R * R;
      if (!g) continue;
      const double k = 2 * b.weight * R;
      Eigen::Map<Vec<D>>(g + D * b.i) += k * 2 * std::abs(h) * gap_gradient(b.wall, Vec<D>(u));
      if (!fixed_rho) g[D * n + b.i] -= k * 2 * rho[b.i];
    }
    return f;
  }
};

/// A pair in the penalised objective: an edge of Eq. 4, a pair near enough to overlap, or both.
struct PairTerm {
  std::uint32_t i, j;
  double eq4;      ///< Eq. 4's weight (0: not an edge)
  double penalty;  ///< 1 / min(rho)^2 (0: too far apart to overlap in this round)
};

/// Eq. 4 plus mu times the overlaps squared (pairs relative to the smaller radius of the round's
/// start, walls to the radius), one-sided: step 1's objective, over Eq. 4's variables. Its
/// minimum keeps the pairs Eq. 4 draws together in contact (overlapping by about 1 / mu). Each
/// pair is read once for both terms, its square root taken only when it overlaps.
template <int D>
struct PenaltyObjective {
  LeastSquaresObjective<D>* eq4;
  double mu = 1.0;
  std::vector<PairTerm> pairs;         ///< the edges of Eq. 4 and the near pairs, by (i, j)
  std::vector<BoundaryTerm<D>> walls;  ///< weight 1 / rho^2

  /// The round's terms: Eq. 4's edges (sorted) merged with `near` (pairs i < j, any order).
  void set_pairs(std::vector<Edge>& near) {
    std::sort(near.begin(), near.end(), [](const Edge& a, const Edge& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
    pairs.clear();
    const std::vector<Edge>& edges = *eq4->edges;
    std::size_t a = 0, b = 0;
    while (a < edges.size() || b < near.size()) {
      const bool take_a = b == near.size() ||
                          (a < edges.size() && (edges[a].i != near[b].i ? edges[a].i < near[b].i : edges[a].j <= near[b].j));
      const bool take_b = a == edges.size() ||
                          (b < near.size() && (near[b].i != edges[a].i ? near[b].i < edges[a].i : near[b].j <= edges[a].j));
      const Edge& e = take_a ? edges[a] : near[b];
      pairs.push_back({e.i, e.j, take_a ? edges[a].weight : 0.0, take_b ? near[b].weight : 0.0});
      a += take_a;
      b += take_b;
    }
  }

  double operator()(const double* v, double* g) {
    ++eq4->evaluations;
    if (g) std::fill(g, g + eq4->variables(), 0.0);
    const double* rho = eq4->radii(v);
    const bool range = !eq4->fixed_rho;
    double f = 0;
    RowGradient<D> rows{g, eq4->n, range};
    for (const PairTerm& t : pairs) {
      const Vec<D> delta = Eigen::Map<const Vec<D>>(v + D * t.i) - Eigen::Map<const Vec<D>>(v + D * t.j);
      const double d2 = delta.squaredNorm();
      const double s = rho[t.i] + rho[t.j];
      double k = 0, kr = 0;  // the gradient: k delta on i, -k delta on j, kr on both radii
      if (t.eq4 > 0) {
        const double d = d2 - s * s;  // Eq. 1
        f += t.eq4 * d * d;
        k = 4 * t.eq4 * d;
        kr = -k * s;
      }
      if (t.penalty > 0 && d2 < s * s) {
        const double dist = std::sqrt(d2);
        const double o = s - dist;
        f += mu * t.penalty * o * o;
        const double kp = 2 * mu * t.penalty * o;
        if (dist > 0) k -= kp / dist;
        kr += kp;
      }
      if (g && (k != 0 || kr != 0)) rows.add(t.i, t.j, k, delta, kr);
    }
    if (g) rows.flush();
    f += eq4->boundary_part(v, g);
    for (const BoundaryTerm<D>& b : walls) {
      const Eigen::Map<const Vec<D>> u(v + D * b.i);
      const double o = -b.wall.gap(Vec<D>(u), rho[b.i]);
      if (o <= 0) continue;
      f += mu * b.weight * o * o;
      if (!g) continue;
      const double k = 2 * mu * b.weight * o;
      Eigen::Map<Vec<D>>(g + D * b.i) -= k * gap_gradient(b.wall, Vec<D>(u));
      if (range) g[D * eq4->n + b.i] += k;
    }
    return f;
  }
};

/// Calls f(i, j, overlap) for every pair closer than r_i + r_j + margin * min(r_i, r_j), i < j.
template <int D, class F>
void near_pairs(const std::vector<Vec<D>>& c, const std::vector<double>& r, double margin, F&& f) {
  if (c.empty()) return;
  Aabb<D> box;
  for (const Vec<D>& x : c) box.extend(x);
  const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
  NeighbourGrid<D> grid(box, *lo, *hi);
  for (std::size_t i = 0; i < c.size(); ++i) grid.insert(static_cast<int>(i), c[i], r[i]);
  for (std::size_t i = 0; i < c.size(); ++i)
    grid.for_each_within(c[i], r[i] * (1 + margin), [&](int k, const Vec<D>&, double rk, double d2) {
      if (static_cast<std::size_t>(k) <= i) return;
      const double reach = r[i] + rk + margin * std::min(r[i], rk);
      if (d2 <= reach * reach) f(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k), r[i] + rk - std::sqrt(d2));
    });
}

/// Whether no pair overlaps beyond tol * the smaller radius and every ball is inside.
template <int D>
bool valid(const std::vector<Vec<D>>& c, const std::vector<double>& r, const Container<D>& container, double tol) {
  bool ok = true;
  near_pairs<D>(c, r, 0.0, [&](std::uint32_t i, std::uint32_t j, double o) {
    if (o > tol * std::min(r[i], r[j])) ok = false;
  });
  for (std::size_t i = 0; ok && i < c.size(); ++i) ok = container.contains_ball(c[i], r[i], tol);
  return ok;
}

template <int D>
double solid_of(const std::vector<double>& r) {
  double s = 0;
  for (const double x : r) s += ball_measure<D>(x);
  return s;
}

/// Step 1's penalty weight in its first round, and its growth from round to round.
constexpr double kPenaltyStart = 10.0;
constexpr double kPenaltyGrowth = 10.0;
/// Step 3's sweeps at most.
constexpr int kSweeps = 64;
/// Step 5's bisections of the move (the share kept is then known to 2^-kBisections).
constexpr int kBisections = 6;

/// Eq. 4's variables: the centres (D each), then the radii (Range only).
template <int D>
void pack_variables(const std::vector<Vec<D>>& u, const std::vector<double>& rho, bool range, std::vector<double>& x) {
  const std::size_t n = u.size();
  x.resize(D * n + (range ? n : 0));
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < D; ++a) x[D * i + a] = u[i][a];
    if (range) x[D * n + i] = rho[i];
  }
}
template <int D>
void unpack_variables(const std::vector<double>& x, bool range, std::vector<Vec<D>>& u, std::vector<double>& rho) {
  const std::size_t n = u.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < D; ++a) u[i][a] = x[D * i + a];
    if (range) rho[i] = x[D * n + i];
  }
}

/// L-BFGS (densify/lbfgs.hpp) within bounds (none: null; a bound pair must be finite): each
/// bounded variable is mid + half sin(z) over a free z. NLopt's bounded L-BFGS, tried first,
/// stalled on many bounded radii (50,000 spheres: Eq. 4 from 5101 to 4005 in 1500 evaluations;
/// with this change of variables it went to 87). Its vectors are kept from one run to the next
/// (Eq. 4, then the removal's rounds, with the same bounds).
class BoundedLbfgs {
 public:
  BoundedLbfgs(const std::vector<double>* lower, const std::vector<double>* upper) {
    if (!lower) return;
    for (std::size_t k = 0; k < lower->size(); ++k)
      if (std::isfinite((*lower)[k]) && std::isfinite((*upper)[k])) {
        index_.push_back(k);
        mid_.push_back(((*lower)[k] + (*upper)[k]) / 2);
        half_.push_back(((*upper)[k] - (*lower)[k]) / 2);
      }
    cosine_.resize(index_.size());
  }

  /// Minimises f (f(v, g): the value at v, its gradient into g) from x, in place; the value.
  template <class F>
  double run(std::vector<double>& x, int evaluations, double stop_below, F& f) {
    z_ = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
    for (std::size_t q = 0; q < index_.size(); ++q) {
      const std::size_t k = index_[q];
      z_[k] = half_[q] > 0 ? std::asin(std::clamp((x[k] - mid_[q]) / half_[q], -1.0, 1.0)) : 0.0;
    }
    LbfgsOptions o;
    o.evaluations = std::max(evaluations, 1);
    o.stop_below = stop_below;
    o.memory = 4;  // as good as 6 or 10 here, and each pair costs a pass over two vectors of every unknown
    const auto over_z = [&](const Eigen::VectorXd& z, Eigen::VectorXd& g) {
      const double value = f(to_v(z), g.data());
      for (std::size_t q = 0; q < index_.size(); ++q) g[index_[q]] *= half_[q] * cosine_[q];
      return value;
    };
    const double value = minimise_lbfgs(z_, over_z, o, workspace_).value;
    const double* v = to_v(z_);
    std::copy(v, v + x.size(), x.data());
    return value;
  }

 private:
  const double* to_v(const Eigen::VectorXd& z) {
    if (index_.empty()) return z.data();
    v_ = z;
    for (std::size_t q = 0; q < index_.size(); ++q) {
      double sine;
      ::sincos(z[index_[q]], &sine, &cosine_[q]);
      v_[index_[q]] = mid_[q] + half_[q] * sine;
    }
    return v_.data();
  }

  std::vector<std::size_t> index_;  ///< the bounded variables
  std::vector<double> mid_, half_, cosine_;
  Eigen::VectorXd z_, v_;
  LbfgsWorkspace workspace_;
};

/// Steps 1-4 of the header on a packing in the unit frame (u, rho): the result in the local
/// frame (c, r), and whether it is valid (no overlap beyond the tolerance, every ball inside).
template <int D>
struct OverlapRemoval {
  const Container<D>& container;
  const UnitFrame<D>& frame;
  const std::vector<double>& r0;  ///< the radii given
  double r_min, r_max;
  bool range;
  int relax_rounds, relax_evaluations;
  double contact_tolerance;
  LeastSquaresObjective<D>* eq4;
  BoundedLbfgs* minimiser;  ///< within Eq. 4's bounds

  /// Fills rep's figures of steps 1-4.
  bool run(std::vector<Vec<D>>& u, std::vector<double>& rho, std::vector<Vec<D>>& c, std::vector<double>& r,
           LeastSquaresReport& rep) const {
    const std::size_t n = u.size();
    std::vector<Wall<D>> scratch, near;
    c.resize(n);
    r.resize(n);
    const auto to_local = [&] {
      for (std::size_t i = 0; i < n; ++i) {
        c[i] = frame.out(u[i]);
        r[i] = range ? rho[i] * frame.scale : r0[i];  // Fixed: exactly the radii given
      }
    };
    to_local();
    // Step 1: Eq. 4 under a penalty on the overlaps, its weight raised round after round.
    std::vector<double> x(D * n + (range ? n : 0));
    PenaltyObjective<D> penalised{eq4, kPenaltyStart, {}, {}};
    std::vector<Edge> close;
    for (int round = 0;; ++round) {
      // The pairs near enough to overlap in the round (within 0.2 of the smaller radius), and
      // the largest overlap now from the same pass (relative: the frame's scale drops out).
      close.clear();
      double worst = 0;
      near_pairs<D>(u, rho, 0.2, [&](std::uint32_t i, std::uint32_t j, double o) {
        const double m = std::min(rho[i], rho[j]);
        close.push_back({i, j, 1 / (m * m)});
        worst = std::max(worst, o / m);
      });
      for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, (container.signed_distance(c[i]) + r[i]) / r[i]);
      rep.max_overlap_relaxed = worst;
      if (round == relax_rounds || worst <= contact_tolerance / 2) break;
      penalised.set_pairs(close);
      penalised.walls.clear();
      for (std::size_t i = 0; i < n; ++i) {
        near.clear();
        walls_of<D>(container, c[i], r[i], 0.5 * r[i], r[i], true, scratch, near);
        for (const Wall<D>& wall : near)
          penalised.walls.push_back({static_cast<std::uint32_t>(i), frame.in(wall), 1 / (rho[i] * rho[i])});
      }
      pack_variables<D>(u, rho, range, x);
      const int before = eq4->evaluations;
      minimiser->run(x, relax_evaluations, -HUGE_VAL, penalised);
      unpack_variables<D>(x, range, u, rho);
      to_local();
      rep.relax_rounds += 1;
      rep.relax_evaluations += eq4->evaluations - before;
      penalised.mu *= kPenaltyGrowth;
    }

    // Step 2: what overlap is left comes off the radii, each pair's from both in proportion to
    // what they can give above their floor.
    std::vector<double> floor(n), clipped = r;
    for (std::size_t i = 0; i < n; ++i) {
      floor[i] = range ? std::min(r_min, r0[i]) : std::min(r0[i], std::max(r0[i] * (1 - kClipAllowance), r_min));
      floor[i] = std::min(floor[i], r[i]);
    }
    near_pairs<D>(c, r, 0.0, [&](std::uint32_t i, std::uint32_t j, double o) {
      if (o <= contact_tolerance / 2 * std::min(r[i], r[j])) return;
      const double si = r[i] - floor[i], sj = r[j] - floor[j];
      if (!(si + sj > 0)) return;  // neither can give: steps 3 and 5
      clipped[i] = std::min(clipped[i], r[i] - o * si / (si + sj));
      clipped[j] = std::min(clipped[j], r[j] - o * sj / (si + sj));
    });
    for (std::size_t i = 0; i < n; ++i) {
      const double inside = -container.signed_distance(c[i]);
      if (r[i] - inside > contact_tolerance / 2 * r[i]) clipped[i] = std::min(clipped[i], inside);
      if (clipped[i] < r[i]) {
        ++rep.radii_clipped;
        rep.max_clip = std::max(rep.max_clip, (r[i] - std::max(clipped[i], floor[i])) / r[i]);
      }
      r[i] = std::max(clipped[i], floor[i]);
    }

    // Step 3: sweeps of projections, radii held: each overlapping pair moved apart to touch (the
    // smaller ball moving more, by volume), each ball past a wall moved back to it.
    {
      std::vector<std::array<std::uint32_t, 2>> pairs;
      near_pairs<D>(c, r, 0.5, [&](std::uint32_t i, std::uint32_t j, double) { pairs.push_back({i, j}); });
      std::vector<std::pair<std::uint32_t, Wall<D>>> walls;
      for (std::size_t i = 0; i < n; ++i) {
        near.clear();
        walls_of<D>(container, c[i], r[i], 0.5 * r[i], r[i], true, scratch, near);
        for (const Wall<D>& wall : near) walls.push_back({static_cast<std::uint32_t>(i), wall});
      }
      for (int sweep = 0; sweep < kSweeps; ++sweep) {
        double worst = 0;
        for (const auto& [i, j] : pairs) {
          const Vec<D> delta = c[i] - c[j];
          const double dist = delta.norm();
          const double o = r[i] + r[j] - dist;
          if (o <= 0 || !(dist > 0)) continue;
          worst = std::max(worst, o / std::min(r[i], r[j]));
          const double vi = std::pow(r[i], D), vj = std::pow(r[j], D);
          const Vec<D> unit = delta / dist;
          c[i] += (o * vj / (vi + vj)) * unit;
          c[j] -= (o * vi / (vi + vj)) * unit;
        }
        for (const auto& [i, wall] : walls) {
          const double o = -wall.gap(c[i], r[i]);
          if (o <= 0) continue;
          worst = std::max(worst, o / r[i]);
          c[i] += o * gap_gradient(wall, c[i]);
        }
        rep.sweeps += 1;
        if (worst <= contact_tolerance / 2) break;
      }
    }

    // Step 4 (Range): each ball, in turn, grows into the room left around it, up to r_max:
    // until it touches its nearest neighbour or a wall (the gaps Eq. 4 left: more solid, more
    // contacts).
    if (range) {
      Aabb<D> box;
      for (const Vec<D>& x : c) box.extend(x);
      const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
      const double largest = std::max(*hi, r_max);  // any radius, now or grown
      NeighbourGrid<D> grid(box, *lo, largest);
      for (std::size_t i = 0; i < n; ++i) grid.insert(static_cast<int>(i), c[i], r[i]);
      for (std::size_t i = 0; i < n; ++i) {
        if (!(r[i] < r_max)) continue;
        double room = std::min(r_max, -container.signed_distance(c[i]));
        grid.for_each_near(c[i], r_max + largest, [&](int k) {  // the grid holds the radii before growth: a superset
          if (static_cast<std::size_t>(k) != i) room = std::min(room, (c[k] - c[i]).norm() - r[k]);
        });
        if (room > r[i]) {
          r[i] = room;
          ++rep.swelled;
        }
      }
    }

    return valid<D>(c, r, container, contact_tolerance);
  }
};

template <int D>
LeastSquaresReport densify_in_order(Packing<D>& packing, const Container<D>& container, double r_min, double r_max,
                                    const LeastSquaresOptions& options, double contact_tolerance) {
  const auto t0 = Clock::now();
  LeastSquaresReport rep;
  const std::size_t n = packing.size();
  rep.particles = n;
  rep.solid_before = rep.solid_solved = rep.solid_after = solid_of<D>(packing.radii);
  if (n == 0) return rep;
  const bool range = options.radii == LeastSquaresRadii::Range;
  const std::vector<Vec<D>> c0 = packing.centers;
  const std::vector<double> r0 = packing.radii;

  UnitFrame<D> frame;
  for (const Vec<D>& x : c0) frame.centre += x / static_cast<double>(n);
  frame.scale = 0;
  for (const double r : r0) frame.scale += r / static_cast<double>(n);
  std::vector<Vec<D>> u(n);
  std::vector<double> rho(n);
  for (std::size_t i = 0; i < n; ++i) {
    u[i] = frame.in(c0[i]);
    rho[i] = r0[i] / frame.scale;
  }

  // The terms of Eq. 4: the triangulation's edges, the walls near the outer particles.
  const auto tt = Clock::now();
  std::vector<Edge> edges;
  for (const auto& [i, j] : delaunay_edges<D>(u)) {
    const double s = rho[i] + rho[j];
    if (options.edge_gap > 0 && (u[i] - u[j]).norm() - s > options.edge_gap * s) continue;
    edges.push_back({i, j, 1 / (s * s * s * s)});
  }
  rep.triangulation_seconds = since(tt);
  rep.edges = edges.size();
  std::vector<BoundaryTerm<D>> boundary;
  std::vector<Wall<D>> scratch, near;
  if (options.boundary) {
    for (std::size_t i = 0; i < n; ++i) {
      near.clear();
      walls_of<D>(container, c0[i], r0[i], r0[i], 0.0, false, scratch, near);
      const double w = 1 / std::pow(2 * rho[i], 4);
      for (const Wall<D>& wall : near) boundary.push_back({static_cast<std::uint32_t>(i), frame.in(wall), w});
    }
  }
  rep.boundary_terms = boundary.size();

  // The minimisation of Eq. 4: centres, then (Range) radii.
  const auto ts = Clock::now();
  std::vector<double> x;
  pack_variables<D>(u, rho, range, x);
  std::vector<double> lower, upper;
  if (range) {
    lower.assign(x.size(), -HUGE_VAL);
    upper.assign(x.size(), HUGE_VAL);
    for (std::size_t i = 0; i < n; ++i) {
      // Above r_min by twice what step 2 may take, so that the clipped radius stays in range.
      lower[D * n + i] = std::min(r_min * (1 + 2 * kClipAllowance), r0[i]) / frame.scale;
      upper[D * n + i] = std::max(r_max, r0[i]) / frame.scale;
    }
  }
  LeastSquaresObjective<D> eq4{&edges, &boundary, range ? nullptr : &rho, n};
  rep.objective_before = eq4(x.data(), nullptr);
  BoundedLbfgs minimiser(range ? &lower : nullptr, range ? &upper : nullptr);
  rep.objective_after = minimiser.run(x, options.evaluations, 0.0, eq4);
  rep.evaluations = eq4.evaluations - 1;
  unpack_variables<D>(x, range, u, rho);
  rep.solve_seconds = since(ts);

  std::vector<Vec<D>> c(n);
  std::vector<double> r(n);
  const auto to_local = [&] {
    for (std::size_t i = 0; i < n; ++i) {
      c[i] = frame.out(u[i]);
      r[i] = rho[i] * frame.scale;
    }
  };
  to_local();
  rep.solid_solved = solid_of<D>(r);
  near_pairs<D>(c, r, 0.0, [&](std::uint32_t i, std::uint32_t j, double o) {
    if (o <= contact_tolerance * std::min(r[i], r[j])) return;
    ++rep.overlaps_solved;
    rep.max_overlap_solved = std::max(rep.max_overlap_solved, o / std::min(r[i], r[j]));
  });

  // Steps 1-4 on the whole move; step 5: the largest share t of it (by bisection, t = 0
  // being the packing given) after which they leave a valid packing.
  std::vector<Vec<D>> u0(n);
  std::vector<double> rho0(n);
  for (std::size_t i = 0; i < n; ++i) {
    u0[i] = frame.in(c0[i]);
    rho0[i] = r0[i] / frame.scale;
  }
  const OverlapRemoval<D> removal{container, frame, r0, r_min, r_max, range, options.relax_rounds, options.relax_evaluations,
                                  contact_tolerance, &eq4, &minimiser};
  std::vector<Vec<D>> ut(n), best_c = c0;
  std::vector<double> rhot(n), best_r = r0;
  const auto attempt = [&](double t) {
    for (std::size_t i = 0; i < n; ++i) {
      ut[i] = u0[i] + t * (u[i] - u0[i]);
      rhot[i] = rho0[i] + t * (rho[i] - rho0[i]);
    }
    std::vector<Vec<D>> c;
    std::vector<double> r;
    LeastSquaresReport figures;
    if (!removal.run(ut, rhot, c, r, figures)) return false;
    best_c = std::move(c);
    best_r = std::move(r);
    rep.kept_share = t;
    rep.relax_rounds = figures.relax_rounds;
    rep.relax_evaluations = figures.relax_evaluations;
    rep.max_overlap_relaxed = figures.max_overlap_relaxed;
    rep.sweeps = figures.sweeps;
    rep.swelled = figures.swelled;
    rep.radii_clipped = figures.radii_clipped;
    rep.max_clip = figures.max_clip;
    return true;
  };
  rep.kept_share = 0;
  if (!attempt(1.0)) {
    double lo = 0, hi = 1;
    for (int k = 0; k < kBisections; ++k) {
      const double mid = (lo + hi) / 2;
      (attempt(mid) ? lo : hi) = mid;
    }
  }
  if (range && solid_of<D>(best_r) < rep.solid_before) {  // a densifier that loses solid: the packing given
    best_c = c0;
    best_r = r0;
    rep.kept_share = 0;
    rep.less_dense = true;
  }
  packing.centers = std::move(best_c);
  packing.radii = std::move(best_r);

  for (std::size_t i = 0; i < n; ++i) {
    const double dr = std::abs(packing.radii[i] - r0[i]) / r0[i];
    rep.mean_radius_change += dr / static_cast<double>(n);
    rep.max_radius_change = std::max(rep.max_radius_change, dr);
    if (packing.radii[i] > r0[i] * (1 + 1e-12)) ++rep.radii_grown;  // not the frame's rounding
    const double move = (packing.centers[i] - c0[i]).norm() / r0[i];
    rep.mean_move += move / static_cast<double>(n);
    rep.max_move = std::max(rep.max_move, move);
  }
  rep.solid_after = solid_of<D>(packing.radii);
  rep.seconds = since(t0);
  return rep;
}

}  // namespace

/// The work is done with the particles in the order of a Hilbert curve through cells of the mean
/// radius, so that neighbours are near in memory (a packing in the front's order of growth had
/// neighbours ~10^4 entries apart at 10^6 spheres); the result goes back in the order given.
template <int D>
LeastSquaresReport densify_least_squares(Packing<D>& packing, const Container<D>& container, double r_min,
                                         double r_max, const LeastSquaresOptions& options, double contact_tolerance) {
  const std::size_t n = packing.size();
  Aabb<D> box;
  double mean = 0;
  for (std::size_t i = 0; i < n; ++i) {
    box.extend(packing.centers[i]);
    mean += packing.radii[i] / static_cast<double>(n);
  }
  const double edge = n ? std::max(mean, box.size().maxCoeff() / double(1 << 20)) : 1.0;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
  for (std::size_t i = 0; i < n; ++i) keyed[i] = {hilbert_key<D>(packing.centers[i], box.lo, edge), static_cast<std::uint32_t>(i)};
  std::sort(keyed.begin(), keyed.end());
  Packing<D> sorted;
  sorted.origin = packing.origin;
  sorted.reserve(n);
  for (const auto& [key, i] : keyed) sorted.add(packing.centers[i], packing.radii[i]);
  const LeastSquaresReport rep = densify_in_order<D>(sorted, container, r_min, r_max, options, contact_tolerance);
  for (std::size_t k = 0; k < n; ++k) {
    packing.centers[keyed[k].second] = sorted.centers[k];
    packing.radii[keyed[k].second] = sorted.radii[k];
  }
  return rep;
}

template LeastSquaresReport densify_least_squares<2>(Packing<2>&, const Container<2>&, double, double,
                                                      const LeastSquaresOptions&, double);
template LeastSquaresReport densify_least_squares<3>(Packing<3>&, const Container<3>&, double, double,
                                                      const LeastSquaresOptions&, double);

}  // namespace fp
