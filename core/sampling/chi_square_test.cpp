#include "core/sampling/chi_square_test.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fp {
namespace {

// Regularised lower incomplete gamma P(a, x) by its series, for x < a + 1 (Numerical Recipes 6.2).
double gamma_p_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int k = 1; k < 1000; ++k) {
    term *= x / (a + k);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-17) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Regularised upper incomplete gamma Q(a, x) by its continued fraction (modified Lentz), for
// x >= a + 1: computed directly, so tiny p-values keep their relative accuracy.
double gamma_q_fraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

// log P(X = k) for X binomial(n, p).
double binomial_log_pmf(std::uint64_t k, std::uint64_t n, double p) {
  const double kd = static_cast<double>(k), nd = static_cast<double>(n);
  return std::lgamma(nd + 1) - std::lgamma(kd + 1) - std::lgamma(nd - kd + 1) + kd * std::log(p) + (nd - kd) * std::log1p(-p);
}

// P(X <= k) (lower) or P(X >= k), summed from k outwards: the terms fall off beyond the mode, so
// the sum stops when they no longer count, or underflow (the tail taken is the one away from the
// mean: a count far beyond it starts below the smallest double, and so does the rest).
double binomial_tail(std::uint64_t k, std::uint64_t n, double p, bool lower) {
  double sum = 0.0;
  for (std::uint64_t j = k;; lower ? --j : ++j) {
    const double term = std::exp(binomial_log_pmf(j, n, p));
    sum += term;
    if (term == 0.0 || term < sum * 1e-17 || (lower ? j == 0 : j == n)) break;
  }
  return std::min(1.0, sum);
}

}  // namespace

double binomial_two_sided_p(std::uint64_t k, std::uint64_t n, double p) {
  if (!(p > 0.0 && p < 1.0) || k > n) throw std::invalid_argument("binomial_two_sided_p: needs 0 < p < 1 and k <= n");
  const double mean = static_cast<double>(n) * p;
  // The tail away from the mean, summed; the other is at least about one half.
  const double tail = static_cast<double>(k) <= mean ? binomial_tail(k, n, p, true) : binomial_tail(k, n, p, false);
  return std::min(1.0, 2.0 * tail);
}

double chi_square_survival(double x, int dof) {
  if (dof < 1) throw std::invalid_argument("chi_square_survival: dof must be >= 1");
  if (std::isnan(x)) throw std::invalid_argument("chi_square_survival: x is NaN");
  if (!(x > 0.0)) return 1.0;
  if (std::isinf(x)) return 0.0;
  const double a = 0.5 * dof, h = 0.5 * x;
  return h < a + 1.0 ? 1.0 - gamma_p_series(a, h) : gamma_q_fraction(a, h);
}

ChiSquareResult chi_square_counts(const std::vector<std::uint64_t>& observed, const std::vector<double>& probabilities) {
  if (observed.size() != probabilities.size())
    throw std::invalid_argument("chi_square_counts: observed and probabilities differ in size");
  std::uint64_t total = 0;
  for (const std::uint64_t o : observed) total += o;
  if (total == 0) throw std::invalid_argument("chi_square_counts: the sample is empty");
  for (const double p : probabilities)
    if (!(p > 0.0) || !std::isfinite(p)) throw std::invalid_argument("chi_square_counts: probabilities must be > 0");
  const double n = static_cast<double>(total);

  // Pool adjacent classes until each expects >= 5; a short tail joins the last pooled class.
  std::vector<double> obs, expd;
  double o_acc = 0.0, e_acc = 0.0;
  for (std::size_t k = 0; k < observed.size(); ++k) {
    o_acc += static_cast<double>(observed[k]);
    e_acc += n * probabilities[k];
    if (e_acc >= 5.0) {
      obs.push_back(o_acc);
      expd.push_back(e_acc);
      o_acc = e_acc = 0.0;
    }
  }
  if (e_acc > 0.0 || o_acc > 0.0) {
    if (obs.empty()) {
      obs.push_back(o_acc);
      expd.push_back(e_acc);
    } else {
      obs.back() += o_acc;
      expd.back() += e_acc;
    }
  }

  ChiSquareResult r;
  r.classes = obs.size();
  r.dof = static_cast<int>(r.classes) - 1;
  // One class: its count is n whatever the law, no evidence either way.
  double smallest = 1.0;
  if (r.dof > 0) {
    for (std::size_t k = 0; k < obs.size(); ++k) r.statistic += (obs[k] - expd[k]) * (obs[k] - expd[k]) / expd[k];
    smallest = chi_square_survival(r.statistic, r.dof);
  }
  for (std::size_t k = 0; k < observed.size() && observed.size() > 1; ++k) {
    if (!(n * probabilities[k] < 5.0) || !(probabilities[k] < 1.0)) continue;
    ++r.rare;
    r.rare_p = std::min(r.rare_p, binomial_two_sided_p(observed[k], total, probabilities[k]));
  }
  const std::size_t tests = (r.dof > 0 ? 1 : 0) + r.rare;
  r.p = r.rare ? std::min(1.0, static_cast<double>(tests) * std::min(smallest, r.rare_p)) : smallest;
  return r;
}

}  // namespace fp
