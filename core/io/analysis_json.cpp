#include "core/io/analysis_json.hpp"

#include <nlohmann/json.hpp>

namespace fp {
namespace {

using Json = nlohmann::ordered_json;

const char* const kAxes[] = {"x", "y", "z"};

Json estimate_json(const Estimate& e) { return Json{{"value", e.value}, {"std_error", e.std_error}}; }

Json ks_fields(Json j, const KsResult& k) {
  j["n"] = k.n;
  j["d"] = k.d;
  j["sqrt_n_d"] = k.sqrt_n_d;
  j["p"] = k.p;
  return j;
}

Json radii_fit_fields(Json j, const RadiiFit& f) {
  j["test"] = f.test;
  j["n"] = f.n;
  j["statistic"] = f.statistic;
  j["dof"] = f.dof;
  j["p"] = f.p;
  j["off_support"] = f.off_support;
  return j;
}

Json region_json(const RegionVolumeFraction& v) {
  return Json{{"shrink", v.shrink},
              {"value", v.vf.value},
              {"std_error", v.vf.std_error},
              {"exact", v.exact},
              {"method", v.method},
              {"measure", estimate_json(v.measure)},
              {"balls",
               Json{{"inside", v.balls_inside}, {"cut_exact", v.balls_cut_exact}, {"sampled", v.balls_sampled}}}};
}

Json fabric_json(const FabricTensor& f, int dimension) {
  Json rows = Json::array();
  for (int a = 0; a < dimension && !f.tensor.empty(); ++a)
    rows.push_back(std::vector<double>(f.tensor.begin() + a * dimension, f.tensor.begin() + (a + 1) * dimension));
  return Json{{"tensor", rows}, {"eigenvalues", f.eigenvalues}, {"count", f.count}};
}

Json validation_json(const ValidationReport& v) {
  Json worst = Json::array();
  for (const ValidationIssue& w : v.worst)
    worst.push_back(Json{{"kind", w.kind}, {"i", w.i}, {"j", w.j}, {"value_rel", w.value_rel}});
  // Per template (null where not computed): the law, its tests and the nematic order about its axis.
  Json orientations = Json::array();
  for (const OrientationFit& f : v.orientations) {
    if (!f.computed()) {
      orientations.push_back(nullptr);
      continue;
    }
    Json tests = Json::object();
    for (const OrientationFit::Test& t : f.tests) tests[t.name] = Json{{"statistic", t.statistic}, {"p", t.p}};
    orientations.push_back(Json{{"law", f.law}, {"n", f.n}, {"tests", tests}, {"order", f.order},
                                {"law_order", f.law_order}, {"order_noise", f.order_noise}});
  }
  return Json{{"ok", v.ok},
              {"tolerance", v.tolerance},
              {"radii_alpha", v.radii_alpha},
              {"particles", v.particles},
              {"pairs_checked", v.pairs_checked},
              {"max_overlap_rel", v.max_overlap_rel},
              {"max_outside_rel", v.max_outside_rel},
              {"overlap_count", v.overlap_count},
              {"outside_count", v.outside_count},
              {"radius_count", v.radius_count},
              {"non_finite_count", v.non_finite_count},
              {"contacts", v.contacts},
              {"wall_contacts", v.wall_contacts},
              {"max_contact_gap_rel", v.max_contact_gap_rel},
              {"worst", worst},
              {"radii", radii_fit_fields(Json::object(), v.radii())},
              {"orientation_alpha", v.orientation_alpha},
              {"orientations", orientations}};
}

}  // namespace

std::string validation_json_text(const ValidationReport& v) {
  return validation_json(v).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string analysis_json(const PackingAnalysis& a, bool include_timings) {
  Json j;
  j["dimension"] = a.dimension;
  j["particles"] = a.particles;
  j["radii"] = Json{{"name", a.radius_name}, {"min", a.r_min}, {"max", a.r_max}, {"mean", a.r_mean}};
  if (!a.templates.empty()) {
    Json t = Json::array();
    for (const auto& [family, count] : a.templates) t.push_back(Json{{"family", family}, {"count", count}});
    j["templates"] = t;
  }
  j["container"] = Json{{"description", a.container}, {"from_particles", a.container_from_particles},
                        {"measure", a.container_measure}};
  j["contact_tolerance"] = a.contact_tolerance;

  Json curve_r = Json::array(), curve_vf = Json::array();
  for (const auto& [r, vf] : a.vf_curve) {
    curve_r.push_back(r);
    curve_vf.push_back(vf);
  }
  j["volume_fraction"] = Json{
      {"reference", Json{{"center", a.reference_center}, {"radius", a.reference_radius}, {"value", a.vf_reference}}},
      {"curve", Json{{"r_ref", curve_r}, {"vf", curve_vf}}},
      {"container", region_json(a.vf_container)},
      {"core", region_json(a.vf_core)},
      {"cells", Json{{"edge", a.vf_cells.edge}, {"diameters", a.vf_cells.diameters}, {"margin", a.vf_cells.margin},
                     {"cells", a.vf_cells.cells}, {"mean", a.vf_cells.mean}, {"std_dev", a.vf_cells.std_dev},
                     {"min", a.vf_cells.min}, {"max", a.vf_cells.max}, {"worst", a.vf_cells.worst},
                     {"worst_centre", a.vf_cells.worst_centre}}}};
  // The wall layers: each shell's middle distance from the boundary, solid fraction and error.
  Json wall_distance = Json::array(), wall_vf = Json::array(), wall_error = Json::array();
  for (std::size_t k = 0; k < a.wall_profile.vf.size(); ++k) {
    wall_distance.push_back(a.wall_profile.middle(k));
    wall_vf.push_back(a.wall_profile.vf[k].value);
    wall_error.push_back(a.wall_profile.vf[k].std_error);
  }
  if (a.bed.computed()) {
    std::vector<double> heights, vf, error;
    for (std::size_t k = 0; k < a.bed.vf.size(); ++k) {
      heights.push_back(a.bed.middle(k));
      vf.push_back(a.bed.vf[k].value);
      error.push_back(a.bed.vf[k].std_error);
    }
    Json bed{{"height", a.bed.height}, {"width", a.bed.width}, {"slab_middle", heights}, {"vf", vf}, {"std_error", error},
             {"bulk", a.bed.bulk.value}, {"top_layer", a.bed.top_layer.value}, {"half_bulk_height", a.bed.half_bulk_height}};
    if (a.bed.surface.columns > 0)
      bed["surface"] = Json{{"columns", a.bed.surface.columns}, {"mean", a.bed.surface.mean}, {"sd", a.bed.surface.std_dev},
                            {"min", a.bed.surface.min}, {"max", a.bed.surface.max}};
    j["volume_fraction"]["bed_profile"] = bed;
  }
  j["volume_fraction"]["wall_profile"] =
      Json{{"width", a.wall_profile.width}, {"distance", wall_distance}, {"vf", wall_vf}, {"std_error", wall_error},
           {"layer", a.wall_profile.layer.value}, {"layer_std_error", a.wall_profile.layer.std_error}};

  const ContactStats& c = a.coordination;
  const PartialCoordination& pc = a.partial_coordination;
  j["coordination"] = Json{{"mean", c.mean_coordination},
                           {"mean_with_walls", c.mean_coordination_with_walls},
                           {"contacts", c.contacts},
                           {"wall_contacts", c.wall_contacts},
                           {"rattlers", c.rattlers},
                           {"histogram", c.histogram},
                           {"partial", Json{{"xi", pc.xi}, {"radius", pc.radius}, {"particles", pc.particles},
                                            {"contacts", pc.contacts}, {"z", pc.z}}}};
  j["overlap"] = Json{{"max_overlap_rel", a.max_overlap_rel},
                      {"max_contact_gap_rel", a.max_contact_gap_rel},
                      {"worst_pair", c.worst_i >= 0 ? Json{c.worst_i, c.worst_j} : Json(nullptr)}};
  j["fabric"] = Json{{"per_contact", fabric_json(a.fabric.per_contact, a.dimension)},
                     {"per_particle", fabric_json(a.fabric.per_particle, a.dimension)}};

  Json axes = Json::array();
  for (std::size_t k = 0; k < a.homogeneity.axis.size(); ++k) {
    const KsResult& ks = a.homogeneity.axis[k];
    axes.push_back(ks_fields(Json{{"axis", kAxes[k]}, {"lo", a.homogeneity.lo[k]}, {"hi", a.homogeneity.hi[k]}}, ks));
    axes.back()["below_critical"] = ks.below_critical();
  }
  j["homogeneity"] = Json{{"margin", a.homogeneity.margin}, {"reference_points", a.homogeneity.reference_points}, {"axes", axes}};
  j["radii_fit"] = radii_fit_fields(Json{{"distribution", a.distribution}}, a.radii_fit);

  Json proj = Json::array();
  for (std::size_t k = 0; k < a.projections.ks.size(); ++k)
    proj.push_back(ks_fields(Json{{"axis", kAxes[k]}, {"histogram", a.projections.histogram[k]}}, a.projections.ks[k]));
  j["relative_projections"] = Json{{"reference", a.projections.reference}, {"bins", a.projections.bins},
                                   {"contacts", a.projections.contacts}, {"axes", proj}};

  const RadialDistribution& g = a.rdf;
  j["rdf"] = Json{{"mean_diameter", g.mean_diameter},
                  {"range", g.range},
                  {"reference_margin", g.reference_margin},
                  {"reference_particles", g.reference_particles},
                  {"reference_measure", estimate_json(g.reference_measure)},
                  {"density", g.density},
                  {"r", g.r},
                  {"g", g.g}};
  if (a.orientation)
    j["orientation"] = Json{{"axis", "body x"},
                            {"tensor", fabric_json(*a.orientation, a.dimension)},
                            {"order", a.orientation_order},
                            {"radial_order", a.radial_order},
                            {"radial_order_noise", a.radial_order_noise},
                            {"radial_axes_order", a.radial_axes_order},
                            {"radial_axes_order_noise", a.radial_axes_order_noise}};
  j["validation"] = a.validation ? validation_json(*a.validation) : Json(nullptr);
  if (include_timings) {
    j["timings"] = Json::object();
    for (const auto& [name, seconds] : a.timings) j["timings"][name] = seconds;
  }
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace fp
