#include "core/metrics/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/metrics/containment_check.hpp"
#include "core/metrics/validate_particles.hpp"

namespace fp {

std::string describe(const ValidationIssue& w) {
  char buf[160];
  if (w.j >= 0)
    std::snprintf(buf, sizeof buf, "%s %lld-%lld: %.3g", w.kind.c_str(), static_cast<long long>(w.i),
                  static_cast<long long>(w.j), w.value_rel);
  else
    std::snprintf(buf, sizeof buf, "%s %lld: %.3g", w.kind.c_str(), static_cast<long long>(w.i), w.value_rel);
  return buf;
}

const RadiiFit& ValidationReport::radii() const {
  static const RadiiFit none;
  return sizes.size() == 1 ? sizes[0] : none;
}

int ValidationReport::tests() const {
  int n = mix ? 1 : 0;
  for (const RadiiFit& f : sizes) n += f.computed() ? 1 : 0;
  return n;
}

bool ValidationReport::sizes_ok() const {
  const double level = test_level();
  for (const RadiiFit& f : sizes)
    if (!f.passes(level)) return false;
  return !mix || !(mix->p < level);
}

int ValidationReport::orientation_tests() const {
  int n = 0;
  for (const OrientationFit& f : orientations) n += static_cast<int>(f.tests.size());
  return n;
}

bool ValidationReport::orientations_ok() const {
  const double level = orientation_level();
  for (const OrientationFit& f : orientations)
    if (!f.passes(level)) return false;
  return true;
}

std::string ValidationReport::summary() const {
  char buf[512];
  if (empty()) return "validate: FAILED: the packing holds no particles";
  std::snprintf(buf, sizeof buf,
                "validate: %s: %llu particles, %llu pairs checked, tol %.3g; max overlap %.3g of the smaller %s, "
                "max outside %.3g of the %s",
                ok ? "OK" : "FAILED", static_cast<unsigned long long>(particles),
                static_cast<unsigned long long>(pairs_checked), tolerance, max_overlap_rel, unit_name.c_str(),
                max_outside_rel, unit_name.c_str());
  std::string s = buf;
  std::snprintf(buf, sizeof buf, "\n  contacts: %llu (coordination %.4g), %llu with the walls; largest contact gap %.3g",
                static_cast<unsigned long long>(contacts), mean_coordination(), static_cast<unsigned long long>(wall_contacts),
                max_contact_gap_rel);
  s += buf;
  if (!worst.empty()) {
    std::snprintf(buf, sizeof buf, "\n  issues: %llu overlaps, %llu outside, %llu sizes out of range, %llu non-finite",
                  static_cast<unsigned long long>(overlap_count), static_cast<unsigned long long>(outside_count),
                  static_cast<unsigned long long>(radius_count), static_cast<unsigned long long>(non_finite_count));
    s += buf;
    s += "\n  worst:";
    for (std::size_t k = 0; k < worst.size() && k < 5; ++k) s += (k ? ", " : " ") + describe(worst[k]);
  }
  if (tests() == 0) return s + "\n  size tests: no size law given";
  const bool one = sizes.size() == 1 && !mix;
  for (std::size_t t = 0; t < sizes.size(); ++t)
    if (sizes[t].computed()) s += (one ? "\n  sizes " : "\n  sizes of template " + std::to_string(t) + ": ") + sizes[t].describe();
  if (mix) {
    std::snprintf(buf, sizeof buf, "\n  mix of templates: chi-square X2 = %.4g (%d dof), p = %.3g", mix->statistic, mix->dof, mix->p);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "\n  each size test fails below %.3g%s", test_level(), sizes_ok() ? "" : ": FAILED");
  s += buf;
  if (orientation_tests() == 0) return s;
  const bool single = orientations.size() == 1;
  for (std::size_t t = 0; t < orientations.size(); ++t)
    if (orientations[t].computed())
      s += (single ? "\n  orientations (" : "\n  orientations of template " + std::to_string(t) + " (") + orientations[t].law + "): " +
           orientations[t].describe();
  std::snprintf(buf, sizeof buf, "\n  each orientation test fails below %.3g%s", orientation_level(), orientations_ok() ? "" : ": FAILED");
  return s + buf;
}

std::string ValidationReport::one_line() const {
  if (empty()) return "FAILED: the packing holds no particles";
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s (every pair: %llu checked, %llu overlapping; every particle against the container: %llu outside; "
                "max overlap %.3g and max outside %.3g of the %s, tolerance %.3g",
                ok ? "ok" : "FAILED", static_cast<unsigned long long>(pairs_checked),
                static_cast<unsigned long long>(overlap_count), static_cast<unsigned long long>(outside_count),
                max_overlap_rel, max_outside_rel, unit_name.c_str(), tolerance);
  std::string s = buf;
  if (radius_count + non_finite_count)
    s += "; " + std::to_string(radius_count) + " sizes out of range, " + std::to_string(non_finite_count) + " non-finite";
  if (tests() == 0) return s + "; no size law to test)";
  std::snprintf(buf, sizeof buf, "; %d size test%s at %.3g: %s", tests(), tests() > 1 ? "s" : "", test_level(),
                sizes_ok() ? "passed" : "FAILED");
  s += buf;
  if (orientation_tests() > 0) {
    std::snprintf(buf, sizeof buf, "; %d orientation test%s at %.3g: %s", orientation_tests(), orientation_tests() > 1 ? "s" : "",
                  orientation_level(), orientations_ok() ? "passed" : "FAILED");
    s += buf;
  }
  return s + ")";
}

namespace {

// Balls as validate_particles sees them: the radius is the length unit and the size; distances
// to the container through ContainmentCheck's own geometry.
template <int D>
class SphereParticles {
 public:
  static constexpr const char* kSizeIssue = "radius_out_of_range";
  static constexpr const char* kUnitName = "radius";
  static constexpr bool kNormalsAreCentreLines = true;

