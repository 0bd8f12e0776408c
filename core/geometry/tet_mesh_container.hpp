#pragma once
// A tetrahedral mesh as a container: read from a Gmsh .msh file (msh_reader.hpp),
// checked (tet_mesh_check.hpp), and bounded by its boundary faces (those of one tetrahedron,
// turned outwards), which make the MeshContainer every packer, check and figure uses; the mesh
// itself is kept, in the container's local frame, for the packers that follow it (fill/).
#include <memory>
#include <optional>
#include <string>

#include "core/geometry/mesh_container.hpp"
#include "core/geometry/tet_mesh.hpp"

namespace fp {

struct TetMeshContainer {
  std::shared_ptr<MeshContainer> container;
  std::shared_ptr<const TetMesh> mesh;  ///< nodes relative to container->origin()
};

/// Reads `path`, coordinates times `scale`, in its own local frame (frame_origin of its bounds)
/// unless `origin` is given. Throws std::invalid_argument naming the file and what is wrong (a
/// reader error with its line or byte, an inverted, flat or non-conforming element, an empty
/// named volume).
TetMeshContainer read_tet_mesh_container(const std::string& path, double scale = 1.0,
                                         const std::optional<Vec3>& origin = std::nullopt);

}  // namespace fp
