#include "contact/shape_containment.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <limits>

#include "core/geometry/bed_region.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/mesh_container.hpp"
#include "core/geometry/polygon_container.hpp"
#include "shapes/facet_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace fp {

template <int D>
ShapeContainment<D>::ShapeContainment(const Container<D>& container, const NarrowPhase<D>& narrow_phase)
    : container_(container), np_(narrow_phase) {
  // A bed: the facets are its container's. A flat surface is a wall plane; a free one is not
  // among the walls, so the hull balls decide against the signed distance (which has the plane).
  const Container<D>* walled = &container;
  bool walls_bound_it = true;
  if (const auto* bed = dynamic_cast<const BedRegion<D>*>(&container))
    walled = &bed->base(), walls_bound_it = bed->surface() == BedSurface::Flat;
  planar_convex_ = dynamic_cast<const BoxContainer<D>*>(walled) != nullptr && walls_bound_it;
  if constexpr (D == 3) {
    if (const auto* mesh = dynamic_cast<const MeshContainer*>(walled))  // any mesh may be non-convex
      for (const auto& t : mesh->triangles()) {
        const std::array<Vec3, 3> v = {mesh->vertices()[static_cast<std::size_t>(t[0])],
                                       mesh->vertices()[static_cast<std::size_t>(t[1])],
                                       mesh->vertices()[static_cast<std::size_t>(t[2])]};
        Particle<3> f;
        f.pose.position = (v[0] + v[1] + v[2]) / 3.0;
        f.shape = std::make_shared<FacetShape>(std::array<Vec3, 3>{v[0] - f.pose.position, v[1] - f.pose.position,
                                                                   v[2] - f.pose.position});
        facets_.push_back(std::move(f));
      }
  } else {
    if (const auto* poly = dynamic_cast<const PolygonContainer*>(walled)) {
      const auto& v = poly->vertices();
      const int n = static_cast<int>(v.size());
      bool convex = true;
      for (int i = 0; i < n; ++i) convex &= !poly->is_reflex(i);
      planar_convex_ = convex && walls_bound_it;
      if (!convex)
        for (int i = 0; i < n; ++i) {  // an edge is a spherocylinder of radius 0
          const Vec2 a = v[static_cast<std::size_t>(i)], b = v[static_cast<std::size_t>((i + 1) % n)];
          Particle<2> f;
          f.shape = std::make_shared<SpherocylinderShape<2>>(0.5 * (b - a).norm(), 0.0);
          f.pose.position = 0.5 * (a + b);
          f.pose.rotation = rotation_2d(std::atan2(b.y() - a.y(), b.x() - a.x()));
          facets_.push_back(std::move(f));
        }
    }
  }
}

template <int D>
double ShapeContainment<D>::protrusion(const Particle<D>& p) const {
  double beyond = -std::numeric_limits<double>::infinity();
  if (planar_convex_) {
    // The container is the intersection of its wall half-spaces: the protrusion is the largest
    // beyond any wall, exact through the support function (a curved shape's hull balls
    // circumscribe it by up to 0.5 % of a semi-axis, which kept ellipsoids off every wall).
    near_.clear();
    container_.walls_near(p.pose.position, std::numeric_limits<double>::infinity(), near_);
    for (const Wall<D>& w : near_)
      if (w.kind == WallKind::Plane) beyond = std::max(beyond, -np_.gap(w, p).value);
    return beyond;
  }
  for (const Ball<D>& b : p.shape->hull_balls())
    beyond = std::max(beyond, container_.signed_distance(p.pose.to_world(b.center)) + b.radius);
  if (facets_.empty() || beyond > 0) return beyond;
  // Facets within reach of the particle (walls_near gives Plane walls whose id is the facet).
  near_.clear();
  container_.walls_near(p.pose.position, p.bounding_radius(), near_);
  for (const Wall<D>& w : near_) {
    if (w.kind != WallKind::Plane || w.id < 0 || static_cast<std::size_t>(w.id) >= facets_.size()) continue;
    const double g = np_.gap(facets_[static_cast<std::size_t>(w.id)], p).value;
    beyond = std::max(beyond, -g);
  }
  return beyond;
}

template class ShapeContainment<2>;
template class ShapeContainment<3>;

}  // namespace fp