  SphereParticles(const Packing<D>& packing, const Container<D>& container) : p_(packing), containment_(container) {}
  std::size_t size() const { return p_.size(); }
  const std::vector<Vec<D>>& centers() const { return p_.centers; }
  const std::vector<double>& reach_radii() const { return p_.radii; }
  bool finite(std::size_t i) const { return std::isfinite(p_.radii[i]) && p_.centers[i].allFinite(); }
  double unit(std::size_t i) const { return p_.radii[i]; }
  double overlap(std::size_t i, std::size_t j, Vec<D>* normal) const {
    const Vec<D> d = p_.centers[j] - p_.centers[i];
    const double len = d.norm();
    if (normal) *normal = len > 0.0 ? Vec<D>(d / len) : Vec<D>::Zero();
    return p_.radii[i] + p_.radii[j] - len;
  }
  // The search reaches 2 units: a ball deeper than its radius must read as inside (< 0), not as
  // touching (a mesh's search returns -reach beyond its reach).
  double protrusion(std::size_t i, double unit) const {
    return containment_.signed_distance(p_.centers[i], 2 * unit) + p_.radii[i];
  }
  int template_of(std::size_t) const { return 0; }
  double size_of(std::size_t i) const { return p_.radii[i]; }

 private:
  const Packing<D>& p_;
  const ContainmentCheck<D> containment_;
};

}  // namespace

template <int D>
ValidationReport validate_packing(const Packing<D>& packing, const Container<D>& container,
                                  const RadiusDistribution* dist_or_null, double overlap_tol_rel, double radii_alpha,
                                  ContactNetwork<D>* network, int threads) {
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

  std::vector<RequestedTemplate> requested;
  if (dist_or_null) requested.push_back({dist_or_null, 1.0});
  return validate_particles<D>(SphereParticles<D>(packing, container), overlap_tol_rel, requested, radii_alpha, network,
                              threads);
}

template ValidationReport validate_packing<2>(const Packing<2>&, const Container<2>&, const RadiusDistribution*, double,
                                             double, ContactNetwork<2>*, int);
template ValidationReport validate_packing<3>(const Packing<3>&, const Container<3>&, const RadiusDistribution*, double,
                                             double, ContactNetwork<3>*, int);

}  // namespace fp
