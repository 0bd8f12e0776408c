#include "cli/pack_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/io/analysis_json.hpp"
#include "core/metrics/radii_fit.hpp"
#include "core/metrics/radius_scale_fit.hpp"
#include "core/sampling/scaled_radius.hpp"
#include "core/sampling/uniform_radius.hpp"

namespace fp {

double overlap_tolerance(const Scene& scene) {
  double epsilon = scene.densify ? scene.densify->overlap : 0.0;
  if (scene.packer.method == "tet_mesh") epsilon = std::max(epsilon, scene.packer.tet_mesh.overlap);
  const double tolerance = scene.packer.contact_tolerance + epsilon;
  return scene.least_squares ? std::max(tolerance, scene.least_squares->tolerance) : tolerance;
}

double radii_alpha_of(const Scene& scene) {
  const bool fitted = scene.packer.method == "tet_mesh" || !scene.regions.empty() ||
                      (scene.densify && scene.densify->radii == VoidRadii::Fit) ||
                      (scene.least_squares && scene.least_squares->radii == LeastSquaresRadii::Range);
  return fitted ? 0.0 : kRadiiAlpha;
}

RadiusDistributionPtr radii_to_check(const Scene& scene, std::span<const double> radii) {
  RadiusDistributionPtr law = scene.radii;
  if (law && scene.stop.scale_sizes) {
    const double s = fit_radius_scale(radii, *law);  // not a number from radii that are not (the test then fails)
    return s > 0 && std::isfinite(s) ? std::make_shared<const ScaledRadius>(law, s) : law;
  }
  if (!law || scene.regions.empty()) return law;
  double lo = law->r_min(), hi = law->r_max();
  for (const RegionSpec& r : scene.regions)
    if (r.radii) lo = std::min(lo, r.radii->r_min()), hi = std::max(hi, r.radii->r_max());
  return lo < hi ? std::make_shared<const UniformRadius>(lo, hi) : law;
}

void add_never_fit_lines(PackCheck& c, const std::vector<double>& never_fit, std::vector<double> placed,
                         const RadiusDistribution* law) {
  if (never_fit.empty()) return;
  const double largest = *std::max_element(never_fit.begin(), never_fit.end());
  char line[200];
  std::snprintf(line, sizeof line, "  no room for   %zu drafts (largest radius %.6g) waited and were left out\n", never_fit.size(), largest);
  c.summary_lines += line;
  const ValidationReport& v = c.validation;
  const bool only_sizes = !v.ok && !v.empty() && v.overlap_count + v.outside_count + v.radius_count + v.non_finite_count == 0;
  if (!only_sizes || !law || v.sizes.size() != 1 || !v.sizes[0].computed()) return;
  const double level = v.test_level();
  placed.insert(placed.end(), never_fit.begin(), never_fit.end());
  const RadiiFit with = radii_fit(std::move(placed), *law);
  if (!with.passes(level)) return;
  c.sizes_short_of_room = true;
  std::snprintf(line, sizeof line,
                "%zu drafted radii (the largest %.6g) found no room once the packing had grown around them; the placed "
                "radii fail the size test (p = %.3g), with them it passes (p = %.3g)",
                never_fit.size(), largest, v.sizes[0].p, with.p);
  c.incomplete.push_back(line);
}

void add_cut_short_reason(PackCheck& c, const StopCriteria& criteria, StopReason stop, std::size_t count,
                          double container_fraction) {
  char line[480];
  const char* cluster = "the particles are a cluster around the seed point, not a packing of the container";
  switch (stop) {
    case StopReason::FrontExhausted: return;
    case StopReason::TimeLimit:
      std::snprintf(line, sizeof line, "the time limit (stop.time: %.6g s) ended the packing before it filled the container, "
                    "at %zu particles (volume fraction %.4f of the container): %s", criteria.time_limit_seconds.value_or(0.0),
                    count, container_fraction, cluster);
      break;
    case StopReason::ParticleCount:
      std::snprintf(line, sizeof line, "stop.particles (%zu) ended the packing before it filled the container (volume "
                    "fraction %.4f of it): %s", static_cast<std::size_t>(criteria.max_particles.value_or(count)),
                    container_fraction, cluster);
      break;
    case StopReason::VolumeFraction:
      std::snprintf(line, sizeof line, "stop.volume_fraction (%.6g) ended the packing before it filled the container: %s; "
                    "`target: {solid_fraction: %.6g}` packs the whole container, then thins it to that fraction",
                    criteria.target_volume_fraction.value_or(0.0), cluster, criteria.target_volume_fraction.value_or(0.0));
      break;
  }
  c.cut_short.push_back(line);
}

PackCheck pack_check_of(const ValidationReport& validation, double volume_fraction) {
  PackCheck c;
  c.validation = validation;
  c.volume_fraction = volume_fraction;
  c.timing_name = "validation";
  return c;
}

PackCheck pack_check_of(const PackingAnalysis& a) {
  PackCheck c;
  c.validation = *a.validation;
  c.volume_fraction = a.vf_container.vf.value;
  c.timing_name = "metrics";
  c.step_timings = a.timings;
  const ContactStats& cs = a.coordination;
  const double n = static_cast<double>(a.particles);
  c.metrics = {{"volume_fraction_core", a.vf_core.vf.value},
               {"volume_fraction_wall_layer", a.wall_profile.layer.value},
               {"volume_fraction_reference_sphere", a.vf_reference},
               {"volume_fraction_cells_mean", a.vf_cells.mean},
               {"volume_fraction_cells_std", a.vf_cells.std_dev},
               {"volume_fraction_cells_worst", a.vf_cells.worst},
               {"reference_sphere_radius", a.reference_radius},
               {"mean_coordination_with_walls", cs.mean_coordination_with_walls},
               {"rattler_fraction", n > 0 ? static_cast<double>(cs.rattlers) / n : 0.0},
               {"max_overlap_over_rmin", a.max_overlap_rel},
               {"radii_statistic", c.validation.radii().statistic},
               {"radii_pvalue", c.validation.radii().p}};
  const char* axis_names[] = {"x", "y", "z"};
  for (std::size_t k = 0; k < a.reference_center.size() && k < 3; ++k)
    c.metrics.emplace_back(std::string("reference_sphere_center_") + axis_names[k], a.reference_center[k]);
  if (a.orientation) {
    c.metrics.emplace_back("orientation_order", a.orientation_order);
    c.metrics.emplace_back("orientation_radial_order", a.radial_order);
    c.metrics.emplace_back("orientation_radial_axes_order", a.radial_axes_order);
  }
  // The smallest p of the orientation tests, and the order about the law's axis, per template.
  for (std::size_t t = 0; t < c.validation.orientations.size(); ++t) {
    const OrientationFit& f = c.validation.orientations[t];
    if (!f.computed()) continue;
    const std::string suffix = c.validation.orientations.size() > 1 ? "_" + std::to_string(t) : "";
    double p = 1.0;
    for (const OrientationFit::Test& test : f.tests) p = std::min(p, test.p);
    c.metrics.emplace_back("orientation_pvalue" + suffix, p);
    if (std::isfinite(f.order)) c.metrics.emplace_back("orientation_axis_order" + suffix, f.order);
  }
  c.counters = {{"rattlers", cs.rattlers}};
  c.info = {{"radii_test", c.validation.radii().test}};
  c.analysis_json = analysis_json(a);
  std::string table = "  " + a.summary();
  for (std::size_t at = table.find('\n'); at != std::string::npos; at = table.find('\n', at + 3)) table.insert(at + 1, "  ");
  c.summary_lines = table + "\n";
  return c;
}

}  // namespace fp
