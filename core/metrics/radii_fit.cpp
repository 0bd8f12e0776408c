#include "core/metrics/radii_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/sampling/chi_square_test.hpp"
#include "core/sampling/ks_test.hpp"

namespace fp {
namespace {

using Atoms = std::vector<std::pair<double, double>>;

// Index of the value nearest to r (values increasing).
std::size_t nearest_atom(const Atoms& atoms, double r) {
  const auto it = std::lower_bound(atoms.begin(), atoms.end(), r,
                                   [](const std::pair<double, double>& a, double x) { return a.first < x; });
  if (it == atoms.begin()) return 0;
  if (it == atoms.end()) return atoms.size() - 1;
  const std::size_t k = static_cast<std::size_t>(it - atoms.begin());
  return (r - atoms[k - 1].first <= atoms[k].first - r) ? k - 1 : k;
}

double atom_excess(const Atoms& atoms, double r) {
  const double v = atoms[nearest_atom(atoms, r)].first;
  return std::abs(r - v) / v;
}

}  // namespace

std::string RadiiFit::describe() const {
  char buf[240];
  if (!computed()) return "not computed";
  if (test == "constant") {
    std::snprintf(buf, sizeof buf, "constant: max |r - value| = %.3g value (%llu radii differ), p = %.3g", statistic,
                  static_cast<unsigned long long>(off_support), p);
  } else if (test == "chi-square") {
    char rare_text[96] = "";
    if (rare)
      std::snprintf(rare_text, sizeof rare_text, " and %zu rare value%s counted exactly (smallest p = %.3g)", rare,
                    rare == 1 ? "" : "s", rare_p);
    std::snprintf(buf, sizeof buf, "chi-square X2 = %.4g (%d dof%s)%s, p = %.3g", statistic, dof,
                  off_support ? ", radii matching no value" : "", rare_text, p);
  } else {
    std::snprintf(buf, sizeof buf, "K-S D = %.4g, p = %.3g", statistic, p);
  }
  return buf;
}

double radius_excess(const RadiusDistribution& dist, double r) {
  const Atoms atoms = dist.atoms();
  if (!atoms.empty()) return atom_excess(atoms, r);
  if (r > dist.r_max()) return (r - dist.r_max()) / dist.r_max();
  if (r < dist.r_min()) return (dist.r_min() - r) / dist.r_min();
  return 0.0;
}

RadiiFit radii_fit(std::vector<double> radii, const RadiusDistribution& dist) {
  RadiiFit f;
  if (radii.empty()) return f;
  f.n = radii.size();
  const Atoms atoms = dist.atoms();
  if (atoms.empty()) {
    f.test = "K-S";
    f.statistic = ks_statistic(std::move(radii), [&dist](double r) { return dist.cdf(r); });
    f.p = ks_pvalue(f.statistic, f.n);
    return f;
  }
  std::vector<std::uint64_t> counts(atoms.size(), 0);
  double worst = 0.0;
  for (const double r : radii) {
    const std::size_t k = nearest_atom(atoms, r);
    const double e = std::abs(r - atoms[k].first) / atoms[k].first;
    worst = std::max(worst, e);
    if (e > kRadiusSlack) ++f.off_support;
    else ++counts[k];
  }
  if (atoms.size() == 1) {
    f.test = "constant";
    f.statistic = worst;
    f.p = f.off_support ? 0.0 : 1.0;
    return f;
  }
  f.test = "chi-square";
  if (f.off_support) {  // a radius of probability zero under the law
    f.statistic = std::numeric_limits<double>::infinity();
    f.p = 0.0;
    return f;
  }
  std::vector<double> probabilities;
  for (const auto& a : atoms) probabilities.push_back(a.second);
  const ChiSquareResult c = chi_square_counts(counts, probabilities);
  f.statistic = c.statistic;
  f.dof = c.dof;
  f.rare = c.rare;
  f.rare_p = c.rare_p;
  f.p = c.p;
  return f;
}

}  // namespace fp
