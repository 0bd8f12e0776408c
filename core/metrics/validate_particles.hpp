#pragma once
// The one verdict of every packing, spheres and shapes alike: validate_packing (spheres,
// validate.hpp) and validate_shapes (contact/shape_validation.hpp) are this function with their
// own geometry. What is checked, and how it is counted, exists once:
//  * every particle: finite, its size within its law's range, inside the container up to
//    tol * its length unit (the radius; a shape's circumscribed radius);
//  * every pair whose reach boxes meet (CellList: this file's own broad phase, never the
//    packer's grid): an overlap beyond tol * the smaller length unit; gap <= that is a contact
//    (contacts.hpp's rule: overlapping pairs count too), and so is a particle whose gap to the
//    boundary is <= tol * its unit; on request the contacts are listed (contact_network.hpp);
//  * the sizes of each template against its law (radii_fit.hpp) and, with two templates or
//    more, the counts per template against the requested shares (chi-square); the tests share
//    the level alpha (Bonferroni), so a correct packing fails with probability below alpha;
//  * an empty packing fails.
//
// `Particles` supplies the geometry (the public members of SphereParticles in validate.cpp are
// the whole interface):
//   size(), centers(), reach_radii()   the balls the broad phase indexes (non-finite ones left out)
//   finite(i)                          position, size and length unit finite
//   unit(i)                            the length unit (may be <= 0 for a broken sphere: reported)
//   overlap(i, j, normal*)             penetration depth, > 0 when the pair overlaps (absolute); with
//                                      a normal to fill, the unit contact normal from i towards j
//   protrusion(i, u)                   how far i reaches beyond the boundary, <= 0 inside (absolute;
//                                      u: its length unit, as the engine scales it)
//   template_of(i), size_of(i)         the template id and the size drawn from its law
//   kSizeIssue, kUnitName              the kind of a size out of range ("radius_out_of_range"),
//                                      the name of the length unit ("radius")
//   kNormalsAreCentreLines             true for spheres: the network then lists no normals
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/metrics/cell_list.hpp"
#include "core/metrics/contact_network.hpp"
#include "core/metrics/validate.hpp"
#include "core/sampling/chi_square_test.hpp"
#include "core/system/parallel_parts.hpp"

namespace fp {
namespace validation_detail {

inline constexpr std::size_t kWorstKept = 20;

// Strict "a is worse than b", total and deterministic: larger value first, then kind, ids.
inline bool worse(const ValidationIssue& a, const ValidationIssue& b) {
  if (a.value_rel != b.value_rel) return a.value_rel > b.value_rel;
  if (a.kind != b.kind) return a.kind < b.kind;
  if (a.i != b.i) return a.i < b.i;
  return a.j < b.j;
}

// Keeps the kWorstKept worst issues in a heap whose front is the mildest kept one.
class WorstIssues {
 public:
  void add(ValidationIssue issue) {
    if (heap_.size() == kWorstKept && !worse(issue, heap_.front())) return;
    heap_.push_back(std::move(issue));
    std::push_heap(heap_.begin(), heap_.end(), worse);
    if (heap_.size() > kWorstKept) {
      std::pop_heap(heap_.begin(), heap_.end(), worse);
      heap_.pop_back();
    }
  }
  std::vector<ValidationIssue> sorted() && {
    std::sort(heap_.begin(), heap_.end(), worse);
    return std::move(heap_);
  }

 private:
  std::vector<ValidationIssue> heap_;
};

// What one part of the particles or of the pairs found; parts merge in any order to the same
// report (sums, maxima, the worst issues by a total order, lists concatenated in part order or
// sorted).
template <int D>
struct Tally {
  ValidationReport rep;
  WorstIssues worst;
  std::vector<std::vector<double>> sizes;  // per template slot, in particle order
  std::vector<std::uint64_t> counts;
  ContactNetwork<D> network;

