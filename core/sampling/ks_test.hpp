#pragma once
// One-sample Kolmogorov–Smirnov test: radii of a packing against the requested distribution,
// and (paper 002, Sec. 4) centre coordinates against the uniform distribution, where
// sqrt(n) D_n is compared with 1.358, the asymptotic 5 % critical value.
#include <cstddef>
#include <functional>
#include <vector>

namespace fp {

/// Asymptotic 5 % critical value of sqrt(n) D_n (Kolmogorov distribution), as used by paper 002.
inline constexpr double kKsCritical5Percent = 1.358;

/// D_n = sup_x |F_n(x) - F(x)| of the samples (any order; ties allowed) against the CDF F.
/// Throws std::invalid_argument for an empty sample.
double ks_statistic(std::vector<double> samples, const std::function<double(double)>& cdf);

/// P(K > lambda) for the Kolmogorov distribution K = lim sqrt(n) D_n:
/// 2 sum_{j>=1} (-1)^(j-1) exp(-2 j^2 lambda^2) (its dual Jacobi-theta form for small lambda).
double kolmogorov_survival(double lambda);

/// p-value of D_n = d from n samples: kolmogorov_survival((sqrt(n) + 0.12 + 0.11 / sqrt(n)) d),
/// Stephens' small-sample correction (as in Numerical Recipes' ksone). Throws for n == 0.
double ks_pvalue(double d, std::size_t n);

}  // namespace fp
