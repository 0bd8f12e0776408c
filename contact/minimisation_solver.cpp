#include "contact/minimisation_solver.hpp"

#include <nlopt.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "contact/gap_newton.hpp"
#include "shapes/sphere_shape.hpp"

namespace fp {

const char* minimisation_algorithms() { return "newton, slsqp, lbfgs, nelder-mead, cobyla, sbplx"; }

namespace {

struct Algorithm {
  nlopt::algorithm id;
  bool smooth;  // Σω² with gradients; otherwise Σ|ω| without (the paper's form)
};

Algorithm algorithm_of(const std::string& name) {
  if (name == "slsqp" || name == "newton") return {nlopt::LD_SLSQP, true};
  if (name == "lbfgs") return {nlopt::LD_LBFGS, true};
  if (name == "nelder-mead") return {nlopt::LN_NELDERMEAD, false};
  if (name == "cobyla") return {nlopt::LN_COBYLA, false};
  if (name == "sbplx") return {nlopt::LN_SBPLX, false};
  throw std::invalid_argument("unknown minimisation algorithm '" + name + "' (known: " + minimisation_algorithms() + ")");
}

}  // namespace

template <int D>
struct MinimisationSolver<D>::Impl {
  Algorithm algorithm;
  nlopt::opt opt;  // reused: building an nlopt::opt per solve costs more than a capsule solve

  // The problem being solved, read by the objective.
  const NarrowPhase<D>* np = nullptr;
  std::span<const Body<D>> fixed;
  std::array<Particle<D>, D> fixed_spheres;  // plain sphere bodies seen as particles
  std::vector<double> y;                      // NLopt's variables, kept between runs (no allocation per run)
  Particle<D> mobile;
  Vec<D> origin, plane_point, plane_normal;
  double scale = 1, side = 0;  // side: +1/-1 = keep n.(x - plane_point) of that sign; 0 = free
  MinimisationStats* stats = nullptr;

  bool newton_first;  // "newton": Newton from each start, SLSQP only where it does not converge

  Impl(const MinimisationOptions& o)
      : algorithm(algorithm_of(o.algorithm)), opt(algorithm.id, D), newton_first(o.algorithm == "newton") {}

  const Particle<D>& fixed_particle(int i) const {
    return fixed[i].shaped ? *fixed[i].shaped : fixed_spheres[static_cast<std::size_t>(i)];
  }

  /// Gaps and their gradients (for the mobile position) at world position x.
  void gaps(const Vec<D>& x, std::array<Gap<D>, D>& g) {
    ++stats->evaluations;
    mobile.pose.position = x;
    for (int i = 0; i < D; ++i)
      g[static_cast<std::size_t>(i)] = fixed[i].is_wall() ? np->gap(*fixed[i].wall, mobile) : np->gap(fixed_particle(i), mobile);
  }

  Vec<D> world(const double* y) const {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = origin[a] + scale * y[a];
    return x;
  }