  void merge(Tally&& t) {
    rep.pairs_checked += t.rep.pairs_checked;
    rep.max_overlap_rel = std::max(rep.max_overlap_rel, t.rep.max_overlap_rel);
    rep.max_outside_rel = std::max(rep.max_outside_rel, t.rep.max_outside_rel);
    rep.overlap_count += t.rep.overlap_count;
    rep.outside_count += t.rep.outside_count;
    rep.radius_count += t.rep.radius_count;
    rep.non_finite_count += t.rep.non_finite_count;
    rep.contacts += t.rep.contacts;
    rep.wall_contacts += t.rep.wall_contacts;
    rep.max_contact_gap_rel = std::max(rep.max_contact_gap_rel, t.rep.max_contact_gap_rel);
    for (ValidationIssue& issue : std::move(t.worst).sorted()) worst.add(std::move(issue));
    sizes.resize(std::max(sizes.size(), t.sizes.size()));
    for (std::size_t k = 0; k < t.sizes.size(); ++k) sizes[k].insert(sizes[k].end(), t.sizes[k].begin(), t.sizes[k].end());
    counts.resize(std::max(counts.size(), t.counts.size()), 0);
    for (std::size_t k = 0; k < t.counts.size(); ++k) counts[k] += t.counts[k];
    network.pairs.insert(network.pairs.end(), t.network.pairs.begin(), t.network.pairs.end());
    network.normals.insert(network.normals.end(), t.network.normals.begin(), t.network.normals.end());
    network.walls.insert(network.walls.end(), t.network.walls.begin(), t.network.walls.end());
    t.network = ContactNetwork<D>();  // freed as they go: a million spheres' network is ~50 MB
    t.sizes = {};
  }
};

// Parts per thread: more parts than threads evens out cells of unequal work.
inline constexpr std::size_t kPartsPerThread = 8;

}  // namespace validation_detail

/// The verdict of `particles` with the packer's allowance `tolerance` (relative to the length
/// unit) against what was `requested` per template id (empty: only a size <= 0 is an issue).
/// With `network`, the contacts are also listed there. `threads` share the particles and the
/// pairs (Particles' queries must then be safe to call at once); the report and the network are
/// the same for every thread count. Throws std::invalid_argument for a tolerance or alpha out of
/// range, and for a template id the request does not have.
template <int D, class Particles>
ValidationReport validate_particles(const Particles& particles, double tolerance,
                                    const std::vector<RequestedTemplate>& requested, double alpha,
                                    ContactNetwork<D>* network = nullptr, int threads = 1) {
  using validation_detail::Tally;
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("validation: the tolerance must be finite and >= 0");
  if (!(alpha >= 0.0 && alpha <= 1.0)) throw std::invalid_argument("validation: the test level must be in [0, 1]");

  const std::size_t n = particles.size();
  // The length unit of a particle or pair; the smallest positive one for a broken (<= 0) unit.
  double unit_min = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    if (!particles.finite(i)) continue;
    if (particles.unit(i) > 0.0) unit_min = std::min(unit_min, particles.unit(i));
    if (const auto t = static_cast<std::size_t>(particles.template_of(i)); !requested.empty() && t >= requested.size())
      throw std::invalid_argument("validation: particle " + std::to_string(i) + " names template " + std::to_string(t) +
                                  " but " + std::to_string(requested.size()) + " were requested");
  }
  if (!std::isfinite(unit_min)) unit_min = 0.0;
  auto scale = [unit_min](double u) { return u > 0.0 ? u : (unit_min > 0.0 ? unit_min : 1.0); };
  const std::size_t slots = std::max<std::size_t>(requested.size(), 1);
  const std::size_t parts = static_cast<std::size_t>(std::max(threads, 1)) * validation_detail::kPartsPerThread;
  std::vector<Tally<D>> tallies(parts);

