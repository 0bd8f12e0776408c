#include "core/geometry/tet_mesh_check.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

namespace fp {
namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
}

}  // namespace

std::string tet_mesh_problem(const TetMesh& mesh, bool boundary_closes) {
  if (mesh.tets.empty()) return "the mesh has no tetrahedra (element type 4)";
  // Orientation and flatness.
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& n = mesh.tets[t];
    const Vec3 &a = mesh.nodes[n[0]], &b = mesh.nodes[n[1]], &c = mesh.nodes[n[2]], &d = mesh.nodes[n[3]];
    const double volume = (b - a).cross(c - a).dot(d - a) / 6.0;
    double longest = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) longest = std::max(longest, (mesh.nodes[n[i]] - mesh.nodes[n[j]]).norm());
    const std::string which = "tetrahedron " + std::to_string(t + 1) + " (nodes " + std::to_string(n[0] + 1) + " " +
                              std::to_string(n[1] + 1) + " " + std::to_string(n[2] + 1) + " " + std::to_string(n[3] + 1) + ")";
    if (volume < 0) return which + " is inverted (negative volume " + std::to_string(volume) + ")";
    if (!(volume > 1e-12 * longest * longest * longest)) return which + " is flat (volume " + std::to_string(volume) + ")";
  }
  // Conformity: each face (by its sorted nodes) counted, with the orientation each tetrahedron
  // gives it outwards (+1 or -1 against the sorted order): two tetrahedra sharing a face lie on
  // its two sides, so their orientations cancel. Then the boundary's edges, counted.
  struct FaceUse {
    int count = 0, orientation = 0;
  };
  std::map<std::array<std::uint32_t, 3>, FaceUse> faces;
  for (const auto& n : mesh.tets)
    for (const auto& face : kTetOutwardFaces) {
      std::array<std::uint32_t, 3> f = {n[static_cast<std::size_t>(face[0])], n[static_cast<std::size_t>(face[1])],
                                        n[static_cast<std::size_t>(face[2])]};
      const int inversions = (f[0] > f[1]) + (f[0] > f[2]) + (f[1] > f[2]);
      std::sort(f.begin(), f.end());
      FaceUse& use = faces[f];
      use.orientation += inversions % 2 ? -1 : 1;
      const std::string nodes = std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1);
      if (++use.count > 2) return "the face of nodes " + nodes + " belongs to three tetrahedra or more (overlapping elements)";
      if (use.count == 2 && use.orientation != 0)
        return "the two tetrahedra of the face of nodes " + nodes + " lie on the same side of it (overlapping elements)";
    }
  std::unordered_map<std::uint64_t, int> boundary_edges;
  for (const auto& [f, use] : faces)
    if (use.count == 1 && boundary_closes)
      for (int i = 0; i < 3; ++i) ++boundary_edges[edge_key(f[static_cast<std::size_t>(i)], f[static_cast<std::size_t>((i + 1) % 3)])];
  std::uint64_t worst = 0;
  bool bad = false;
  for (const auto& [edge, count] : boundary_edges)
    if (count != 2 && (!bad || edge < worst)) worst = edge, bad = true;  // the smallest, for a stable message
  if (bad)
    return "the mesh is not conforming: the boundary edge of nodes " + std::to_string((worst >> 32) + 1) + " " +
           std::to_string((worst & 0xffffffffu) + 1) + " is on " + std::to_string(boundary_edges.at(worst)) +
           " boundary faces, not 2 (a hanging node, a crack or a gap between elements)";
  // Named volumes hold tetrahedra.
  std::set<int> used(mesh.tet_group.begin(), mesh.tet_group.end());
  for (const auto& [key, name] : mesh.group_names)
    if (key.first == 3 && !used.count(key.second))
      return "the physical volume '" + name + "' (" + std::to_string(key.second) + ") has no tetrahedra";
  return "";
}

}  // namespace fp
