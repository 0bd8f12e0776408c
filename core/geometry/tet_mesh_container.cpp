#include "core/geometry/tet_mesh_container.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/local_frame.hpp"
#include "core/geometry/msh_reader.hpp"
#include "core/geometry/tet_mesh_check.hpp"

namespace fp {
namespace {

/// The faces of one tetrahedron, each turned away from the tetrahedron's fourth node.
std::vector<std::array<int, 3>> boundary_faces(const TetMesh& mesh) {
  std::map<std::array<std::uint32_t, 3>, std::pair<int, std::array<int, 3>>> seen;  // sorted face -> (count, oriented)
  for (const auto& t : mesh.tets) {
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      int k = 0;
      for (int i = 0; i < 4; ++i)
        if (i != skip) f[static_cast<std::size_t>(k++)] = static_cast<int>(t[static_cast<std::size_t>(i)]);
      const Vec3 &a = mesh.nodes[static_cast<std::size_t>(f[0])], &b = mesh.nodes[static_cast<std::size_t>(f[1])],
                 &c = mesh.nodes[static_cast<std::size_t>(f[2])], &opposite = mesh.nodes[t[static_cast<std::size_t>(skip)]];
      if ((b - a).cross(c - a).dot(opposite - a) > 0) std::swap(f[1], f[2]);
      std::array<std::uint32_t, 3> key = {static_cast<std::uint32_t>(f[0]), static_cast<std::uint32_t>(f[1]),
                                          static_cast<std::uint32_t>(f[2])};
      std::sort(key.begin(), key.end());
      auto [it, fresh] = seen.try_emplace(key, 0, f);
      ++it->second.first;
    }
  }
  std::vector<std::array<int, 3>> faces;
  for (const auto& [key, entry] : seen)
    if (entry.first == 1) faces.push_back(entry.second);
  return faces;
}

}  // namespace

TetMeshContainer read_tet_mesh_container(const std::string& path, double scale, const std::optional<Vec3>& origin) {
  auto mesh = std::make_shared<TetMesh>();
  std::string error;
  if (!read_msh(path, *mesh, error)) throw std::invalid_argument("mesh file '" + path + "': " + error);
  for (Vec3& p : mesh->nodes) p *= scale;
  if (const std::string problem = tet_mesh_problem(*mesh); !problem.empty())
    throw std::invalid_argument("mesh file '" + path + "': " + problem);
  Aabb<3> box;
  for (const Vec3& p : mesh->nodes) box.extend(p);
  const Vec3 o = origin.value_or(frame_origin<3>(box));
  TetMeshContainer out;
  out.container = MeshContainer::from_triangles(mesh->nodes, boundary_faces(*mesh), path, o);
  for (Vec3& p : mesh->nodes) p -= o;
  out.mesh = std::move(mesh);
  return out;
}

}  // namespace fp
