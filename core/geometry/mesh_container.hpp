#pragma once
// A closed triangle surface (3D) read from STL / OFF / OBJ. Inside test, distances and the
// facet search run on CGAL structures hidden behind a pimpl (see mesh_cgal.hpp); this header
// is CGAL-free.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/local_frame.hpp"

namespace fp {

namespace detail {
class TriangleSurfaceIndex;
class MeshCells;
}

class MeshContainer final : public Container<3> {
 public:
  /// Reads an .off, .obj or .stl (ascii or binary) file; coordinates are multiplied by `scale`.
  /// Faces with more than 3 vertices are fan-triangulated (right for convex faces).
  /// Throws std::invalid_argument, naming the file, if it cannot be read or the surface is empty,
  /// open ("mesh 'x.off' is not closed: 12 boundary edges"), non-manifold (edges shared by more
  /// than 2 facets), not orientable, or encloses no volume.
  /// With FrameChoice::Local the mesh is stored in its own local frame (frame_origin of its
  /// bounds), as a scene does; with Absolute, origin 0.
  /// An explicit `origin` overrides the choice.
  static std::shared_ptr<MeshContainer> from_file(const std::string& path, double scale = 1.0,
                                                  FrameChoice frame = FrameChoice::Absolute,
                                                  const std::optional<Vec3>& origin = std::nullopt);
  /// Same checks for a surface given in code (absolute vertices, stored relative to `origin`);
  /// `name` is used in messages and describe().
  static std::shared_ptr<MeshContainer> from_triangles(std::vector<Vec3> vertices,
                                                       std::vector<std::array<int, 3>> triangles,
                                                       const std::string& name = "triangles",
                                                       const Vec3& origin = Vec3::Zero());
  ~MeshContainer() override;

  /// Closed: points on the surface are inside.
  bool inside(const Vec3& p) const override;
  /// Distance to the closest surface point (AABB tree), negative inside.
  double signed_distance(const Vec3& p) const override;
  Aabb<3> bounds() const override { return box_; }
  /// Enclosed volume (divergence theorem over the outward-oriented facets).
  double measure() const override { return volume_; }
  /// The facets within reach of p, as Plane walls: point = the facet's first vertex,
  /// normal = its inward unit normal, id = facet index. (Facets of zero area are skipped.)
  void walls_near(const Vec3& p, double reach, std::vector<Wall<3>>& out) const override;
  /// A deep inside point (grid search + local polish), computed once at load.
  Vec3 interior_point() const override { return interior_; }
  std::string describe() const override;
  /// Same answer as the default (signed distance based) but stops at the first facet closer
  /// than the radius instead of finding the nearest one.
  bool contains_ball(const Vec3& c, double r, double rel_tol = 1e-9) const override;

  /// Builds the cell index for queries up to `reach` (the largest particle): points deep inside
  /// or outside are then answered by their cell, those near the surface from a short list of
  /// facets, exactly as the tree answers them (mesh_cells.hpp); the rest by the tree. Call it
  /// before queries run concurrently.
  void prepare_queries(double reach) const override;
  /// The cell index's size (0 without one): cells and facet listings.
  std::array<std::size_t, 2> cell_index_size() const;

  std::size_t num_facets() const { return triangles_.size(); }
  /// Vertices (duplicates merged, scaled, in the local frame) and facets oriented with outward normals.
  const std::vector<Vec3>& vertices() const { return vertices_; }
  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }
  /// Facets dropped at load because two of their corners were the same vertex.
  int dropped_degenerate_facets() const { return dropped_degenerate_; }

 private:
  MeshContainer(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> triangles, std::string name,
                const Vec3& origin);

  std::string name_;
  std::vector<Vec3> vertices_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<Vec3> inward_;  ///< unit inward normal per facet (zero for zero-area facets)
  std::vector<std::array<FaceEdge<3>, 3>> sides_;  ///< per facet: its three edges, as a bounded wall
  std::unique_ptr<detail::TriangleSurfaceIndex> index_;
  mutable std::unique_ptr<const detail::MeshCells> cells_;  ///< prepare_queries(): a cache, not state
  Aabb<3> box_;
  double volume_ = 0.0;
  Vec3 interior_ = Vec3::Zero();
  int dropped_degenerate_ = 0;
};

}  // namespace fp
