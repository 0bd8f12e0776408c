// Fuzz harness of the MSH reader (core/geometry/msh_reader.hpp: Gmsh's versions 2.2 and 4.1,
// ASCII and binary). Property: read_msh returns true, or false with a message (never throws, no
// C++ internals in it); a mesh it accepts has every element's node index in range, one group per
// element, and finite nodes, and tet_mesh_problem judges it without throwing.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/geometry/msh_reader.hpp"
#include "core/geometry/tet_mesh_check.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using fp::fuzz::require;
  if (size > fp::fuzz::kMaxInputBytes) size = fp::fuzz::kMaxInputBytes;
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::string path = fp::fuzz::write_scratch_file("x.msh", data, size);
  fp::TetMesh mesh;
  std::string error;
  bool ok = false;
  try {
    ok = fp::read_msh(path, mesh, error);
  } catch (...) {
    fp::fuzz::unexpected_exception("read_msh");
  }
  if (!ok) {
    fp::fuzz::check_error_message(error, input, "read_msh");
    return 0;
  }
  require(mesh.tet_group.size() == mesh.tets.size(), "a group per tetrahedron");
  require(mesh.triangle_group.size() == mesh.triangles.size(), "a group per triangle");
  for (const auto& t : mesh.tets)
    for (const std::uint32_t n : t) require(n < mesh.nodes.size(), "a tetrahedron's node index out of range");
  for (const auto& t : mesh.triangles)
    for (const std::uint32_t n : t) require(n < mesh.nodes.size(), "a triangle's node index out of range");
  for (const auto& x : mesh.nodes) require(x.allFinite(), "a node that is not finite");
  try {
    const std::string problem = fp::tet_mesh_problem(mesh);
    if (!problem.empty()) fp::fuzz::check_error_message(problem, input, "tet_mesh_problem");
  } catch (...) {
    fp::fuzz::unexpected_exception("tet_mesh_problem");
  }
  return 0;
}
