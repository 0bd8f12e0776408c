#pragma once
// A particle = shape (at its own size) + pose; a shape packing = the placed particles plus the
// names of the scene's particle templates (their index is the "shape id" of the outputs).
#include <string>
#include <vector>

#include "shapes/pose.hpp"
#include "shapes/shape.hpp"

namespace fp {

template <int D>
struct Particle {
  ShapePtr<D> shape;     ///< already scaled to the particle's size
  Pose<D> pose;
  int template_id = 0;   ///< index of the scene's particle template
  double size = 0.0;     ///< the size drawn from the template's distribution (on its named dimension)

  double bounding_radius() const { return shape->bounding_radius(); }
  const Vec<D>& position() const { return pose.position; }
  /// World-frame support point along u.
  Vec<D> support(const Vec<D>& u) const { return pose.to_world(shape->support(pose.direction_to_body(u))); }
  bool contains(const Vec<D>& world) const { return shape->contains(pose.to_body(world)); }
};

template <int D>
struct ShapePacking {
  std::vector<Particle<D>> particles;
  std::vector<std::string> template_names;  ///< per template id: its family (and label)
  /// Positions are in the container's local frame (core/geometry/local_frame.hpp): absolute =
  /// origin + pose.position.
  Vec<D> origin = Vec<D>::Zero();

  std::size_t size() const { return particles.size(); }
  bool empty() const { return particles.empty(); }
};

}  // namespace fp
