// The L-BFGS of the least-squares densification (densify/lbfgs.hpp) on problems whose minimum is
// known: a badly scaled quadratic, Rosenbrock's valley, a sum of squares of many variables; the
// evaluation budget and the stop value honoured; the same iterates on a rerun.
#include "densify/lbfgs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fp {
namespace {

TEST(Lbfgs, BadlyScaledQuadratic) {
  // f = sum a_k (x_k - k)^2 with a_k from 1 to 1e4: minimum 0 at x_k = k.
  const int n = 50;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  const auto f = [&](const Eigen::VectorXd& v, Eigen::VectorXd& g) {
    double s = 0;
    for (int k = 0; k < n; ++k) {
      const double a = std::pow(1e4, k / double(n - 1)), d = v[k] - k;
      s += a * d * d;
      g[k] = 2 * a * d;
    }
    return s;
  };
  LbfgsOptions o;
  o.evaluations = 2000;
  const LbfgsResult r = minimise_lbfgs(x, f, o);
  EXPECT_LT(r.value, 1e-10);
  for (int k = 0; k < n; ++k) EXPECT_NEAR(x[k], k, 1e-5) << k;
  EXPECT_LE(r.evaluations, o.evaluations);
}

TEST(Lbfgs, RosenbrocksValley) {
  Eigen::VectorXd x(2);
  x << -1.2, 1.0;
  const auto f = [](const Eigen::VectorXd& v, Eigen::VectorXd& g) {
    const double a = 1 - v[0], b = v[1] - v[0] * v[0];
    g[0] = -2 * a - 400 * v[0] * b;
    g[1] = 200 * b;
    return a * a + 100 * b * b;
  };
  LbfgsOptions o;
  o.evaluations = 1000;
  const LbfgsResult r = minimise_lbfgs(x, f, o);
  EXPECT_NEAR(x[0], 1.0, 1e-4);
  EXPECT_NEAR(x[1], 1.0, 1e-4);
  EXPECT_LT(r.value, 1e-8);
}

TEST(Lbfgs, BudgetAndStopValueAreHonouredAndRerunsAreIdentical) {
  const int n = 10000;  // a chain of springs pinned at both ends, rest length 1
  const auto f = [&](const Eigen::VectorXd& v, Eigen::VectorXd& g) {
    g.setZero();
    double s = 0;
    for (int k = 0; k <= n; ++k) {
      const double left = k == 0 ? 0.0 : v[k - 1], right = k == n ? n + 1.0 : v[k];
      const double d = right - left - 1;
      s += d * d;
      if (k > 0) g[k - 1] -= 2 * d;
      if (k < n) g[k] += 2 * d;
    }
    return s;
  };
  Eigen::VectorXd a = Eigen::VectorXd::Zero(n), b = a;
  LbfgsOptions o;
  o.evaluations = 37;
  const LbfgsResult ra = minimise_lbfgs(a, f, o);
  const LbfgsResult rb = minimise_lbfgs(b, f, o);
  EXPECT_LE(ra.evaluations, 37);
  EXPECT_EQ(ra.value, rb.value);
  EXPECT_TRUE(a == b);
  Eigen::VectorXd c = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd g(n);
  const double start = f(c, g);
  o.evaluations = 100000;
  o.stop_below = start / 2;
  const LbfgsResult rc = minimise_lbfgs(c, f, o);
  EXPECT_LE(rc.value, start / 2);
  EXPECT_LT(rc.evaluations, 1000) << "stopped at the stop value, not the budget";
  // A workspace kept between runs (of other sizes too) gives the same iterates as a fresh one.
  LbfgsWorkspace w;
  o.evaluations = 37;
  o.stop_below = -std::numeric_limits<double>::infinity();
  Eigen::VectorXd small = Eigen::VectorXd::Zero(3);
  const auto bowl = [](const Eigen::VectorXd& v, Eigen::VectorXd& gv) {
    gv = 2 * v - Eigen::VectorXd::Ones(v.size());
    return v.squaredNorm() - v.sum();
  };
  minimise_lbfgs(small, bowl, o, w);
  EXPECT_NEAR(small[0], 0.5, 1e-9);
  for (int run = 0; run < 2; ++run) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
    const LbfgsResult rd = minimise_lbfgs(d, f, o, w);
    EXPECT_EQ(rd.value, ra.value) << "run " << run;
    EXPECT_TRUE(d == a) << "run " << run;
  }
}

}  // namespace
}  // namespace fp
