#pragma once
// A scene's particle template resolved for packing: the family's prototype (circumscribed radius
// 1), the size distribution on its named dimension and how orientations are drawn. Drafts are
// the particles drawn from templates, waiting in the pool for a place.
#include <vector>

#include "core/io/scene.hpp"
#include "core/sampling/rng.hpp"
#include "shapes/particle.hpp"
#include "shapes/shape_registry.hpp"

namespace fp {

template <int D>
struct ShapeTemplate {
  std::string family;
  ShapePrototype<D> prototype;
  RadiusDistributionPtr size;         ///< on the named dimension
  double scale_per_size = 1.0;        ///< prototype scale factor per unit of size (1 / dimension value)
  OrientationSpec orientation;       ///< as written
  OrientationLaw<D> orientation_law;  ///< how orientations are drawn
  double fraction = 1.0;

  double bounding_min() const { return size->r_min() * scale_per_size; }
  double bounding_max() const { return size->r_max() * scale_per_size; }
};

/// A drawn particle not yet placed: shape at its size, and its orientation (drawn from the
/// template's law; the front may turn it while placing it, within the law: front/advancing_front.hpp).
template <int D>
struct Draft {
  int template_id = 0;
  double size = 0.0;
  ShapePtr<D> shape;
  Mat<D> rotation = Mat<D>::Identity();
  double bounding_radius() const { return shape->bounding_radius(); }
};

/// Resolves the scene's templates (throws SceneError for a bad family or parameter).
template <int D>
std::vector<ShapeTemplate<D>> resolve_templates(const Scene& scene);

/// Mean measure (volume in 3D, area in 2D) of the particles drawn from `templates`: each
/// prototype's measure times E[(size x scale_per_size)^D], weighted by fraction.
template <int D>
double mean_measure(const std::vector<ShapeTemplate<D>>& templates);

/// Draws a template by fraction, a size from its distribution and an orientation from its law
/// (core/sampling/orientation_law.hpp). Deterministic in rng.
template <int D>
Draft<D> draw_draft(const std::vector<ShapeTemplate<D>>& templates, Rng& rng);

}  // namespace fp
