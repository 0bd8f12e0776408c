#pragma once
// Is a particle of any shape inside the container? Two parts:
//  * its hull balls inside (container signed distance): exact for convex containers, because the
//    signed distance to a convex set is convex and so peaks on the hull balls;
//  * for containers that may be non-convex (meshes, polygons with a reflex corner), also no
//    boundary facet (triangle / edge) near the particle reaching into it (narrow phase against
//    the facet): with its hull balls inside and no facet crossing it, the particle is inside.
#include <vector>

#include "contact/narrow_phase.hpp"
#include "core/geometry/container.hpp"

namespace fp {

template <int D>
class ShapeContainment {
 public:
  ShapeContainment(const Container<D>& container, const NarrowPhase<D>& narrow_phase);

  /// How far the particle reaches beyond the boundary (<= 0: inside). A box or a convex polygon:
  /// the largest protrusion beyond a wall plane, by the support function (exact); otherwise the
  /// largest of the hull balls' protrusion and, for non-convex containers, the depth of any
  /// facet into it.
  double protrusion(const Particle<D>& p) const;
  /// protrusion <= tol * circumscribed radius.
  bool inside(const Particle<D>& p, double tol) const { return protrusion(p) <= tol * p.bounding_radius(); }
  bool checks_facets() const { return !facets_.empty(); }

 private:
  const Container<D>& container_;
  const NarrowPhase<D>& np_;
  bool planar_convex_ = false;  ///< a box or a convex polygon: the intersection of its plane walls
  /// Boundary facets of a non-convex container, by wall id, as particles of zero thickness
  /// (3D: FacetShape; 2D: radius-0 spherocylinders), built once.
  std::vector<Particle<D>> facets_;
  mutable std::vector<Wall<D>> near_;
};

}  // namespace fp
