#include "core/metrics/contact_stats.hpp"

#include <algorithm>
#include <cstdio>

#include "core/metrics/contacts.hpp"

namespace fp {

std::string ContactStats::summary() const {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "z = %.4f (%.4f with walls), %llu contacts, %llu wall contacts, %llu rattlers, "
                "max overlap %.3g r_min, tol %.3g",
                mean_coordination, mean_coordination_with_walls, static_cast<unsigned long long>(contacts),
                static_cast<unsigned long long>(wall_contacts), static_cast<unsigned long long>(rattlers),
                max_overlap_rel, tolerance);
  return buf;
}

ContactStats contact_stats_of(int dimension, std::size_t particles, const std::vector<PairContact>& pairs,
                              const std::vector<WallContact>* walls, double r_unit, double rel_tol) {
  ContactStats s;
  s.tolerance = rel_tol;
  s.particles = particles;
  s.contacts = pairs.size();

  const std::vector<std::uint32_t> z = coordination_numbers(particles, pairs);
  std::vector<std::uint32_t> z_all = z;
  if (walls != nullptr) {
    s.wall_contacts = walls->size();
    for (const WallContact& w : *walls) ++z_all[w.i];
  }

  const std::uint32_t z_max = z.empty() ? 0 : *std::max_element(z.begin(), z.end());
  s.histogram.assign(z_max + 1, 0);
  for (const std::uint32_t zi : z) ++s.histogram[zi];
  const std::uint32_t stable = dimension == 3 ? 3 : 2;
  for (const std::uint32_t zi : z_all) s.rattlers += zi < stable ? 1 : 0;
  if (s.particles > 0) {
    const double n = static_cast<double>(s.particles);
    s.mean_coordination = 2.0 * static_cast<double>(s.contacts) / n;
    s.mean_coordination_with_walls = (2.0 * static_cast<double>(s.contacts) + static_cast<double>(s.wall_contacts)) / n;
  }

  // Every overlapping pair has gap < 0 <= tol, so it is in the contact list.
  double worst_gap = 0.0;
  for (const PairContact& c : pairs)
    if (c.gap < worst_gap) {
      worst_gap = c.gap;
      s.worst_i = c.i;
      s.worst_j = c.j;
    }
  if (worst_gap < 0.0) s.max_overlap_rel = -worst_gap / r_unit;
  return s;
}

template <int D>
ContactStats contact_stats(const Packing<D>& packing, const Container<D>* container_or_null, double rel_tol) {
  const std::vector<PairContact> pairs = find_pair_contacts(packing, rel_tol);
  std::vector<WallContact> walls;
  if (container_or_null != nullptr) walls = find_wall_contacts(packing, *container_or_null, rel_tol);
  return contact_stats_of(D, packing.size(), pairs, container_or_null ? &walls : nullptr, smallest_radius(packing), rel_tol);
}

template ContactStats contact_stats<2>(const Packing<2>&, const Container<2>*, double);
template ContactStats contact_stats<3>(const Packing<3>&, const Container<3>*, double);

}  // namespace fp
