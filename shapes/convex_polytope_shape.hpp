#pragma once
// Convex polygon (2D, family "polygon") / convex polyhedron (3D, family "polyhedron"): the convex
// hull of the given vertices. Its vertices are its hull balls (radius 0) and its support points,
// so containment in convex containers is exact. FCL gets an fcl::Convexd (3D) or a tall prism
// over the polygon (2D, see fcl_embedding.hpp).
#include <array>
#include <vector>

#include "shapes/shape.hpp"
#include "shapes/shape_registry.hpp"

namespace fp {

template <int D>
class ConvexPolytopeShape final : public Shape<D> {
 public:
  /// The hull in the body frame: vertices (extreme points) and facets, 2D: the edges (i, i + 1) of
  /// a counter-clockwise polygon, 3D: triangles counter-clockwise seen from outside.
  ConvexPolytopeShape(std::vector<Vec<D>> vertices, std::vector<std::array<int, D>> facets);
  /// The hull of any points (duplicates, points on faces or inside are dropped), in the same
  /// frame; throws std::invalid_argument when they span no area / volume.
  static ConvexPolytopeShape hull_of(const std::vector<Vec<D>>& points);

  static constexpr const char* kKind = D == 2 ? "polygon" : "polyhedron";
  /// A particle template's largest number of points (sides, listed vertices): building the face
  /// planes costs (vertices x faces), and every contact problem touches each face. Beyond a few
  /// hundred sides a polygon is a disk to any packing anyway.
  static constexpr int kMaxTemplatePoints = 10000;
  const std::vector<Vec<D>>& vertices() const { return vertices_; }
  const std::vector<std::array<int, D>>& facets() const { return facets_; }
  /// Centroid of the solid (the family puts the reference point there).
  Vec<D> centroid() const { return centroid_; }
  /// The distinct face planes: unit outward normals and offsets (n . x <= offset inside).
  const std::vector<Vec<D>>& plane_normals() const { return normals_; }
  const std::vector<double>& plane_offsets() const { return offsets_; }
  /// 3D: an edge between two faces of different planes (vertex indices; plane indices on either
  /// side): with the planes, the Gauss map the polytope wrapper needs.
  struct Edge {
    int a, b;
    int plane0, plane1;
  };
  const std::vector<Edge>& edges() const { return edges_; }

  const char* kind() const override { return kKind; }
  double measure() const override { return measure_; }
  double bounding_radius() const override { return bounding_; }
  /// Distance from the origin to the nearest face plane (0 if the origin is outside).
  double inscribed_radius() const override { return inscribed_; }
  Vec<D> support(const Vec<D>& u) const override;
  bool contains(const Vec<D>& x) const override;
  std::vector<Ball<D>> hull_balls() const override;
  void rounded_cores(std::vector<RoundedCore<D>>& out) const override {
    out.resize(1);
    out[0].points.assign(vertices_.begin(), vertices_.end()), out[0].radius = 0.0;
  }
  SurfaceMesh<D> surface(int resolution) const override;
  std::vector<FclPart<D>> fcl_parts() const override;
  ShapePtr<D> scaled(double s) const override;
  std::string definition_json() const override;

 private:
  std::vector<Vec<D>> vertices_;
  std::vector<std::array<int, D>> facets_;
  std::vector<Vec<D>> normals_;  ///< unit outward normals of the distinct face planes
  std::vector<double> offsets_;  ///< n . x <= offset inside
  std::vector<int> facet_plane_; ///< per facet: its plane
  std::vector<Edge> edges_;      ///< 3D only
  Vec<D> centroid_ = Vec<D>::Zero();
  double measure_ = 0.0, bounding_ = 0.0, inscribed_ = 0.0;
};

/// "polygon" (2D) / "polyhedron" (3D): `vertices` (D-points, hull taken), or 2D `sides: n` (regular
/// n-gon), or 3D `platonic: 4 | 6 | 8 | 12 | 20` (the Platonic solid with that many faces). The
/// reference point is the centroid of the solid; the prototype has circumscribed radius 1.
/// Dimensions: circumscribed_radius, inscribed_radius, equivalent_radius.
template <int D>
ShapePrototype<D> convex_polytope_prototype(const ShapeParameters& p);

}  // namespace fp
