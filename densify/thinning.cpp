#include "densify/thinning.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace fp {

std::vector<char> thin_to_measure(const ThinningInput& in, double target_measure, int dimension, Rng& rng,
                                  ThinningReport& report, int classes) {
  const std::size_t n = in.measure.size();
  if (in.size.size() != n || in.wall_contacts.size() != n)
    throw std::invalid_argument("thin_to_measure: measure, size and wall_contacts differ in length");
  if (!(target_measure >= 0.0) || !std::isfinite(target_measure))
    throw std::invalid_argument("thin_to_measure: the target must be a finite measure >= 0");
  report = {};
  report.before = n;
  double solid = 0.0;
  for (const double m : in.measure) solid += m;
  report.measure_before = solid;
  std::vector<char> keep(n, 1);
  report.level = dimension;

  // Neighbours (compressed rows) and contacts per particle, walls included.
  std::vector<std::uint32_t> start(n + 1, 0), nb(2 * in.contacts.size());
  for (const ThinningContact& c : in.contacts) ++start[c.i + 1], ++start[c.j + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const ThinningContact& c : in.contacts) nb[fill[c.i]++] = c.j, nb[fill[c.j]++] = c.i;
  }
  std::vector<std::uint32_t> z0(n), z(n);
  for (std::size_t i = 0; i < n; ++i) z0[i] = z[i] = start[i + 1] - start[i] + in.wall_contacts[i];

  // Size classes of equal count; each may lose its share of the removal, by count.
  const double share = solid > 0.0 ? std::max(0.0, 1.0 - target_measure / solid) : 0.0;
  const std::size_t k = std::clamp<std::size_t>(n / 50, 1, static_cast<std::size_t>(std::max(classes, 1)));
  std::vector<std::uint32_t> by_size(n), cls(n);
  std::iota(by_size.begin(), by_size.end(), 0u);
  std::stable_sort(by_size.begin(), by_size.end(), [&](std::uint32_t a, std::uint32_t b) { return in.size[a] < in.size[b]; });
  std::vector<std::uint64_t> cap(k, 0), taken(k, 0);
  for (std::size_t q = 0; q < n; ++q) cls[by_size[q]] = static_cast<std::uint32_t>(q * k / n);
  for (std::size_t c = 0; c < k; ++c) {
    const std::size_t count = (c + 1) * n / k - c * n / k;
    cap[c] = static_cast<std::uint64_t>(std::floor(share * static_cast<double>(count) + 0.5));
  }

  // One random order for every pass.
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  for (std::size_t q = n; q > 1; --q) std::swap(order[q - 1], order[rng.below(q)]);

  auto done = [&] { return solid <= target_measure; };
  auto removable = [&](std::uint32_t i, int level, bool capped) {
    if (!keep[i] || (capped && taken[cls[i]] >= cap[cls[i]])) return false;
    if (solid - in.measure[i] / 2 < target_measure) return false;  // would end farther from the target
    for (std::uint32_t e = start[i]; e < start[i + 1]; ++e) {
      const std::uint32_t j = nb[e];
      if (keep[j] && z[j] - 1 < std::min<std::uint32_t>(static_cast<std::uint32_t>(level), z0[j])) return false;
    }
    return true;
  };
  auto remove = [&](std::uint32_t i) {
    keep[i] = 0;
    solid -= in.measure[i];
    ++taken[cls[i]];
    ++report.removed;
    for (std::uint32_t e = start[i]; e < start[i + 1]; ++e) --z[nb[e]];
  };
  // Levels D .. 0 with the class caps, then free of them; each pass until nothing more goes.
  for (const bool capped : {true, false}) {
    for (int level = dimension; level >= 0 && !done(); --level) {
      bool any = true;
      while (any && !done()) {
        any = false;
        for (const std::uint32_t i : order) {
          if (done()) break;
          if (removable(i, level, capped)) {
            remove(i);
            report.level = level;
            any = true;
          }
        }
      }
    }
    if (done()) break;
  }
  // Within half a particle: no particle's removal brings the solid closer to the target.
  report.reached = true;
  for (std::size_t i = 0; i < n && report.reached; ++i)
    if (keep[i] && solid - in.measure[i] / 2 >= target_measure) report.reached = false;
  report.measure_after = solid;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i] && z0[i] > 0 && z[i] == 0) ++report.lost_every_contact;
  return keep;
}

}  // namespace fp
