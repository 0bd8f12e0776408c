#pragma once
// Limited-memory BFGS (Nocedal and Wright, Numerical Optimization, Algorithm 7.4 and 7.5: the
// two-loop recursion) with a backtracking Armijo line search, over Eigen vectors. The least-
// squares densification minimises over millions of unknowns: NLopt's L-BFGS (Luksan's code)
// spent 55 % of a 50,000-sphere run in its own scalar vector loops (perf), this one's vector
// work is Eigen's. Deterministic: the same start gives the same iterates.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace fp {

struct LbfgsOptions {
  int evaluations = 400;        ///< of the objective, at most
  int memory = 6;               ///< (s, y) pairs kept
  double relative_decrease = 1e-12;  ///< stop when an iteration lowers f by less than this times |f|
  double stop_below = -std::numeric_limits<double>::infinity();  ///< stop once f is at most this
};

struct LbfgsResult {
  double value = 0.0;
  int evaluations = 0;
};

/// The vectors of a run, kept between runs of the same size: a minimisation over millions of
/// unknowns repeated round after round (densify/least_squares.cpp) otherwise spends its time in
/// page faults on fresh memory (1,000,000 spheres: 9 % of the run).
struct LbfgsWorkspace {
  Eigen::VectorXd g, x_new, g_new, d;
  std::vector<Eigen::VectorXd> S, Y;  ///< a ring of (s, y) pairs
};

/// Minimises f from x (in place). f(x, g) returns the value and writes the gradient into g (an
/// Eigen::VectorXd of x's size). The step of the first iteration is scaled to move x by about
/// one unit along the steepest descent (the objective's variables are of order one).
template <class F>
LbfgsResult minimise_lbfgs(Eigen::VectorXd& x, F&& f, const LbfgsOptions& o, LbfgsWorkspace& w) {
  const Eigen::Index n = x.size();
  const std::size_t m = static_cast<std::size_t>(std::max(o.memory, 1));
  w.g.resize(n), w.x_new.resize(n), w.g_new.resize(n), w.d.resize(n);
  w.S.resize(m), w.Y.resize(m);
  for (std::size_t k = 0; k < m; ++k) w.S[k].resize(n), w.Y[k].resize(n);
  Eigen::VectorXd &g = w.g, &x_new = w.x_new, &g_new = w.g_new, &d = w.d;
  std::vector<double> rho(m), alpha(m);
  std::size_t head = 0, count = 0;  // the newest pair is at (head + count - 1) % m
  const auto slot = [&](std::size_t age) { return (head + age) % m; };  // age 0: the oldest kept
  LbfgsResult r;
  double fx = f(x, g);
  r.evaluations = 1;
  while (r.evaluations < o.evaluations && fx > o.stop_below) {
    // Two-loop recursion: d = -H g.
    d = -g;
    for (std::size_t a = count; a-- > 0;) {
      const std::size_t k = slot(a);
      alpha[k] = rho[k] * w.S[k].dot(d);
      d.noalias() -= alpha[k] * w.Y[k];
    }
    if (count > 0) {
      const std::size_t k = slot(count - 1);
      d *= 1 / (rho[k] * w.Y[k].squaredNorm());  // s.y / y.y
    } else {
      d /= std::max(g.lpNorm<Eigen::Infinity>(), 1e-300);
    }
    for (std::size_t a = 0; a < count; ++a) {
      const std::size_t k = slot(a);
      const double beta = rho[k] * w.Y[k].dot(d);
      d.noalias() += (alpha[k] - beta) * w.S[k];
    }
    double slope = g.dot(d);
    if (!(slope < 0)) {  // not a descent direction: forget the memory, go down the gradient
      count = 0;
      d = -g / std::max(g.lpNorm<Eigen::Infinity>(), 1e-300);
      slope = g.dot(d);
      if (!(slope < 0)) break;  // a stationary point
    }
    // Backtracking to sufficient decrease (Armijo, c1 = 1e-4), halving the step.
    double t = 1.0, f_new = 0.0;
    bool accepted = false;
    while (r.evaluations < o.evaluations) {
      x_new = x + t * d;
      f_new = f(x_new, g_new);
      ++r.evaluations;
      if (f_new <= fx + 1e-4 * t * slope) {
        accepted = true;
        break;
      }
      t *= 0.5;
      if (t < 1e-20) break;
    }
    if (!accepted) break;
    // The new pair goes into the next slot (the oldest's when full: the oldest is then gone
    // even if the new one is not kept), s, y and their products in one pass; it is kept only if
    // the curvature is positive.
    const std::size_t k = count < m ? slot(count) : head;
    double* sk = w.S[k].data();
    double* yk = w.Y[k].data();
    const double *xn = x_new.data(), *xo = x.data(), *gn = g_new.data(), *go = g.data();
    double sy = 0, ss = 0, yy = 0;
    for (Eigen::Index q = 0; q < n; ++q) {
      const double sq = xn[q] - xo[q], yq = gn[q] - go[q];
      sk[q] = sq, yk[q] = yq;
      sy += sq * yq, ss += sq * sq, yy += yq * yq;
    }
    const bool keep = sy > 1e-12 * std::sqrt(ss * yy);
    if (keep) rho[k] = 1.0 / sy;
    if (count == m) head = (head + 1) % m, count -= keep ? 0 : 1;
    else count += keep ? 1 : 0;
    const double decrease = fx - f_new;
    x.swap(x_new);
    g.swap(g_new);
    fx = f_new;
    if (decrease <= o.relative_decrease * std::abs(fx)) break;
  }
  r.value = fx;
  return r;
}

/// The same with a workspace of its own.
template <class F>
LbfgsResult minimise_lbfgs(Eigen::VectorXd& x, F&& f, const LbfgsOptions& o) {
  LbfgsWorkspace w;
  return minimise_lbfgs(x, std::forward<F>(f), o, w);
}

}  // namespace fp
