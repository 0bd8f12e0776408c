#include "shapes/template_fractions.hpp"

#include <cmath>

#include "core/sampling/radius_moment.hpp"

namespace fp {

template <int D>
double mean_particle_measure(const ShapePrototype<D>& prototype, double scale_per_size, const RadiusDistribution& size) {
  return prototype.shape->measure() * std::pow(scale_per_size, D) * radius_moment(size, D);
}

std::vector<double> number_fractions(const Scene& scene, const std::vector<double>& measures) {
  std::vector<double> share;
  double total = 0;
  for (std::size_t k = 0; k < scene.particle_templates.size(); ++k) {
    const ParticleTemplateSpec& t = scene.particle_templates[k];
    share.push_back(t.fraction_basis == FractionBasis::Number ? t.fraction : t.fraction / measures[k]);
    total += share.back();
  }
  for (double& s : share) s /= total;
  return share;
}

template <int D>
std::vector<double> number_fractions(const Scene& scene) {
  std::vector<double> measures;
  for (const ParticleTemplateSpec& t : scene.particle_templates) {
    if (t.fraction_basis == FractionBasis::Number) {  // no prototype needed
      measures.push_back(1.0);
      continue;
    }
    const ShapePrototype<D> prototype = ShapeFamilies::builtin().prototype<D>(t);
    measures.push_back(mean_particle_measure<D>(prototype, 1.0 / prototype.dimensions.at(t.size_on), *t.size));
  }
  return number_fractions(scene, measures);
}

template std::vector<double> number_fractions<2>(const Scene&);
template std::vector<double> number_fractions<3>(const Scene&);
template double mean_particle_measure<2>(const ShapePrototype<2>&, double, const RadiusDistribution&);
template double mean_particle_measure<3>(const ShapePrototype<3>&, double, const RadiusDistribution&);

}  // namespace fp
