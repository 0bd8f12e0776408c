#include "core/metrics/partial_coordination.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sampling/sort_doubles.hpp"

namespace fp {
namespace {

bool usable(double r) { return r > 0.0 && std::isfinite(r); }

// Entries of the ascending `sorted` that are >= t.
std::uint64_t at_least(const std::vector<double>& sorted, double t) {
  return static_cast<std::uint64_t>(sorted.end() - std::lower_bound(sorted.begin(), sorted.end(), t));
}

}  // namespace

PartialCoordination partial_coordination(const std::vector<double>& radii, const std::vector<PairContact>& contacts,
                                         int points) {
  if (points < 2) throw std::invalid_argument("partial_coordination: points must be >= 2");
  std::vector<double> r;  // particle radii, ascending
  for (const double v : radii)
    if (usable(v)) r.push_back(v);
  sort_doubles(r);
  std::vector<double> weakest;  // per contact, the smaller radius: the contact survives while both do
  for (const PairContact& c : contacts)
    if (usable(radii[c.i]) && usable(radii[c.j])) weakest.push_back(std::min(radii[c.i], radii[c.j]));
  sort_doubles(weakest);

  PartialCoordination out;
  const double r_min = r.empty() ? 0.0 : r.front(), r_max = r.empty() ? 0.0 : r.back();
  for (int k = 0; k < points; ++k) {
    const double xi = static_cast<double>(k) / (points - 1);
    // At xi = 1 exactly r_max, so the largest particles remain.
    const double t = k == points - 1 ? r_max : r_min + xi * (r_max - r_min);
    const std::uint64_t n = at_least(r, t), nc = at_least(weakest, t);
    out.xi.push_back(xi);
    out.radius.push_back(t);
    out.particles.push_back(n);
    out.contacts.push_back(nc);
    out.z.push_back(n > 0 ? 2.0 * static_cast<double>(nc) / static_cast<double>(n) : 0.0);
  }
  return out;
}

}  // namespace fp
