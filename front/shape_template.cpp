#include "front/shape_template.hpp"

#include "core/io/scene_error.hpp"
#include "shapes/template_fractions.hpp"

namespace fp {

template <int D>
std::vector<ShapeTemplate<D>> resolve_templates(const Scene& scene) {
  std::vector<ShapeTemplate<D>> out;
  std::vector<double> measures;
  for (const ParticleTemplateSpec& spec : scene.particle_templates) {
    ShapeTemplate<D> t;
    t.family = spec.family;
    t.prototype = ShapeFamilies::builtin().prototype<D>(spec);
    t.size = spec.size;
    t.scale_per_size = 1.0 / t.prototype.dimensions.at(spec.size_on);
    t.orientation = spec.orientation;
    t.orientation_law = spec.orientation.law<D>();
    measures.push_back(mean_particle_measure<D>(t.prototype, t.scale_per_size, *t.size));
    out.push_back(std::move(t));
  }
  const std::vector<double> shares = number_fractions(scene, measures);  // by volume: converted to number
  for (std::size_t k = 0; k < out.size(); ++k) out[k].fraction = shares[k];
  return out;
}

template <int D>
double mean_measure(const std::vector<ShapeTemplate<D>>& templates) {
  double sum = 0, weights = 0;
  for (const ShapeTemplate<D>& t : templates) {
    sum += t.fraction * mean_particle_measure<D>(t.prototype, t.scale_per_size, *t.size);
    weights += t.fraction;
  }
  return sum / weights;
}

template <int D>
Draft<D> draw_draft(const std::vector<ShapeTemplate<D>>& templates, Rng& rng) {
  Draft<D> d;
  if (templates.size() > 1) {
    double total = 0;
    for (const auto& t : templates) total += t.fraction;
    double u = rng.uniform01() * total;
    d.template_id = static_cast<int>(templates.size()) - 1;
    for (std::size_t k = 0; k < templates.size(); ++k) {
      if (u < templates[k].fraction) { d.template_id = static_cast<int>(k); break; }
      u -= templates[k].fraction;
    }
  }
  const ShapeTemplate<D>& t = templates[static_cast<std::size_t>(d.template_id)];
  d.size = t.size->sample(rng);
  d.shape = t.prototype.shape->scaled(d.size * t.scale_per_size);
  d.rotation = t.orientation_law.draw(rng);
  return d;
}

template std::vector<ShapeTemplate<2>> resolve_templates<2>(const Scene&);
template std::vector<ShapeTemplate<3>> resolve_templates<3>(const Scene&);
template double mean_measure<2>(const std::vector<ShapeTemplate<2>>&);
template double mean_measure<3>(const std::vector<ShapeTemplate<3>>&);
template Draft<2> draw_draft<2>(const std::vector<ShapeTemplate<2>>&, Rng&);
template Draft<3> draw_draft<3>(const std::vector<ShapeTemplate<3>>&, Rng&);

}  // namespace fp
