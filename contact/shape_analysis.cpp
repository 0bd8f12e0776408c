#include "contact/shape_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "contact/shape_validation.hpp"
#include "core/geometry/ball_container.hpp"
#include "core/metrics/compensated_sum.hpp"
#include "core/metrics/contact_network.hpp"
#include "core/metrics/timed_step.hpp"

namespace fp {

template <int D>
PackingAnalysis analyze_shape_packing(const ShapePacking<D>& packing, const Container<D>& container,
                                      const std::vector<RequestedTemplate>& requested,
                                      const std::vector<std::string>& families, const AnalysisOptions& options) {
  if (container.origin() != packing.origin)
    throw std::invalid_argument("analyze_shape_packing: the packing and the container are in different frames");
  const auto& ps = packing.particles;
  const std::size_t n = ps.size();
  PackingAnalysis a;
  a.dimension = D;
  a.particles = n;
  a.contact_tolerance = options.contact_tolerance;
  a.radius_name = "r_eq";
  a.container = container.describe();
  a.container_measure = container.measure();
  for (std::size_t t = 0; t < families.size(); ++t) a.templates.emplace_back(families[t], 0);

  // The particles as balls of their equivalent radius (centres, sizes), and as bodies (their
  // bounding balls, exact measures, membership) for the volume fractions.
  Packing<D> balls;
  balls.origin = packing.origin;
  RegionBodies<D> bodies;
  double bounding_max = 0.0, sum = 0.0;
  std::size_t counted = 0;
  a.r_min = std::numeric_limits<double>::infinity();
  std::vector<Vec<D>> axes;
  for (const Particle<D>& p : ps) {
    const double measure = p.shape->measure();
    const double r = equivalent_radius<D>(measure);
    balls.add(p.pose.position, r);
    bodies.centres.push_back(p.pose.position);
    bodies.bounding_radii.push_back(p.bounding_radius());
    bodies.measures.push_back(measure);
    axes.push_back(p.pose.rotation.col(0));
    if (static_cast<std::size_t>(p.template_id) < a.templates.size()) ++a.templates[static_cast<std::size_t>(p.template_id)].second;
    if (!(r > 0.0) || !std::isfinite(r) || !p.pose.position.allFinite()) continue;
    a.r_min = std::min(a.r_min, r);
    a.r_max = std::max(a.r_max, r);
    bounding_max = std::max(bounding_max, p.bounding_radius());
    sum += r;
    ++counted;
  }
  if (counted == 0) {
    a.r_min = 0.0;
    return a;
  }
  a.r_mean = sum / static_cast<double>(counted);
  bodies.contains = [&ps](std::size_t i, const Vec<D>& x) { return ps[i].contains(x); };
  auto& t = a.timings;

  ContactNetwork<D> net;
  timed_step(t, "validate", [&] {
    a.validation = validate_shapes<D>(packing, container, options.contact_tolerance, requested, kRadiiAlpha, &net);
  });
  timed_step(t, "contact network", [&] {
    a.coordination = contact_stats_of(D, n, net.pairs, &net.walls, a.r_min, options.contact_tolerance);
    a.max_overlap_rel = a.coordination.max_overlap_rel;
    for (const PairContact& c : net.pairs) a.max_contact_gap_rel = std::max(a.max_contact_gap_rel, std::abs(c.gap));
    a.max_contact_gap_rel /= a.r_min;
    a.partial_coordination = partial_coordination(balls.radii, net.pairs, options.partial_coordination_points);
    a.fabric = fabric_tensors<D>(n, net.pairs, net.normals);
    a.projections = relative_projections<D>(net.normals, options.projection_bins);
  });

  timed_step(t, "homogeneity", [&] {
    a.homogeneity = centre_homogeneity(balls, container, 2 * bounding_max);  // the core of VF core
    for (std::size_t k = 0; k < requested.size() && k < families.size(); ++k)
      if (requested[k].size) a.distribution += (a.distribution.empty() ? "" : "; ") + families[k] + " " + requested[k].size->describe();
    a.radii_fit = a.validation->radii();  // the one template's sizes (none for several: see the validation)
    a.orientation = fabric_of_directions<D>(axes);
    a.orientation_order = a.orientation->eigenvalues.empty() ? 0.0 : (D * a.orientation->eigenvalues.back() - 1) / (D - 1);
    // The texture about the reference centre: 3D P2(t), 2D cos 2 psi = 2 t^2 - 1, t = a . r / |r|;
    // an isotropic sample's variance of them is 1/5 (3D), 1/2 (2D).
    // Every body axis: sum_i (e_i . r)^4 has mean 3/5 and variance 16/525 for an isotropic
    // rotation in 3D (moments of a uniform unit vector: E x^8 = 1/9, E x^4 y^4 = 1/105), mean
    // 3/4 and variance 1/32 in 2D (cos^4 + sin^4 = 1 - sin^2(2 psi) / 2).
    const Vec<D> centre = container.interior_point();
    double sum = 0.0, sum_axes = 0.0;
    std::size_t used = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec<D> r = ps[i].pose.position - centre;
      const double len = r.norm();
      if (!(len > bounding_max) || !std::isfinite(len)) continue;
      const double t = axes[i].dot(r) / (len * axes[i].norm());
      sum += D == 3 ? 1.5 * t * t - 0.5 : 2 * t * t - 1;
      const Vec<D> in_body = ps[i].pose.rotation.transpose() * (r / len);
      sum_axes += in_body.array().square().square().sum() - (D == 3 ? 0.6 : 0.75);
      ++used;
    }
    if (used > 0) {
      a.radial_order = sum / static_cast<double>(used);
      a.radial_order_noise = std::sqrt((D == 3 ? 0.2 : 0.5) / static_cast<double>(used));
      a.radial_axes_order = sum_axes / static_cast<double>(used);
      a.radial_axes_order_noise = std::sqrt((D == 3 ? 16.0 / 525.0 : 1.0 / 32.0) / static_cast<double>(used));
    }
  });

