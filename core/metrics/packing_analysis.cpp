#include "core/metrics/packing_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/box_container.hpp"
#include "core/metrics/contacts.hpp"
#include "core/metrics/timed_step.hpp"
#include "core/metrics/volume_fraction.hpp"
#include "core/system/parallel_parts.hpp"

namespace fp {
template <int D>
std::unique_ptr<Container<D>> bounding_box_of_balls(const Packing<D>& packing) {
  Aabb<D> box;
  for (std::size_t i = 0; i < packing.size(); ++i) {
    const double r = packing.radii[i];
    if (!(r >= 0.0) || !std::isfinite(r) || !packing.centers[i].allFinite()) continue;
    box.extend(packing.centers[i] - Vec<D>::Constant(r));
    box.extend(packing.centers[i] + Vec<D>::Constant(r));
  }
  if (!((box.hi.array() > box.lo.array()).all())) return nullptr;
  return std::make_unique<BoxContainer<D>>(BoxContainer<D>::from_local(box.lo, box.hi, packing.origin));
}

template std::unique_ptr<Container<2>> bounding_box_of_balls<2>(const Packing<2>&);
template std::unique_ptr<Container<3>> bounding_box_of_balls<3>(const Packing<3>&);

std::string PackingAnalysis::summary() const {
  std::string s;
  char buf[400];
  auto line = [&](const char* fmt, auto... args) {
    std::snprintf(buf, sizeof buf, fmt, args...);
    if (!s.empty()) s += '\n';
    s += buf;
  };
  auto estimate = [](const RegionVolumeFraction& v) {
    char b[200];
    if (v.exact) std::snprintf(b, sizeof b, "%.6f (exact)", v.vf.value);
    else std::snprintf(b, sizeof b, "%.6f +- %.2g (%s)", v.vf.value, v.vf.std_error, v.method.c_str());
    return std::string(b);
  };
  line("particles            %llu (%dD), %s in [%.6g, %.6g], mean %.6g", static_cast<unsigned long long>(particles),
       dimension, radius_name.c_str(), r_min, r_max, r_mean);
  if (!templates.empty()) {
    std::string t;
    for (const auto& [family, count] : templates) t += (t.empty() ? "" : ", ") + std::to_string(count) + " " + family;
    line("templates            %s", t.c_str());
  }
  line("container            %s%s", container.c_str(),
       container_from_particles ? " (bounding box of the particles)" : "");
  line("VF reference ball    %.6f (r_ref = a = %.6g; %zu radii from r_max%s)", vf_reference, reference_radius,
       vf_curve.size(), radius_name == "r" ? "" : "; QMC for the particles it cuts");
  line("VF container         %s", estimate(vf_container).c_str());
  if (std::isfinite(vf_core.vf.value))
    line("VF core              %s, 2 r_max = %.6g inside", estimate(vf_core).c_str(), vf_core.shrink);
  else
    line("VF core              none: the container has no core 2 r_max = %.6g inside", vf_core.shrink);
  if (wall_profile.computed()) {
    std::string shells;
    for (const Estimate& e : wall_profile.vf) {
      std::snprintf(buf, sizeof buf, "%s%.3f", shells.empty() ? "" : " ", e.value);
      shells += buf;
    }
    line("VF wall layers       %.4f within 2 r_max; shells of %.4g from the wall: %s", wall_profile.layer.value,
         wall_profile.width, shells.c_str());
  }
  if (bed.computed()) {
    // The first and last four slabs: the floor's layers and the surface's.
    std::string slabs;
    for (std::size_t k = 0; k < bed.vf.size(); ++k) {
      if (k == 4 && bed.vf.size() > 8) {
        slabs += " ...";
        k = bed.vf.size() - 4;
      }
      std::snprintf(buf, sizeof buf, "%s%.3f", slabs.empty() ? "" : " ", bed.vf[k].value);
      slabs += buf;
    }
    line("bed profile          height %.6g; slabs of %.4g from the floor up: %s", bed.height, bed.width, slabs.c_str());
    if (std::isfinite(bed.bulk.value))
      line("bed bulk / top       %.4f from 2 r_max over the floor to 2 r_max under the level; %.4f in its last 2 r_max; "
           "half the bulk at height %.6g",
           bed.bulk.value, bed.top_layer.value, bed.half_bulk_height);
    else
      line("bed bulk / top       none: the bed is not 4 r_max high; %.4f in its last 2 r_max", bed.top_layer.value);
    if (bed.surface.columns > 0)
      line("bed surface          highest tops over %llu columns of 4 r_max: mean %.6g, sd %.3g, range [%.6g, %.6g]",
           static_cast<unsigned long long>(bed.surface.columns), bed.surface.mean, bed.surface.std_dev, bed.surface.min,
           bed.surface.max);
  }
  if (vf_cells.computed() && vf_cells.cells < 2)
    line("VF cells             %.4f in the one cell of %g <d> (edge %.6g) that fits 2 r_max inside: no spread from one cell",
         vf_cells.mean, vf_cells.diameters, vf_cells.edge);
  else if (vf_cells.computed())
    line("VF cells             mean %.4f, sd %.4f, range [%.4f, %.4f] over %llu cells of %g <d> (edge %.6g), 2 r_max inside",
         vf_cells.mean, vf_cells.std_dev, vf_cells.min, vf_cells.max, static_cast<unsigned long long>(vf_cells.cells),
         vf_cells.diameters, vf_cells.edge);
  else
    line("VF cells             none: no cell of 2 mean diameters fits 2 r_max inside the container");
  line("coordination z       %.4f (%.4f with walls), %llu rattlers, tol %.3g", coordination.mean_coordination,
       coordination.mean_coordination_with_walls, static_cast<unsigned long long>(coordination.rattlers),
       contact_tolerance);
  line("contacts             %llu between particles, %llu with walls",
       static_cast<unsigned long long>(coordination.contacts),
       static_cast<unsigned long long>(coordination.wall_contacts));
  line("max overlap / gap    %.3g / %.3g %s_min", max_overlap_rel, max_contact_gap_rel, radius_name.c_str());
  auto eigen = [&](const char* name, const FabricTensor& f) {
    std::string v;
    for (const double e : f.eigenvalues) {
      std::snprintf(buf, sizeof buf, "%s%.4f", v.empty() ? "" : ", ", e);
      v += buf;
    }
    line("%s (%s)", name, v.c_str());
  };
  eigen("fabric per contact  ", fabric.per_contact);
  eigen("fabric per particle ", fabric.per_particle);
  const char* axes = "xyz";
  for (std::size_t a = 0; a < homogeneity.axis.size(); ++a) {
    const KsResult& k = homogeneity.axis[a];
    if (k.n == 0) {
      line("K-S centres %c        none: no centre lies %.6g (2 r_max) inside the container", axes[a], homogeneity.margin);
      continue;
    }
    line("K-S centres %c        sqrt(n) D = %.4f (%s 1.358), p = %.3g; the %llu centres 2 r_max inside", axes[a], k.sqrt_n_d,
         k.below_critical() ? "<" : ">=", k.p, static_cast<unsigned long long>(k.n));
  }
  for (std::size_t a = 0; a < projections.ks.size(); ++a)
    line("K-S projections %c    D = %.4f, p = %.3g vs %s", axes[a], projections.ks[a].d, projections.ks[a].p,
         projections.reference.c_str());
  if (!distribution.empty() && radii_fit.computed())
    line("radii test           %s vs %s", radii_fit.describe().c_str(), distribution.c_str());
  else if (!distribution.empty())
    line("size tests           per template, in the validation below (%s)", distribution.c_str());
  if (!rdf.g.empty() && rdf.reference_particles == 0) {
    line("g(r)                 none: no centre lies %.6g (r_cut %g <d> + r_max) inside the container, so no shell of "
         "r_cut around one is free of the walls", rdf.reference_margin, rdf.range);
  } else if (!rdf.g.empty()) {
    const auto peak = std::max_element(rdf.g.begin(), rdf.g.end()) - rdf.g.begin();
    line("g(r)                 max %.3f at r = %.3f <d>, %llu reference particles", rdf.g[peak], rdf.r[peak],
         static_cast<unsigned long long>(rdf.reference_particles));
  }
  if (orientation) {
    line("orientation order    S = %.4f (body x axes; 0 isotropic, 1 parallel)", orientation_order);
    eigen("orientation tensor  ", *orientation);
    line("radial order         %.4f (axes against the direction from the reference centre; isotropic 0 +- %.4f, "
         "> 0 radial, < 0 tangential)", radial_order, radial_order_noise);
    line("radial axes order    %.4f (every body axis: <sum (e.r)^4> less its isotropic mean; isotropic 0 +- %.4f, "
         "> 0 a face along the radius, < 0 an edge)", radial_axes_order, radial_axes_order_noise);
  }
  if (validation) {
    s += '\n';
    s += validation->summary();
  }
  return s;
}

template <int D>
PackingAnalysis analyze_packing(const Packing<D>& packing, const Container<D>* container_or_null,
                                const RadiusDistribution* dist_or_null, const AnalysisOptions& options) {
  PackingAnalysis a;
  a.dimension = D;
  a.particles = packing.size();
  a.contact_tolerance = options.contact_tolerance;
  std::vector<double> radii;  // positive and finite
  for (std::size_t i = 0; i < packing.size(); ++i)
    if (packing.radii[i] > 0.0 && std::isfinite(packing.radii[i]) && packing.centers[i].allFinite())
      radii.push_back(packing.radii[i]);
  if (!radii.empty()) {
    a.r_min = *std::min_element(radii.begin(), radii.end());
    a.r_max = *std::max_element(radii.begin(), radii.end());
    for (const double r : radii) a.r_mean += r;
    a.r_mean /= static_cast<double>(radii.size());
  }

  std::unique_ptr<Container<D>> own;
  if (container_or_null == nullptr) {
    own = bounding_box_of_balls(packing);
    a.container_from_particles = true;
  }
  const Container<D>* container = own ? own.get() : container_or_null;
  if (container && container->origin() != packing.origin)
    throw std::invalid_argument("analyze_packing: the packing and the container are in different frames");
  if (container == nullptr) return a;  // no ball with a positive size: nothing to measure
  a.container = container->describe();
  a.container_measure = container->measure();
  auto& t = a.timings;
  const int threads = std::max(options.threads, 1);

  // The contacts are found once: by the validation when it runs (its network), else here; the
  // coordination and the network's figures share them.
  ContactNetwork<D> network;
  if (options.validate)
    timed_step(t, "validate", [&] {
      a.validation = validate_packing(packing, *container, dist_or_null, options.contact_tolerance, options.radii_alpha,
                                      &network, threads);
    });
  else
    timed_step(t, "contacts", [&] {
      network.pairs = find_pair_contacts(packing, options.contact_tolerance);
      network.walls = find_wall_contacts(packing, *container, options.contact_tolerance);
    });
  const std::vector<PairContact>& contacts = network.pairs;

  // The figures below read the packing, the container and the contacts, and each writes its own
  // members of `a`: they run at once, on the threads given.
  std::vector<std::pair<const char*, std::function<void()>>> steps;
  steps.emplace_back("contact network", [&] {  // the largest first: three sorts of every contact
    for (const PairContact& c : contacts) a.max_contact_gap_rel = std::max(a.max_contact_gap_rel, std::abs(c.gap));
    if (a.r_min > 0.0) a.max_contact_gap_rel /= a.r_min;
    a.projections = relative_projections(packing, contacts, options.projection_bins);
  });
  steps.emplace_back("homogeneity", [&] {
    a.homogeneity = centre_homogeneity(packing, *container, 2 * a.r_max);  // the core of VF core
    if (dist_or_null != nullptr) {
      a.distribution = dist_or_null->describe();
      if (a.validation) {
        a.radii_fit = a.validation->radii();  // one test, one figure
      } else {
        // The sample validate_packing tests: every ball with a finite centre and radius.
        std::vector<double> sample;
        for (std::size_t i = 0; i < packing.size(); ++i)
          if (std::isfinite(packing.radii[i]) && packing.centers[i].allFinite()) sample.push_back(packing.radii[i]);
        a.radii_fit = radii_fit(std::move(sample), *dist_or_null);
      }
    }
  });
  steps.emplace_back("coordination", [&] {
    a.coordination = contact_stats_of(D, packing.size(), contacts, &network.walls, smallest_radius(packing),
                                      options.contact_tolerance);
    a.max_overlap_rel = a.coordination.max_overlap_rel;
    a.partial_coordination = partial_coordination(packing.radii, contacts, options.partial_coordination_points);
    a.fabric = fabric_tensors(packing, contacts);
  });
  steps.emplace_back("volume fraction", [&] {
    const Vec<D> c = container->interior_point();
    const Vec<D> shown = c + container->origin();  // reported in absolute coordinates
    a.reference_center.assign(shown.data(), shown.data() + D);
    a.reference_radius = -container->signed_distance(c);
    if (a.reference_radius > 0.0) {
      const double from = a.r_max > 0.0 ? std::min(a.r_max, a.reference_radius) : a.reference_radius;
      const int points = from < a.reference_radius ? options.vf_curve_points : 1;
      a.vf_curve = vf_reference_curve(packing, c, from, a.reference_radius, points);
      a.vf_reference = a.vf_curve.back().second;
    }
    a.vf_container = vf_region(packing, *container, 0.0, options.qmc);
    a.vf_core = vf_region(packing, *container, 2.0 * a.r_max, options.qmc);
    if (a.r_max > 0.0) a.wall_profile = wall_profile<D>(packing, *container, 2.0 * a.r_max / kWallShells, kWallShells, options.qmc);
    if (const auto* bed = dynamic_cast<const BedRegion<D>*>(container); bed && a.r_max > 0.0)
      a.bed = bed_profile<D>(packing, *bed, a.r_max);
  });
  steps.emplace_back("cells", [&] {
    a.vf_cells = cell_volume_fraction_auto(packing, *container, a.r_mean, a.r_max);
  });
  std::vector<double> seconds(steps.size(), 0.0);
  for_each_part(steps.size(), threads, [&](std::size_t k) {
    std::vector<std::pair<std::string, double>> one;
    timed_step(one, steps[k].first, steps[k].second);
    seconds[k] = one.front().second;
  });
  for (std::size_t k = 0; k < steps.size(); ++k) t.emplace_back(steps[k].first, seconds[k]);

  timed_step(t, "g(r)", [&] { a.rdf = radial_distribution(packing, *container, options.rdf, threads); });
  return a;
}

template PackingAnalysis analyze_packing<2>(const Packing<2>&, const Container<2>*, const RadiusDistribution*,
                                            const AnalysisOptions&);
template PackingAnalysis analyze_packing<3>(const Packing<3>&, const Container<3>*, const RadiusDistribution*,
                                            const AnalysisOptions&);

}  // namespace fp
