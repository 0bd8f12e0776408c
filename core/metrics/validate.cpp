#include "core/metrics/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/metrics/cell_list.hpp"
#include "core/metrics/contacts.hpp"
#include "core/sampling/ks_test.hpp"

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
  std::snprintf(buf, sizeof buf,
                "validate: %s: %llu particles, %llu pairs checked, tol %.3g; max overlap %.3g r_min, "
                "max outside %.3g r",
                ok ? "OK" : "FAILED", static_cast<unsigned long long>(particles),
                static_cast<unsigned long long>(pairs_checked), tolerance, max_overlap_rel, max_outside_rel);
  std::string s = buf;
  if (!ok) {
    std::snprintf(buf, sizeof buf, "\n  issues: %llu overlaps, %llu outside, %llu radii out of range, %llu non-finite",
                  static_cast<unsigned long long>(overlap_count), static_cast<unsigned long long>(outside_count),
                  static_cast<unsigned long long>(radius_count), static_cast<unsigned long long>(non_finite_count));
    s += buf;
    s += "\n  worst:";
    for (std::size_t k = 0; k < worst.size() && k < 5; ++k) s += (k ? ", " : " ") + describe(worst[k]);
  }
  if (std::isnan(radii_ks_statistic)) {
    s += "\n  radii K-S: no distribution given";
  } else {
    std::snprintf(buf, sizeof buf, "\n  radii K-S: D = %.4g, p = %.3g", radii_ks_statistic, radii_ks_pvalue);
    s += buf;
  }
  return s;
}

template <int D>
ValidationReport validate_packing(const Packing<D>& packing, const Container<D>& container,
                                  const RadiusDistribution* dist_or_null, double overlap_tol_rel) {
  if (!(overlap_tol_rel >= 0.0) || !std::isfinite(overlap_tol_rel))
    throw std::invalid_argument("validate_packing: overlap_tol_rel must be finite and >= 0");
  if (packing.centers.size() != packing.radii.size())
    throw std::invalid_argument("validate_packing: centers and radii differ in size");

  ValidationReport rep;
  rep.tolerance = overlap_tol_rel;
  rep.particles = packing.size();
  WorstIssues worst;
  const double r_unit = smallest_radius(packing);

  // Per ball: finiteness, radius range, container.
  const double lo = dist_or_null ? dist_or_null->r_min() * (1.0 - 1e-12) : 0.0;
  const double hi = dist_or_null ? dist_or_null->r_max() * (1.0 + 1e-12) : std::numeric_limits<double>::infinity();
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
    if (dist_or_null ? (r < lo || r > hi) : !(r > 0.0)) {
      ++rep.radius_count;
      double v = 1.0;
      if (dist_or_null) v = r > hi ? (r - dist_or_null->r_max()) / dist_or_null->r_max()
                                   : (dist_or_null->r_min() - r) / dist_or_null->r_min();
      worst.add({"radius_out_of_range", i, -1, v});
    }
    const double scale = r > 0.0 ? r : (r_unit > 0.0 ? r_unit : 1.0);
    const double out = (container.signed_distance(c) + r) / scale;
    rep.max_outside_rel = std::max(rep.max_outside_rel, out);
    if (out > overlap_tol_rel) {
      ++rep.outside_count;
      worst.add({"outside", i, -1, out});
    }
  }

  // Every pair that can overlap (cell list over the finite, non-negative balls).
  const CellList<D> cells(packing.centers, packing.radii, 0.0);
  cells.for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
    ++rep.pairs_checked;
    const double d = (packing.centers[i] - packing.centers[j]).norm();
    const double overlap = (packing.radii[i] + packing.radii[j] - d) / r_unit;
    rep.max_overlap_rel = std::max(rep.max_overlap_rel, overlap);
    if (overlap > overlap_tol_rel) {
      ++rep.overlap_count;
      worst.add({"overlap", i, j, overlap});
    }
  });

  if (dist_or_null && !finite_radii.empty()) {
    const RadiusDistribution& dist = *dist_or_null;
    rep.radii_ks_statistic = ks_statistic(std::move(finite_radii), [&dist](double r) { return dist.cdf(r); });
    rep.radii_ks_pvalue = ks_pvalue(rep.radii_ks_statistic, rep.particles - rep.non_finite_count);
  }
  rep.worst = std::move(worst).sorted();
  rep.ok = rep.overlap_count + rep.outside_count + rep.radius_count + rep.non_finite_count == 0;
  return rep;
}

template ValidationReport validate_packing<2>(const Packing<2>&, const Container<2>&, const RadiusDistribution*, double);
template ValidationReport validate_packing<3>(const Packing<3>&, const Container<3>&, const RadiusDistribution*, double);

}  // namespace fp
