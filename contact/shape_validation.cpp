#include "contact/shape_validation.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "contact/narrow_phase.hpp"
#include "contact/shape_containment.hpp"
#include "core/geometry/neighbour_grid.hpp"

namespace fp {

std::vector<RequestedTemplate> requested_templates(const Scene& scene) {
  std::vector<RequestedTemplate> requested;  // template ids follow the scene's list
  for (const ParticleTemplateSpec& t : scene.particle_templates) requested.push_back({t.size.get(), t.fraction});
  return requested;
}

bool ShapeValidation::sizes_ok() const {
  if (sizes_out_of_range) return false;
  const double level = tests > 0 ? sizes_alpha / tests : sizes_alpha;
  for (const RadiiFit& f : sizes)
    if (!f.passes(level)) return false;
  return !mix_tested || !(mix.p < level);
}

std::string ShapeValidation::summary() const {
  if (empty) return "FAILED: the packing holds no particles";
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s: %llu pairs checked, %llu overlapping (max overlap %.3g of the smaller circumscribed radius, pair %d-%d), "
                "%llu outside the container (max %.3g r), tolerance %.3g",
                ok ? "ok" : "FAILED", static_cast<unsigned long long>(pairs_checked),
                static_cast<unsigned long long>(overlaps), max_overlap_rel, worst_a, worst_b,
                static_cast<unsigned long long>(outside), max_outside_rel, tolerance);
  std::string s = buf;
  for (std::size_t k = 0; k < sizes.size(); ++k)
    if (sizes[k].computed()) s += "; sizes of template " + std::to_string(k) + ": " + sizes[k].describe();
  if (sizes_out_of_range) s += "; " + std::to_string(sizes_out_of_range) + " sizes out of range";
  if (mix_tested) {
    std::snprintf(buf, sizeof buf, "; mix of templates: chi-square X2 = %.4g (%d dof), p = %.3g", mix.statistic, mix.dof, mix.p);
    s += buf;
  }
  if (tests > 0) {
    std::snprintf(buf, sizeof buf, " (each test fails below %.3g)%s", sizes_alpha / tests, sizes_ok() ? "" : ": FAILED");
    s += buf;
  }
  return s;
}

template <int D>
ShapeValidation validate_shapes(const ShapePacking<D>& packing, const Container<D>& container, double tolerance,
                                const std::vector<RequestedTemplate>& requested, double sizes_alpha) {
  ShapeValidation v;
  v.tolerance = tolerance;
  v.sizes_alpha = sizes_alpha;
  const auto& P = packing.particles;
  if (P.empty()) {
    v.empty = true;
    v.ok = false;
    return v;
  }
  double r_min = P[0].bounding_radius(), r_max = r_min;
  Aabb<D> box;
  for (const auto& p : P) {
    r_min = std::min(r_min, p.bounding_radius());
    r_max = std::max(r_max, p.bounding_radius());
    box.extend(p.pose.position);
  }
  box.lo.array() -= r_max;
  box.hi.array() += r_max;
  NeighbourGrid<D> grid(box, r_min, r_max);
  NarrowPhase<D> np;
  const ShapeContainment<D> containment(container, np);
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Particle<D>& p = P[i];
    const double r = p.bounding_radius();
    grid.for_each_within(p.pose.position, r, [&](int j, const Vec<D>&, double rj, double) {
      ++v.pairs_checked;
      const double g = np.gap(P[static_cast<std::size_t>(j)], p).value;
      const double scale = std::min(r, rj);
      if (std::abs(g) <= tolerance * scale) {
        ++v.contacts;
        v.max_contact_gap_rel = std::max(v.max_contact_gap_rel, std::abs(g) / scale);
      }
      if (-g / scale > v.max_overlap_rel) {
        v.max_overlap_rel = -g / scale;
        v.worst_a = j;
        v.worst_b = static_cast<int>(i);
      }
      if (g < -tolerance * scale) ++v.overlaps;
    });
    grid.insert(static_cast<int>(i), p.pose.position, r);
    const double beyond = containment.protrusion(p);
    if (beyond / r > v.max_outside_rel) v.max_outside_rel = beyond / r;
    if (beyond > tolerance * r) ++v.outside;
    if (std::abs(beyond) <= tolerance * r) ++v.wall_contacts;
  }
  v.mean_coordination = 2.0 * static_cast<double>(v.contacts) / static_cast<double>(P.size());

  // Sizes per template and the mix of templates, as the radii of a sphere packing.
  if (!requested.empty()) {
    std::vector<std::vector<double>> sizes(requested.size());
    std::vector<std::uint64_t> counts(requested.size(), 0);
    for (const Particle<D>& p : P) {
      const auto t = static_cast<std::size_t>(p.template_id);
      if (t >= requested.size()) throw std::invalid_argument("shape validation: a particle names a template that was not requested");
      ++counts[t];
      if (!requested[t].size) continue;
      if (radius_excess(*requested[t].size, p.size) > kRadiusSlack) ++v.sizes_out_of_range;
      sizes[t].push_back(p.size);
    }
    v.sizes.resize(requested.size());
    for (std::size_t t = 0; t < requested.size(); ++t)
      if (requested[t].size && !sizes[t].empty()) {
        v.sizes[t] = radii_fit(std::move(sizes[t]), *requested[t].size);
        ++v.tests;
      }
    if (requested.size() > 1) {
      double total = 0;
      for (const RequestedTemplate& r : requested) total += r.fraction;
      std::vector<double> share;
      for (const RequestedTemplate& r : requested) share.push_back(r.fraction / total);
      v.mix = chi_square_counts(counts, share);
      v.mix_tested = true;
      ++v.tests;
    }
  }
  v.ok = v.overlaps == 0 && v.outside == 0 && v.sizes_ok();
  return v;
}

template ShapeValidation validate_shapes<2>(const ShapePacking<2>&, const Container<2>&, double,
                                           const std::vector<RequestedTemplate>&, double);
template ShapeValidation validate_shapes<3>(const ShapePacking<3>&, const Container<3>&, double,
                                           const std::vector<RequestedTemplate>&, double);

}  // namespace fp
