#include "core/geometry/tet_mesh_container.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/geometry/local_frame.hpp"
#include "core/geometry/msh_reader.hpp"
#include "core/geometry/tet_mesh_check.hpp"

namespace fp {
namespace {

/// The faces of one tetrahedron, turned outwards (tet_mesh_problem has checked every tetrahedron
/// positive), in the order of their sorted nodes.
std::vector<std::array<int, 3>> boundary_faces(const TetMesh& mesh) {
  std::map<std::array<std::uint32_t, 3>, std::pair<int, std::array<int, 3>>> seen;  // sorted face -> (count, outward)
  for (const auto& t : mesh.tets)
    for (const auto& face : kTetOutwardFaces) {
      std::array<int, 3> f{};
      for (int k = 0; k < 3; ++k) f[static_cast<std::size_t>(k)] = static_cast<int>(t[static_cast<std::size_t>(face[k])]);
      std::array<std::uint32_t, 3> key = {t[static_cast<std::size_t>(face[0])], t[static_cast<std::size_t>(face[1])],
                                          t[static_cast<std::size_t>(face[2])]};
      std::sort(key.begin(), key.end());
      ++seen.try_emplace(key, 0, f).first->second.first;
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
