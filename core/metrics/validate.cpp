#include "core/metrics/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/metrics/cell_list.hpp"
#include "core/metrics/containment_check.hpp"
#include "core/metrics/contacts.hpp"

namespace fp {
namespace {

constexpr std::size_t kWorstKept = 20;

// Strict "a is worse than b", total and deterministic: larger value first, then kind, ids.
bool worse(const ValidationIssue& a, const ValidationIssue& b) {
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

}  // namespace

std::string describe(const ValidationIssue& w) {
  char buf[160];
  if (w.j >= 0)
    std::snprintf(buf, sizeof buf, "%s %lld-%lld: %.3g", w.kind.c_str(), static_cast<long long>(w.i),
                  static_cast<long long>(w.j), w.value_rel);
  else
    std::snprintf(buf, sizeof buf, "%s %lld: %.3g", w.kind.c_str(), static_cast<long long>(w.i), w.value_rel);
  return buf;
}

std::string ValidationReport::summary() const {
  char buf[512];
  if (empty()) return "validate: FAILED: the packing holds no particles";
  std::snprintf(buf, sizeof buf,
                "validate: %s: %llu particles, %llu pairs checked, tol %.3g; max overlap %.3g of the smaller radius, "
                "max outside %.3g r",
                ok ? "OK" : "FAILED", static_cast<unsigned long long>(particles),
                static_cast<unsigned long long>(pairs_checked), tolerance, max_overlap_rel, max_outside_rel);
  std::string s = buf;
  if (!worst.empty()) {
    std::snprintf(buf, sizeof buf, "\n  issues: %llu overlaps, %llu outside, %llu radii out of range, %llu non-finite",
                  static_cast<unsigned long long>(overlap_count), static_cast<unsigned long long>(outside_count),
                  static_cast<unsigned long long>(radius_count), static_cast<unsigned long long>(non_finite_count));
    s += buf;
    s += "\n  worst:";
    for (std::size_t k = 0; k < worst.size() && k < 5; ++k) s += (k ? ", " : " ") + describe(worst[k]);
  }
  if (!radii.computed()) {
    s += "\n  radii test: no distribution given";
  } else {
    std::snprintf(buf, sizeof buf, "\n  radii %s (fails below %.3g)%s", radii.describe().c_str(), radii_alpha,
                  radii_ok() ? "" : ": FAILED");
    s += buf;
  }
  return s;
}

template <int D>
ValidationReport validate_packing(const Packing<D>& packing, const Container<D>& container,
                                  const RadiusDistribution* dist_or_null, double overlap_tol_rel, double radii_alpha) {
  if (!(overlap_tol_rel >= 0.0) || !std::isfinite(overlap_tol_rel))
    throw std::invalid_argument("validate_packing: overlap_tol_rel must be finite and >= 0");
  if (!(radii_alpha >= 0.0 && radii_alpha <= 1.0))
    throw std::invalid_argument("validate_packing: radii_alpha must be in [0, 1]");
  if (packing.centers.size() != packing.radii.size())
    throw std::invalid_argument("validate_packing: centers and radii differ in size");
  // Both must be in the same local frame (core/geometry/local_frame.hpp): the check works on
  // coordinates relative to the container, never on absolute ones.
  if (packing.origin != container.origin())
    throw std::invalid_argument("validate_packing: the packing and the container are in different frames");

  ValidationReport rep;
  rep.tolerance = overlap_tol_rel;
  rep.radii_alpha = radii_alpha;
  rep.particles = packing.size();
  WorstIssues worst;
  const double r_unit = smallest_radius(packing);
  // The length unit of a ball or pair: its (smaller) radius; r_min for a zero radius (already an issue).
  auto scale = [r_unit](double r) { return r > 0.0 ? r : (r_unit > 0.0 ? r_unit : 1.0); };

  // Per ball: finiteness, radius range, container (through the check's own geometry, not the
  // container's code).
  const ContainmentCheck<D> containment(container);
  std::vector<double> finite_radii;
  finite_radii.reserve(packing.size());
  for (std::size_t n = 0; n < packing.size(); ++n) {
    const auto i = static_cast<std::int64_t>(n);
    const double r = packing.radii[n];
    const Vec<D>& c = packing.centers[n];
    if (!std::isfinite(r) || !c.allFinite()) {
      ++rep.non_finite_count;
      worst.add({"non_finite", i, -1, std::numeric_limits<double>::infinity()});
      continue;
    }
    finite_radii.push_back(r);
    const double excess = dist_or_null ? radius_excess(*dist_or_null, r) : (r > 0.0 ? 0.0 : 1.0);
    if (dist_or_null ? excess > kRadiusSlack : excess > 0.0) {
      ++rep.radius_count;
      worst.add({"radius_out_of_range", i, -1, excess});
    }
    const double out = (containment.signed_distance(c, scale(r)) + r) / scale(r);
    rep.max_outside_rel = std::max(rep.max_outside_rel, out);
    if (out > overlap_tol_rel) {
      ++rep.outside_count;
      worst.add({"outside", i, -1, out});
    }
  }

  // Every pair that can overlap (cell list over the finite, non-negative balls), with the
  // packer's allowance: tol * min(ri, rj).
  const CellList<D> cells(packing.centers, packing.radii, 0.0);
  cells.for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
    ++rep.pairs_checked;
    const double d = (packing.centers[i] - packing.centers[j]).norm();
    const double overlap = (packing.radii[i] + packing.radii[j] - d) / scale(std::min(packing.radii[i], packing.radii[j]));
    rep.max_overlap_rel = std::max(rep.max_overlap_rel, overlap);
    if (overlap > overlap_tol_rel) {
      ++rep.overlap_count;
      worst.add({"overlap", i, j, overlap});
    }
  });

  if (dist_or_null) rep.radii = radii_fit(std::move(finite_radii), *dist_or_null);
  rep.worst = std::move(worst).sorted();
  rep.ok = !rep.empty() && rep.overlap_count + rep.outside_count + rep.radius_count + rep.non_finite_count == 0 &&
           rep.radii_ok();
  return rep;
}

template ValidationReport validate_packing<2>(const Packing<2>&, const Container<2>&, const RadiusDistribution*, double,
                                             double);
template ValidationReport validate_packing<3>(const Packing<3>&, const Container<3>&, const RadiusDistribution*, double,
                                             double);

}  // namespace fp
