#pragma once
// A tetrahedral mesh as frontpack uses it (paper 000's packing of a finite-element
// mesh): nodes, linear tetrahedra and the triangles the file lists (boundary or interface
// faces), each with the physical group it belongs to, and the groups' names.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/vec.hpp"

namespace fp {

struct TetMesh {
  std::vector<Vec3> nodes;
  std::vector<std::array<std::uint32_t, 4>> tets;       ///< node indices (0-based), as the file orders them
  std::vector<int> tet_group;                           ///< physical group tag per tet (0: none)
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< node indices (0-based)
  std::vector<int> triangle_group;                      ///< physical group tag per triangle (0: none)
  /// (dimension, tag) -> name, for the physical groups the file names.
  std::map<std::pair<int, int>, std::string> group_names;
};

/// The faces of a positively oriented tetrahedron (node 3 on the side the right-hand normal of
/// 0-1-2 points to), by their nodes' places in it, each turned outwards.
inline constexpr int kTetOutwardFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

/// The volume of tetrahedron t.
inline double tet_volume(const TetMesh& mesh, std::size_t t) {
  const auto& v = mesh.tets[t];
  const Vec3& a = mesh.nodes[v[0]];
  return std::abs((mesh.nodes[v[1]] - a).cross(mesh.nodes[v[2]] - a).dot(mesh.nodes[v[3]] - a)) / 6.0;
}

}  // namespace fp
