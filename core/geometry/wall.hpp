#pragma once
// A container wall seen as a body a particle can touch. The contact solvers never see the
// container itself, only the few walls near the front particle, as loci of centres.
#include "core/geometry/vec.hpp"

namespace fp {

enum class WallKind {
  Plane,     ///< half-space boundary; `normal` points into the container (a box face, a mesh facet, a polygon edge line)
  Sphere,    ///< inside of a sphere (3D) or disk (2D) of `radius` around `point` (the particle is inside)
  Cylinder,  ///< inside of an infinite circular cylinder: axis through `point` along unit `axis`, `radius` (3D only)
  Vertex,    ///< a convex-to-the-particle point (reflex corner of a polygon/mesh): a ball of radius 0, particle outside
};

template <int D>
struct Wall {
  WallKind kind = WallKind::Plane;
  Vec<D> point = Vec<D>::Zero();  ///< Plane: a point on it; Sphere: centre; Cylinder: point on axis; Vertex: the point
  Vec<D> normal = Vec<D>::Zero(); ///< Plane: unit normal into the container
  Vec<D> axis = Vec<D>::Zero();   ///< Cylinder: unit axis
  double radius = 0.0;            ///< Sphere / Cylinder radius
  int id = -1;                    ///< container-local wall id (face index, edge index, ...), for reports

  static Wall plane(const Vec<D>& p, const Vec<D>& inward_unit_normal, int id = -1) {
    Wall w; w.kind = WallKind::Plane; w.point = p; w.normal = inward_unit_normal; w.id = id; return w;
  }
  static Wall sphere(const Vec<D>& c, double r, int id = -1) {
    Wall w; w.kind = WallKind::Sphere; w.point = c; w.radius = r; w.id = id; return w;
  }
  static Wall cylinder(const Vec<D>& p, const Vec<D>& unit_axis, double r, int id = -1) {
    Wall w; w.kind = WallKind::Cylinder; w.point = p; w.axis = unit_axis; w.radius = r; w.id = id; return w;
  }
  static Wall vertex(const Vec<D>& p, int id = -1) {
    Wall w; w.kind = WallKind::Vertex; w.point = p; w.id = id; return w;
  }

  /// Signed gap between this wall and a ball (c, r) on the container side: 0 = tangent, < 0 = overlap.
  double gap(const Vec<D>& c, double r) const {
    switch (kind) {
      case WallKind::Plane: return normal.dot(c - point) - r;
      case WallKind::Sphere: return radius - (c - point).norm() - r;
      case WallKind::Cylinder: {
        Vec<D> d = c - point;
        return radius - (d - d.dot(axis) * axis).norm() - r;
      }
      case WallKind::Vertex: return (c - point).norm() - r;
    }
    return 0.0;
  }
};

}  // namespace fp
