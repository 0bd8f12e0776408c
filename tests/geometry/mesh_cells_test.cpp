// The mesh container's cell index (prepare_queries): every answer equal to the AABB tree's, bit
// for bit, on the femur and on a cube whose facets lie on the grid's planes, near the surface,
// on it, deep inside and outside, at every reach the index is asked about and beyond; and the
// same when the scene is scaled by 2^+-60 or far from the origin.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <set>

#include "core/geometry/mesh_container.hpp"
#include "core/sampling/rng.hpp"

namespace fp {
namespace {

std::string data(const std::string& name) { return std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/meshes/" + name; }

std::set<int> wall_ids(const MeshContainer& m, const Vec3& p, double reach) {
  std::vector<Wall<3>> walls;
  m.walls_near(p, reach, walls);
  std::set<int> ids;
  for (const Wall<3>& w : walls) ids.insert(w.id);
  return ids;
}

/// Points that stress the index: uniform in the padded box, near facets (just off, on, and at
/// a random height within a few reaches), at corners of facets, and at the cells' own sample
/// offsets along grid planes.
std::vector<Vec3> probe_points(const MeshContainer& m, double reach, Rng& rng, int count) {
  std::vector<Vec3> points;
  const Aabb<3> b = m.bounds();
  const Vec3 pad = Vec3::Constant(3 * reach);
  const auto& v = m.vertices();
  for (int k = 0; k < count; ++k) {
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = rng.uniform(b.lo[a] - pad[a], b.hi[a] + pad[a]);
    points.push_back(p);
    const auto& t = m.triangles()[static_cast<std::size_t>(rng.uniform(0, double(m.num_facets())))];
    const double u = rng.uniform01(), w = rng.uniform01() * (1 - u);
    const Vec3 on = v[t[0]] + u * (v[t[1]] - v[t[0]]) + w * (v[t[2]] - v[t[0]]);
    const Vec3 n = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized();
    points.push_back(on);
    points.push_back(on + rng.uniform(-3, 3) * reach * n);
    points.push_back(on + 1e-12 * reach * n);
    points.push_back(v[t[k % 3]]);
  }
  return points;
}

/// Every query of the indexed container against the plain one.
void expect_same_answers(const MeshContainer& plain, const MeshContainer& indexed, double reach, std::uint64_t seed,
                         int count) {
  Rng rng(seed);
  int mismatches = 0;
  for (const Vec3& p : probe_points(plain, reach, rng, count)) {
    if (plain.inside(p) != indexed.inside(p)) ++mismatches;
    if (plain.signed_distance(p) != indexed.signed_distance(p)) ++mismatches;
    for (const double r : {0.1 * reach, 0.5 * reach, reach, 2 * reach, 3.5 * reach})
      for (const double tol : {0.0, 1e-9})
        if (plain.contains_ball(p, r, tol) != indexed.contains_ball(p, r, tol)) ++mismatches;
    for (const double r : {reach, 3 * reach})
      if (wall_ids(plain, p, r) != wall_ids(indexed, p, r)) ++mismatches;
    if (mismatches > 0) {
      ADD_FAILURE() << "indexed and plain queries differ at " << p.transpose();
      return;
    }
  }
}

TEST(MeshCells, FemurAnswersAsTheTreeDoes) {
  const auto plain = MeshContainer::from_file(data("femur.off"));
  const auto indexed = MeshContainer::from_file(data("femur.off"));
  indexed->prepare_queries(0.01);
  ASSERT_GT(indexed->cell_index_size()[0], 0u) << "no cell index was built";
  EXPECT_EQ(plain->cell_index_size()[0], 0u);
  expect_same_answers(*plain, *indexed, 0.01, 1, 4000);
}

TEST(MeshCells, AnyReachAnswersAsTheTreeDoes) {
  // Cells far larger than the facets, about as large, and far smaller (capped in number).
  for (const double reach : {0.2, 0.03, 0.002}) {
    const auto plain = MeshContainer::from_file(data("femur.off"));
    const auto indexed = MeshContainer::from_file(data("femur.off"));
    indexed->prepare_queries(reach);
    expect_same_answers(*plain, *indexed, reach, 7, 150);
  }
}

TEST(MeshCells, CubeWithFacetsOnGridPlanesAnswersAsTheTreeDoes) {
  // [0, 20]^3 with cells of 1.5: facets on the cells' faces and samples on the diagonals.
  const auto plain = MeshContainer::from_file(data("cube.stl"), 20.0);
  const auto indexed = MeshContainer::from_file(data("cube.stl"), 20.0);
  indexed->prepare_queries(1.0);
  ASSERT_GT(indexed->cell_index_size()[0], 0u);
  expect_same_answers(*plain, *indexed, 1.0, 3, 2000);
  // Points on the grid: integers and halves, on the faces, edges and corners of the cube.
  for (double x = -1; x <= 21; x += 0.5)
    for (double y : {-0.5, 0.0, 0.75, 10.0, 20.0})
      for (double z : {0.0, 1.5, 19.25, 20.0, 20.5}) {
        const Vec3 p(x, y, z);
        ASSERT_EQ(plain->inside(p), indexed->inside(p)) << p.transpose();
        ASSERT_EQ(plain->signed_distance(p), indexed->signed_distance(p)) << p.transpose();
        ASSERT_EQ(plain->contains_ball(p, 1.0, 1e-9), indexed->contains_ball(p, 1.0, 1e-9)) << p.transpose();
      }
}

TEST(MeshCells, ScaledAndFarScenesAnswerAsTheTreeDoes) {
  for (const double scale : {0x1p-60, 0x1p60}) {
    const auto plain = MeshContainer::from_file(data("femur.off"), scale);
    const auto indexed = MeshContainer::from_file(data("femur.off"), scale);
    indexed->prepare_queries(0.01 * scale);
    ASSERT_GT(indexed->cell_index_size()[0], 0u);
    expect_same_answers(*plain, *indexed, 0.01 * scale, 11, 400);
  }
  const Vec3 far(1e9, -1e9, 1e9);
  const auto plain = MeshContainer::from_file(data("femur.off"), 1.0, FrameChoice::Local, far);
  const auto indexed = MeshContainer::from_file(data("femur.off"), 1.0, FrameChoice::Local, far);
  indexed->prepare_queries(0.01);
  expect_same_answers(*plain, *indexed, 0.01, 13, 400);
}

TEST(MeshCells, SecondPreparationAtAnotherReachStillAnswersAlike) {
  const auto plain = MeshContainer::from_file(data("femur.off"));
  const auto indexed = MeshContainer::from_file(data("femur.off"));
  indexed->prepare_queries(0.01);
  const auto first = indexed->cell_index_size();
  indexed->prepare_queries(0.01);  // same reach: kept
  EXPECT_EQ(indexed->cell_index_size(), first);
  indexed->prepare_queries(0.05);  // rebuilt for the new scale
  EXPECT_NE(indexed->cell_index_size(), first);
  expect_same_answers(*plain, *indexed, 0.05, 17, 400);
}

}  // namespace
}  // namespace fp
