#pragma once
// Which tetrahedron of a mesh holds a point: a uniform grid over the mesh's bounds (cells of
// about the mean edge), each cell listing the tetrahedra whose bounding boxes meet it; a point is
// tested against its cell's list by barycentric coordinates. Used to give a point the physical
// region of the tetrahedron it lies in (regions of their own radii and solid fraction).
#include <array>
#include <cstdint>
#include <vector>

#include "core/geometry/tet_mesh.hpp"
#include "core/geometry/vec.hpp"

namespace fp {

class TetLocator {
 public:
  explicit TetLocator(const TetMesh& mesh);
  /// The tetrahedron holding p (within 1e-12 of its size; on a shared face the lower index), or
  /// -1 outside the mesh.
  int tet_at(const Vec3& p) const;

 private:
  const TetMesh& mesh_;
  Vec3 lo_ = Vec3::Zero();
  double cell_ = 1.0;
  std::array<std::int64_t, 3> n_{1, 1, 1};
  std::vector<std::uint32_t> start_;  ///< per cell, its first entry in `tets_` (CSR)
  std::vector<std::uint32_t> tets_;
};

}  // namespace fp
