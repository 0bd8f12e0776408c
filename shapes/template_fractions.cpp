#include "shapes/template_fractions.hpp"

#include <cmath>

#include "core/sampling/radius_moment.hpp"
#include "shapes/shape_registry.hpp"

namespace fp {

template <int D>
double mean_particle_measure(const ParticleTemplateSpec& spec) {
  const ShapePrototype<D> prototype = ShapeFamilies::builtin().prototype<D>(spec);
  const double scale = 1.0 / prototype.dimensions.at(spec.size_on);
  return prototype.shape->measure() * std::pow(scale, D) * radius_moment(*spec.size, D);
}

template <int D>
std::vector<double> number_fractions(const Scene& scene) {
  std::vector<double> share;
  double total = 0;
  for (const ParticleTemplateSpec& t : scene.particle_templates) {
    share.push_back(t.fraction_basis == FractionBasis::Number ? t.fraction : t.fraction / mean_particle_measure<D>(t));
    total += share.back();
  }
  for (double& s : share) s /= total;
  return share;
}

template std::vector<double> number_fractions<2>(const Scene&);
template std::vector<double> number_fractions<3>(const Scene&);
template double mean_particle_measure<2>(const ParticleTemplateSpec&);
template double mean_particle_measure<3>(const ParticleTemplateSpec&);

}  // namespace fp
