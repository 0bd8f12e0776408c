#include "contact/shape_validation.hpp"

#include <cmath>

#include "contact/narrow_phase.hpp"
#include "contact/shape_containment.hpp"
#include "core/metrics/validate_particles.hpp"
#include "shapes/template_fractions.hpp"

namespace fp {

std::vector<RequestedTemplate> requested_templates(const Scene& scene) {
  std::vector<RequestedTemplate> requested;  // template ids follow the scene's list, shares by number
  const std::vector<double> shares = scene.particle_templates.empty() ? std::vector<double>{}
                                     : scene.dimension == 2 ? number_fractions<2>(scene) : number_fractions<3>(scene);
  for (std::size_t k = 0; k < scene.particle_templates.size(); ++k) {
    const ParticleTemplateSpec& t = scene.particle_templates[k];
    requested.push_back({t.size.get(), shares[k], &t.orientation});
  }
  return requested;
}

namespace {

// Particles as validate_particles sees them: the circumscribed spheres for the broad phase, the
// narrow phase's signed gap for pairs, ShapeContainment for the container.
template <int D>
class ShapeParticles {
 public:
  static constexpr const char* kSizeIssue = "size_out_of_range";
  static constexpr const char* kUnitName = "circumscribed radius";
  static constexpr bool kNormalsAreCentreLines = false;  // the narrow phase's normals

  ShapeParticles(const ShapePacking<D>& packing, const Container<D>& container)
      : p_(packing.particles), containment_(container, np_) {
    centers_.reserve(p_.size());
    radii_.reserve(p_.size());
    for (const Particle<D>& q : p_) {
      centers_.push_back(q.pose.position);
      radii_.push_back(q.bounding_radius());
    }
  }
  std::size_t size() const { return p_.size(); }
  const std::vector<Vec<D>>& centers() const { return centers_; }
  const std::vector<double>& reach_radii() const { return radii_; }
  bool finite(std::size_t i) const {
    return centers_[i].allFinite() && std::isfinite(radii_[i]) && std::isfinite(p_[i].size) && p_[i].pose.rotation.allFinite();
  }
  double unit(std::size_t i) const { return radii_[i]; }
  double overlap(std::size_t i, std::size_t j, Vec<D>* normal) const {
    const Gap<D> g = np_.gap(p_[i], p_[j]);
    if (normal) *normal = g.normal;
    return -g.value;
  }
  double protrusion(std::size_t i, double) const { return containment_.protrusion(p_[i]); }
  int template_of(std::size_t i) const { return p_[i].template_id; }
  double size_of(std::size_t i) const { return p_[i].size; }

 private:
  const std::vector<Particle<D>>& p_;
  std::vector<Vec<D>> centers_;
  std::vector<double> radii_;
  NarrowPhase<D> np_;
  const ShapeContainment<D> containment_;
};

}  // namespace

template <int D>
ValidationReport validate_shapes(const ShapePacking<D>& packing, const Container<D>& container, double tolerance,
                                 const std::vector<RequestedTemplate>& requested, double sizes_alpha,
                                 ContactNetwork<D>* network) {
  ValidationReport rep = validate_particles<D>(ShapeParticles<D>(packing, container), tolerance, requested, sizes_alpha, network);
  // The orientations of each template against its law (validate_particles has no rotations).
  std::vector<std::vector<Mat<D>>> rotations(requested.size());
  for (const Particle<D>& p : packing.particles) {
    const auto t = static_cast<std::size_t>(p.template_id);
    if (t < requested.size() && requested[t].orientation && p.pose.rotation.allFinite()) rotations[t].push_back(p.pose.rotation);
  }
  rep.orientations.resize(requested.size());
  for (std::size_t t = 0; t < requested.size(); ++t)
    if (requested[t].orientation && !rotations[t].empty())
      rep.orientations[t] = orientation_fit<D>(rotations[t], requested[t].orientation->template law<D>());
  rep.ok = rep.ok && rep.orientations_ok();
  return rep;
}

template ValidationReport validate_shapes<2>(const ShapePacking<2>&, const Container<2>&, double,
                                            const std::vector<RequestedTemplate>&, double, ContactNetwork<2>*);
template ValidationReport validate_shapes<3>(const ShapePacking<3>&, const Container<3>&, double,
                                            const std::vector<RequestedTemplate>&, double, ContactNetwork<3>*);

}  // namespace fp