  // Per particle: finiteness, size range, container.
  for_each_part(parts, threads, [&](std::size_t part) {
    Tally<D>& tally = tallies[part];
    ValidationReport& rep = tally.rep;
    tally.sizes.resize(slots);
    tally.counts.assign(slots, 0);
    const auto [first, last] = part_range(n, part, parts);
    for (std::size_t k = first; k < last; ++k) {
      const auto i = static_cast<std::int64_t>(k);
      if (!particles.finite(k)) {
        ++rep.non_finite_count;
        tally.worst.add({"non_finite", i, -1, std::numeric_limits<double>::infinity()});
        continue;
      }
      const auto t = static_cast<std::size_t>(particles.template_of(k));
      const RadiusDistribution* law = requested.empty() ? nullptr : requested[t].size;
      const double size = particles.size_of(k);
      const double excess = law ? radius_excess(*law, size) : (size > 0.0 ? 0.0 : 1.0);
      if (law ? excess > kRadiusSlack : excess > 0.0) {
        ++rep.radius_count;
        tally.worst.add({Particles::kSizeIssue, i, -1, excess});
      }
      const std::size_t slot = requested.empty() ? 0 : t;
      tally.sizes[slot].push_back(size);
      ++tally.counts[slot];
      const double u = scale(particles.unit(k));
      const double out = particles.protrusion(k, u) / u;
      rep.max_outside_rel = std::max(rep.max_outside_rel, out);
      if (out > tolerance) {
        ++rep.outside_count;
        tally.worst.add({"outside", i, -1, out});
      }
      if (out >= -tolerance) {
        ++rep.wall_contacts;
        if (network) tally.network.walls.push_back({static_cast<std::uint32_t>(k), -out * u});
      }
    }
  });

  // Every pair that can overlap or touch: the reach boxes grown by the tolerance.
  const CellList<D> cells(particles.centers(), particles.reach_radii(), tolerance);
  std::vector<Tally<D>> pair_tallies(parts);
  const bool list_normals = network && !Particles::kNormalsAreCentreLines;
  for_each_part(parts, threads, [&](std::size_t part) {
    Tally<D>& tally = pair_tallies[part];
    ValidationReport& rep = tally.rep;
    cells.for_each_candidate_pair(part, parts, [&](std::uint32_t i, std::uint32_t j) {
      ++rep.pairs_checked;
      const double u = scale(std::min(particles.unit(i), particles.unit(j)));
      Vec<D> normal;
      const double overlap = particles.overlap(i, j, list_normals ? &normal : nullptr) / u;
      rep.max_overlap_rel = std::max(rep.max_overlap_rel, overlap);
      if (overlap > tolerance) {
        ++rep.overlap_count;
        tally.worst.add({"overlap", i, j, overlap});
      }
      if (overlap >= -tolerance) {
        ++rep.contacts;
        rep.max_contact_gap_rel = std::max(rep.max_contact_gap_rel, std::abs(overlap));
        if (network) {
          tally.network.pairs.push_back({i, j, -overlap * u});
          if (list_normals) tally.network.normals.push_back(normal);
        }
      }
    });
  });
  Tally<D> all;
  for (Tally<D>& t : tallies) all.merge(std::move(t));
  for (Tally<D>& t : pair_tallies) all.merge(std::move(t));
  ValidationReport rep = std::move(all.rep);
  rep.tolerance = tolerance;
  rep.unit_name = Particles::kUnitName;
  rep.radii_alpha = alpha;
  rep.particles = n;
  std::vector<std::vector<double>>& sizes = all.sizes;
  const std::vector<std::uint64_t>& counts = all.counts;
  if (network) {
    network->pairs = std::move(all.network.pairs);
    network->normals = std::move(all.network.normals);
    network->walls = std::move(all.network.walls);
    sort_by_pair(*network, n);
  }

  // Sizes per template and the mix of templates.
  rep.sizes.resize(requested.size());
  for (std::size_t t = 0; t < requested.size(); ++t)
    if (requested[t].size && !sizes[t].empty()) rep.sizes[t] = radii_fit(std::move(sizes[t]), *requested[t].size);
  if (requested.size() > 1 && n > rep.non_finite_count) {
    double total = 0;
    for (const RequestedTemplate& r : requested) total += r.fraction;
    std::vector<double> share;
    for (const RequestedTemplate& r : requested) share.push_back(r.fraction / total);
    rep.mix = chi_square_counts(counts, share);
  }
  rep.worst = std::move(all.worst).sorted();
  rep.ok = !rep.empty() && rep.overlap_count + rep.outside_count + rep.radius_count + rep.non_finite_count == 0 &&
           rep.sizes_ok();
  return rep;
}

}  // namespace fp