  timed_step(t, "volume fraction", [&] {
    const Vec<D> c = container.interior_point();
    const Vec<D> shown = c + container.origin();
    a.reference_center.assign(shown.data(), shown.data() + D);
    a.reference_radius = -container.signed_distance(c);
    if (a.reference_radius > 0.0) {
      // The curve samples the particles the reference sphere cuts at every radius: fewer points
      // per radius than a region of its own gets.
      QmcOptions per_radius = options.qmc;
      per_radius.max_ball_points = std::min<std::size_t>(per_radius.max_ball_points, std::size_t{1} << 16);
      const double from = std::min(bounding_max, a.reference_radius);
      const int points = from < a.reference_radius ? options.vf_curve_points : 1;
      for (int k = 0; k < points; ++k) {
        const double r = points == 1 ? a.reference_radius : from + (a.reference_radius - from) * k / (points - 1);
        const BallContainer<D> ball(shown, r, container.origin());
        a.vf_curve.emplace_back(r, vf_region<D>(bodies, ball, 0.0, per_radius).vf.value);
      }
      a.vf_reference = a.vf_curve.back().second;
    }
    if (a.validation->outside_count == 0 && a.validation->non_finite_count == 0) {
      // Every particle inside: the whole measure of each, exact (no bounding ball to sample
      // against a non-convex boundary).
      CompensatedSum solid;
      for (const double m : bodies.measures) solid.add(m);
      a.vf_container.measure = {a.container_measure, 0.0};
      a.vf_container.vf = {solid.value() / a.container_measure, 0.0};
      a.vf_container.balls_inside = n;
      a.vf_container.method = "exact";
    } else {
      a.vf_container = vf_region<D>(bodies, container, 0.0, options.qmc);
    }
    a.vf_core = vf_region<D>(bodies, container, 2.0 * bounding_max, options.qmc);
    // The shells cut many particles each: fewer QMC points per particle than a region of its own.
    QmcOptions per_shell = options.qmc;
    per_shell.max_ball_points = std::min<std::size_t>(per_shell.max_ball_points, std::size_t{1} << 17);
    a.wall_profile = wall_profile<D>(bodies, container, 2.0 * bounding_max / kWallShells, kWallShells, per_shell);
    if (const auto* bed = dynamic_cast<const BedRegion<D>*>(&container)) {
      std::vector<double> tops;  // each particle's highest point, by its support function along up
      for (const Particle<D>& q : ps) tops.push_back(bed->up().dot(q.support(bed->up())));
      a.bed = bed_profile<D>(bodies, *bed, bounding_max, per_shell, tops);
    }
    // Per cell, each particle as its ball of the same volume (cells are many diameters wide).
    a.vf_cells = cell_volume_fraction_auto(balls, container, a.r_mean, bounding_max);
  });

  timed_step(t, "g(r)", [&] { a.rdf = radial_distribution(balls, container, options.rdf, std::max(options.threads, 1)); });
  return a;
}

template <int D>
PackingAnalysis analyze_shape_packing(const ShapePacking<D>& packing, const Scene& scene, const AnalysisOptions& options) {
  std::vector<std::string> families;
  for (const ParticleTemplateSpec& t : scene.particle_templates) families.push_back(t.family);
  return analyze_shape_packing<D>(packing, *scene.container<D>(), requested_templates(scene), families, options);
}

template PackingAnalysis analyze_shape_packing<2>(const ShapePacking<2>&, const Scene&, const AnalysisOptions&);
template PackingAnalysis analyze_shape_packing<3>(const ShapePacking<3>&, const Scene&, const AnalysisOptions&);
template PackingAnalysis analyze_shape_packing<2>(const ShapePacking<2>&, const Container<2>&,
                                                  const std::vector<RequestedTemplate>&, const std::vector<std::string>&,
                                                  const AnalysisOptions&);
template PackingAnalysis analyze_shape_packing<3>(const ShapePacking<3>&, const Container<3>&,
                                                  const std::vector<RequestedTemplate>&, const std::vector<std::string>&,
                                                  const AnalysisOptions&);

}  // namespace fp
