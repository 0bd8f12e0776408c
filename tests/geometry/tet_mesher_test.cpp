// The tetrahedral mesher (core/geometry/tet_mesher_cgal.hpp, CGAL Mesh_3): a unit cube meshed at
// two edge lengths gives positive, conforming tetrahedra filling the cube (their volumes sum to
// it within the corners' rounding), edges of about the size asked, all nodes inside; about 8
// times the tetrahedra at half the edge; the same mesh on a second call.
#include "core/geometry/tet_mesher_cgal.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/tet_mesh_check.hpp"

namespace fp {
namespace {

const std::vector<Vec3> kCube = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0),
                                 Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(1, 1, 1)};
const std::vector<std::array<int, 3>> kFaces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};

TEST(TetMesher, ACubeBecomesConformingTetrahedraOfTheAskedSize) {
  const TetMesh coarse = mesh_tetrahedra(kCube, kFaces, 0.25), fine = mesh_tetrahedra(kCube, kFaces, 0.125);
  for (const TetMesh* m : {&coarse, &fine}) {
    EXPECT_EQ(tet_mesh_problem(*m, false), "");
    double volume = 0, edges = 0;
    int count = 0;
    for (std::size_t t = 0; t < m->tets.size(); ++t) {
      volume += tet_volume(*m, t);
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j, ++count) edges += (m->nodes[m->tets[t][i]] - m->nodes[m->tets[t][j]]).norm();
    }
    EXPECT_NEAR(volume, 1.0, 0.05) << m->tets.size() << " tetrahedra";
    EXPECT_LE(volume, 1.0 + 1e-9) << "inside the cube";
    for (const Vec3& p : m->nodes) EXPECT_TRUE((p.array() >= -1e-9).all() && (p.array() <= 1 + 1e-9).all()) << p.transpose();
    const double mean = edges / count, size = m == &coarse ? 0.25 : 0.125;
    EXPECT_GT(mean, 0.4 * size);
    EXPECT_LT(mean, 1.5 * size);
  }
  const double ratio = static_cast<double>(fine.tets.size()) / static_cast<double>(coarse.tets.size());
  EXPECT_GT(ratio, 4.0);
  EXPECT_LT(ratio, 14.0);
  const TetMesh again = mesh_tetrahedra(kCube, kFaces, 0.25);
  EXPECT_EQ(again.nodes, coarse.nodes);
  EXPECT_EQ(again.tets, coarse.tets);
}

TEST(TetMesher, RefusesWhatItCannotMesh) {
  EXPECT_THROW(mesh_tetrahedra(kCube, kFaces, 0.0), std::invalid_argument);
  std::vector<std::array<int, 3>> twice = kFaces;
  twice.push_back(kFaces[0]);  // a face given twice: not a manifold
  EXPECT_THROW(mesh_tetrahedra(kCube, twice, 0.25), std::invalid_argument);
}

}  // namespace
}  // namespace fp
