#include "core/metrics/contacts.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

#include "core/metrics/cell_list.hpp"
#include "core/metrics/contact_network.hpp"

namespace fp {

template <int D>
std::vector<PairContact> find_pair_contacts(const Packing<D>& packing, double rel_tol) {
  if (!(rel_tol >= 0.0) || !std::isfinite(rel_tol))
    throw std::invalid_argument("find_pair_contacts: rel_tol must be finite and >= 0");
  const CellList<D> cells(packing.centers, packing.radii, rel_tol);
  std::vector<PairContact> out;
  cells.for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
    const double ri = packing.radii[i], rj = packing.radii[j];
    const double gap = (packing.centers[i] - packing.centers[j]).norm() - ri - rj;
    if (gap <= rel_tol * std::min(ri, rj)) out.push_back({i, j, gap});
  });
  ContactNetwork<D> net;
  net.pairs = std::move(out);
  sort_by_pair(net, packing.size());
  return std::move(net.pairs);
}

template <int D>
std::vector<WallContact> find_wall_contacts(const Packing<D>& packing, const Container<D>& container,
                                            double rel_tol) {
  if (!(rel_tol >= 0.0) || !std::isfinite(rel_tol))
    throw std::invalid_argument("find_wall_contacts: rel_tol must be finite and >= 0");
  std::vector<WallContact> out;
  for (std::size_t i = 0; i < packing.size(); ++i) {
    const double r = packing.radii[i];
    if (!(r >= 0.0) || !std::isfinite(r) || !packing.centers[i].allFinite()) continue;
    const double gap = -container.signed_distance(packing.centers[i]) - r;
    if (gap <= rel_tol * r) out.push_back({static_cast<std::uint32_t>(i), gap});
  }
  return out;
}

std::vector<std::uint32_t> coordination_numbers(std::size_t particle_count, const std::vector<PairContact>& contacts) {
  std::vector<std::uint32_t> z(particle_count, 0);
  for (const PairContact& c : contacts) {
    ++z[c.i];
    ++z[c.j];
  }
  return z;
}

template <int D>
std::vector<Vec<D>> centre_lines(const Packing<D>& packing, const std::vector<PairContact>& contacts) {
  std::vector<Vec<D>> lines;
  lines.reserve(contacts.size());
  for (const PairContact& c : contacts) lines.push_back(packing.centers[c.j] - packing.centers[c.i]);
  return lines;
}

template <int D>
double smallest_radius(const Packing<D>& packing) {
  double r_min = std::numeric_limits<double>::infinity();
  for (const double r : packing.radii)
    if (r > 0.0 && std::isfinite(r)) r_min = std::min(r_min, r);
  return std::isfinite(r_min) ? r_min : 0.0;
}

template std::vector<PairContact> find_pair_contacts<2>(const Packing<2>&, double);
template std::vector<PairContact> find_pair_contacts<3>(const Packing<3>&, double);
template std::vector<WallContact> find_wall_contacts<2>(const Packing<2>&, const Container<2>&, double);
template std::vector<WallContact> find_wall_contacts<3>(const Packing<3>&, const Container<3>&, double);
template std::vector<Vec<2>> centre_lines<2>(const Packing<2>&, const std::vector<PairContact>&);
template std::vector<Vec<3>> centre_lines<3>(const Packing<3>&, const std::vector<PairContact>&);
template double smallest_radius<2>(const Packing<2>&);
template double smallest_radius<3>(const Packing<3>&);

}  // namespace fp
