// The checks a tetrahedral mesh passes before a packing: Gmsh's meshes pass; an
// inverted or flat tetrahedron, overlapping elements, a hanging node, an empty named volume and a
// mesh without tetrahedra are each refused, naming the element or nodes.
#include "core/geometry/tet_mesh_check.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/geometry/msh_reader.hpp"

namespace fp {
namespace {

TetMesh mesh_of(const std::vector<Vec3>& nodes, const std::vector<std::array<std::uint32_t, 4>>& tets) {
  TetMesh m;
  m.nodes = nodes;
  m.tets = tets;
  m.tet_group.assign(tets.size(), 0);
  return m;
}

void expect_problem(const TetMesh& m, const std::string& part) {
  const std::string p = tet_mesh_problem(m);
  EXPECT_NE(p.find(part), std::string::npos) << "problem '" << p << "' lacks '" << part << "'";
}

const std::vector<Vec3> kCorner = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1),
                                   Vec3(0.5, 0, 0)};

TEST(TetMeshCheck, GmshMeshesPass) {
  for (const char* name : {"two_boxes_v2.2_ascii.msh", "two_boxes_v4.1_binary.msh"}) {
    TetMesh m;
    std::string error;
    ASSERT_TRUE(read_msh(std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/meshes/msh/" + name, m, error)) << error;
    EXPECT_EQ(tet_mesh_problem(m), "") << name;
  }
  // Two tetrahedra glued on a face, one above and one below z = 0.
  EXPECT_EQ(tet_mesh_problem(mesh_of(kCorner, {{0, 1, 2, 3}, {0, 2, 1, 4}})), "");
}

TEST(TetMeshCheck, BadMeshesAreRefusedNamingTheElement) {
  expect_problem(mesh_of(kCorner, {{0, 1, 2, 3}, {0, 1, 2, 4}}), "tetrahedron 2 (nodes 1 2 3 5) is inverted");
  expect_problem(mesh_of(kCorner, {{0, 1, 5, 2}}), "tetrahedron 1 (nodes 1 2 6 3) is flat (volume 0");  // 6 on edge 1-2
  expect_problem(mesh_of({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 1e-13)}, {{0, 1, 2, 3}}), "is flat");
  // The same tetrahedron twice: every face shared, both copies on the same side.
  expect_problem(mesh_of(kCorner, {{0, 1, 2, 3}, {0, 1, 2, 3}}), "lie on the same side of it (overlapping elements)");
  std::vector<Vec3> deeper = kCorner;
  deeper.push_back(Vec3(0.2, 0.2, -2));  // node 7, below the face 1-2-3 as node 5 is
  expect_problem(mesh_of(deeper, {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 2, 1, 6}}), "belongs to three tetrahedra or more");
  // A hanging node: the face 1-2-3 above z = 0 meets two faces below, split at node 6 (0.5, 0, 0).
  expect_problem(mesh_of(kCorner, {{0, 1, 2, 3}, {0, 2, 5, 4}, {5, 2, 1, 4}}), "the mesh is not conforming");
  TetMesh ghost = mesh_of(kCorner, {{0, 1, 2, 3}});
  ghost.group_names[{3, 7}] = "ghost";
  ghost.group_names[{2, 7}] = "a surface may be empty";
  expect_problem(ghost, "the physical volume 'ghost' (7) has no tetrahedra");
  expect_problem(TetMesh{}, "no tetrahedra");
}

}  // namespace
}  // namespace fp
