#pragma once
// Limited-memory BFGS (Nocedal and Wright, Numerical Optimization, Algorithm 7.4 and 7.5: the
// two-loop recursion) with a backtracking Armijo line search, over Eigen vectors. The least-
// squares densification minimises over millions of unknowns: NLopt's L-BFGS (Luksan's code)
// spent 55 % of a 50,000-sphere run in its own scalar vector loops (perf), this one's vector
// work is Eigen's. Deterministic: the same start gives the same iterates.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <deque>
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

/// Minimises f from x (in place). f(x, g) returns the value and writes the gradient into g (an
/// Eigen::VectorXd of x's size). The step of the first iteration is scaled to move x by about
/// one unit along the steepest descent (the objective's variables are of order one).
template <class F>
LbfgsResult minimise_lbfgs(Eigen::VectorXd& x, F&& f, const LbfgsOptions& o) {
  const Eigen::Index n = x.size();
  Eigen::VectorXd g(n), x_new(n), g_new(n), d(n);
  std::deque<Eigen::VectorXd> S, Y;
  std::deque<double> rho;
  LbfgsResult r;
  double fx = f(x, g);
  r.evaluations = 1;
  std::vector<double> alpha;
  while (r.evaluations < o.evaluations && fx > o.stop_below) {
    // Two-loop recursion: d = -H g.
    d = -g;
    alpha.assign(S.size(), 0.0);
    for (std::size_t k = S.size(); k-- > 0;) {
      alpha[k] = rho[k] * S[k].dot(d);
      d.noalias() -= alpha[k] * Y[k];
    }
    if (!S.empty()) d *= S.back().dot(Y.back()) / Y.back().squaredNorm();
    else d /= std::max(g.lpNorm<Eigen::Infinity>(), 1e-300);
    for (std::size_t k = 0; k < S.size(); ++k) {
      const double beta = rho[k] * Y[k].dot(d);
      d.noalias() += (alpha[k] - beta) * S[k];
    }
    double slope = g.dot(d);
    if (!(slope < 0)) {  // not a descent direction: forget the memory, go down the gradient
      S.clear(), Y.clear(), rho.clear();
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
    const double sy = (x_new - x).dot(g_new - g);
    if (sy > 1e-12 * (x_new - x).norm() * (g_new - g).norm()) {  // curvature: keep the pair
      if (static_cast<int>(S.size()) == o.memory) {  // the oldest pair's storage reused
        S.push_back(std::move(S.front())), Y.push_back(std::move(Y.front()));
        S.pop_front(), Y.pop_front(), rho.pop_front();
        S.back() = x_new - x;
        Y.back() = g_new - g;
      } else {
        S.push_back(x_new - x);
        Y.push_back(g_new - g);
      }
      rho.push_back(1.0 / sy);
    }
    const double decrease = fx - f_new;
    x.swap(x_new);
    g.swap(g_new);
    fx = f_new;
    if (decrease <= o.relative_decrease * std::abs(fx)) break;
  }
  r.value = fx;
  return r;
}

}  // namespace fp