  // Objective in local units y = (x - origin) / scale, gaps in units of scale: relative
  // tolerances whatever the coordinates' magnitude.
  static double objective(unsigned, const double* y, double* grad, void* data) {
    Impl& s = *static_cast<Impl*>(data);
    const Vec<D> x = s.world(y);
    std::array<Gap<D>, D> g;
    s.gaps(x, g);
    double f = 0;
    Vec<D> df = Vec<D>::Zero();
    for (const Gap<D>& gi : g) {
      const double w = gi.value / s.scale;
      if (s.algorithm.smooth) {
        f += w * w;
        df += 2 * w * gi.normal;
      } else {
        f += std::abs(w);
      }
    }
    if (s.side != 0) {  // the half-space restriction of the paper, as a penalty
      const double v = s.side * s.plane_normal.dot(x - s.plane_point) / s.scale;
      if (v < 0) {
        f += s.algorithm.smooth ? v * v : -v;
        if (s.algorithm.smooth) df += 2 * v * s.side * s.plane_normal;
      }
    }
    if (grad)
      for (int a = 0; a < D; ++a) grad[a] = df[a];
    return f;
  }
};

template <int D>
MinimisationSolver<D>::MinimisationSolver(const NarrowPhase<D>& narrow_phase, const MinimisationOptions& options)
    : np_(narrow_phase), opt_(options), impl_(std::make_unique<Impl>(options)) {
  if (!(opt_.gap_tolerance > 0)) throw std::invalid_argument("gap_tolerance must be positive");
  if (opt_.max_evaluations < 1) throw std::invalid_argument("max_evaluations must be at least 1");
  nlopt::opt& o = impl_->opt;
  o.set_maxeval(opt_.max_evaluations);
  o.set_xtol_abs(1e-3 * opt_.gap_tolerance);
  // With the Newton polish the minimiser only has to get close (Newton then converges
  // quadratically); without it, it must reach the tolerance itself.
  const double close = (opt_.polish ? 1e2 : 1e-2) * opt_.gap_tolerance;
  const double f_tol = impl_->algorithm.smooth ? close * close : close;
  o.set_stopval(f_tol);
  // A minimisation with no zero to find (most of them: no contact position in that half-space)
  // stalls at a positive value; stop it once an iteration gains less than 1 % (converging
  // ones gain orders of magnitude per iteration).
  o.set_ftol_rel(1e-2);
  if (!impl_->algorithm.smooth) o.set_initial_step(0.1);
}

template <int D>
MinimisationSolver<D>::~MinimisationSolver() = default;

template <int D>
int MinimisationSolver<D>::solve(std::span<const Body<D>> fixed, const Mobile<D>& mobile,
                                 std::span<Placement<D>> out) const {
  if (static_cast<int>(fixed.size()) != D || !mobile.shape || out.empty()) return 0;
  ++stats_.solves;
  Impl& s = *impl_;
  s.np = &np_;
  s.stats = &stats_;
  s.fixed = fixed;
  for (int i = 0; i < D; ++i)
    if (!fixed[i].is_wall() && !fixed[i].shaped) {
      auto& p = s.fixed_spheres[static_cast<std::size_t>(i)];
      // Reused while the radius is the same; a replaced one is dropped from the narrow phase's
      // FCL cache, which keeps every shape it has seen alive.
      if (!p.shape || p.shape->bounding_radius() != fixed[i].radius) {
        if (p.shape) np_.forget(p.shape.get());
        p.shape = std::make_shared<SphereShape<D>>(fixed[i].radius);
      }
      p.pose.position = fixed[i].center;
    }
  s.mobile.shape = mobile.shape;
  s.mobile.pose.rotation = mobile.rotation;
  const double r_mob = mobile.shape->bounding_radius();
  s.scale = r_mob;

  // Tolerance per body: relative to the smaller of the two sizes (circumscribed radii).
  std::array<double, D> limit;
  for (int i = 0; i < D; ++i)
    limit[static_cast<std::size_t>(i)] = opt_.gap_tolerance * (fixed[i].is_wall() ? r_mob : std::min(r_mob, fixed[i].radius));

  // Half-space of the paper: the hyperplane through the fixed centres (walls: none).
  bool all_particles = true;
  for (const Body<D>& b : fixed) all_particles &= !b.is_wall();
  bool has_plane = false;
  if (all_particles) {
    Vec<D> n;
    if constexpr (D == 2) {
      const Vec2 d = fixed[1].center - fixed[0].center;
      n = Vec2(-d.y(), d.x());
    } else {
      n = (fixed[1].center - fixed[0].center).cross(fixed[2].center - fixed[0].center);
    }
    double span = 0;
    for (const Body<D>& b : fixed) span = std::max(span, (b.center - fixed[0].center).norm());
    if (n.norm() > 1e-9 * span * (D == 2 ? 1 : span)) {
      has_plane = true;
      s.plane_normal = n.normalized();
      s.plane_point = fixed[0].center;
    }
  }

  // Starting points: the analytic positions of equivalent spheres.
  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> starts;
  int n_starts = gap_newton::equivalent_sphere_starts<D>(fixed, *mobile.shape, starts);
  if (n_starts == 0 && has_plane) {  // far apart for equivalent spheres: both sides of the plane
    Vec<D> c = Vec<D>::Zero();
    for (const Body<D>& b : fixed) c += b.center / D;
    starts[0].position = c + r_mob * s.plane_normal;
    starts[1].position = c - r_mob * s.plane_normal;
    n_starts = 2;
  }
  if (n_starts == 0) {
    ++stats_.no_start;
    return 0;
  }

  int found = 0;
  std::array<Gap<D>, D> g;
  auto converged = [&](double slack) {
    for (int i = 0; i < D; ++i)
      if (std::abs(g[static_cast<std::size_t>(i)].value) > slack * limit[static_cast<std::size_t>(i)]) return false;
    return true;
  };
  auto is_new = [&](const Vec<D>& x) {
    for (int q = 0; q < found; ++q)
      if ((out[static_cast<std::size_t>(q)].position - x).norm() <= 1e-6 * r_mob) return false;
    return true;
  };
  // Newton on the D x D system ω_i(x) = 0 from x with gaps g, polishing to 1e-3 of the tolerance.
  auto newton = [&](Vec<D>& x, int iterations) {
    gap_newton::newton<D>([&](const Vec<D>& y, std::array<Gap<D>, D>& gy) { s.gaps(y, gy); },
                          [&](const std::array<Gap<D>, D>&) { return converged(1e-3); }, x, g, 0.5 * r_mob, iterations);
  };
  for (int k = 0; k < n_starts && found < static_cast<int>(out.size()); ++k) {
    const Vec<D> x0 = starts[static_cast<std::size_t>(k)].position;
    Vec<D> x = x0;
    bool done = false;
    if (impl_->newton_first) {  // Newton alone from the start; the minimiser only where it fails
      s.gaps(x, g);
      newton(x, 10);
      done = converged(1.0) && is_new(x);
    }
    if (!done) {
      s.origin = x0;
      s.side = has_plane ? (s.plane_normal.dot(x0 - s.plane_point) >= 0 ? 1.0 : -1.0) : 0.0;
      std::vector<double>& y = s.y;
      y.assign(D, 0.0);
      double f = 0;
      ++stats_.minimisations;
      s.opt.set_min_objective(&Impl::objective, &s);
      try {
        s.opt.optimize(y, f);
      } catch (const std::exception&) {
        // roundoff_limited and friends: y holds the best point NLopt reached; the gap test decides.
      }
      x = s.world(y.data());
      s.gaps(x, g);
      if (opt_.polish) newton(x, 12);
    }
    if (!converged(1.0)) {
      ++stats_.rejected_gap;
      continue;
    }
    if (!is_new(x)) continue;
    out[static_cast<std::size_t>(found++)].position = x;
    ++stats_.accepted;
  }
  return found;
}

template class MinimisationSolver<2>;
template class MinimisationSolver<3>;

}  // namespace fp
