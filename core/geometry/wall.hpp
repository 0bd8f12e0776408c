#pragma once
// A container wall seen as a body a particle can touch. The contact solvers never see the
// container itself, only the few walls near the front particle, as loci of centres.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "core/geometry/vec.hpp"

namespace fp {

enum class WallKind {
  Plane,     ///< half-space boundary; `normal` points into the container (a box face, a mesh facet, a polygon edge line)
  Sphere,    ///< inside of a sphere (3D) or disk (2D) of `radius` around `point` (the particle is inside)
  Cylinder,  ///< inside of an infinite circular cylinder: axis through `point` along unit `axis`, `radius` (3D only)
  Vertex,    ///< a convex-to-the-particle point (reflex corner of a polygon/mesh): a ball of radius 0, particle outside
};

/// One edge of a bounded Plane wall (a mesh facet's side, a polygon edge's end): the points p of
/// the face satisfy normal . p <= offset. `normal` lies in the wall's plane, so a point off the
/// plane is tested by its foot.
template <int D>
struct FaceEdge {
  Vec<D> normal = Vec<D>::Zero();  ///< unit, in the plane, out of the face
  double offset = 0.0;
  Vec<D> start = Vec<D>::Zero();   ///< the corner the edge starts from (corners in order around the face)
};

template <int D>
struct Wall {
  WallKind kind = WallKind::Plane;
  Vec<D> point = Vec<D>::Zero();  ///< Plane: a point on it; Sphere: centre; Cylinder: point on axis; Vertex: the point
  Vec<D> normal = Vec<D>::Zero(); ///< Plane: unit normal into the container
  Vec<D> axis = Vec<D>::Zero();   ///< Cylinder: unit axis
  double radius = 0.0;            ///< Sphere / Cylinder radius
  int id = -1;                    ///< container-local wall id (face index, edge index, ...), for reports
  /// Plane: the face a contact must lie over (a mesh facet, a polygon edge), as its edges, owned
  /// by the container; none (the default): the whole plane (a box face).
  const FaceEdge<D>* face = nullptr;
  int face_edges = 0;

  static Wall plane(const Vec<D>& p, const Vec<D>& inward_unit_normal, int id = -1) {
    Wall w; w.kind = WallKind::Plane; w.point = p; w.normal = inward_unit_normal; w.id = id; return w;
  }
  /// This plane bounded to a face (the container owns the edges and outlives the wall).
  template <std::size_t N>
  Wall over(const std::array<FaceEdge<D>, N>& edges) const {
    Wall w = *this; w.face = edges.data(); w.face_edges = static_cast<int>(N); return w;
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

  /// Plane: p's foot on it.
  Vec<D> foot(const Vec<D>& p) const { return p - normal.dot(p - point) * normal; }

  /// Plane: the points at `height` over it and at distance `reach` from c have their feet on a
  /// circle around c's foot (two points in 2D): its radius, or -1 if there are none. A mobile
  /// touching a ball around c (reach: the two radii) and this plane (height: the mobile's
  /// support towards it) has its reference point there.
  double feet_radius(const Vec<D>& c, double height, double reach) const {
    const double above = normal.dot(c - point) - height;
    if (std::abs(above) > reach * (1 + 1e-9)) return -1.0;
    return std::sqrt(std::max((reach - above) * (reach + above), 0.0));
  }

  /// Plane: whether p's foot on the plane lies over the face, within `slack` of its edges. A
  /// particle tangent to the plane elsewhere touches the plane but not this wall.
  bool over_face(const Vec<D>& p, double slack) const {
    for (int k = 0; k < face_edges; ++k)
      if (face[k].normal.dot(p) > face[k].offset + slack) return false;
    return true;
  }

  /// Plane with a face: whether the face holds a point at distance rho from q (q on the plane:
  /// the circle of radius rho around q in 3D, the two points q +- rho along the line in 2D), within
  /// `slack`. The face is connected: it does iff its nearest point is within rho and its farthest
  /// corner beyond. A mobile ball touching a sphere and the plane has its foot on such a circle.
  bool face_reaches(const Vec<D>& q, double rho, double slack) const {
    double farthest2 = 0.0;
    for (int k = 0; k < face_edges; ++k) farthest2 = std::max(farthest2, (face[k].start - q).squaredNorm());
    const double lo = rho + slack, hi = std::max(rho - slack, 0.0);
    return farthest2 >= hi * hi && face_distance2(q) <= lo * lo;
  }

  /// Plane with a face: the squared distance from q (on the plane) to the face.
  double face_distance2(const Vec<D>& q) const {
    if (over_face(q, 0.0)) return 0.0;
    double nearest2 = std::numeric_limits<double>::infinity();
    for (int k = 0; k < face_edges; ++k) {
      const Vec<D>& a = face[k].start;
      const Vec<D> ab = face[(k + 1) % face_edges].start - a;
      const double len2 = ab.squaredNorm();
      const double t = len2 > 0.0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
      nearest2 = std::min(nearest2, (a + t * ab - q).squaredNorm());
    }
    return nearest2;
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
