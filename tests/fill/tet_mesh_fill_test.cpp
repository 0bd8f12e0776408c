// The tetrahedral-mesh fill of paper 000 (fill/tet_mesh_fill.hpp, steps 2-7a) on a jittered
// Kuhn cube (tests/data/meshes/msh/cube_kuhn4.msh, 384 tetrahedra) and on the two-region box
// Gmsh wrote, checked by brute force: no overlap beyond epsilon r_min, every sphere inside the
// cube, radii in [r_min, r_max]; the edge spheres of step 2 at the edge midpoints with l / 8;
// every sphere of steps 4-6 with z_min contacts; loose skips steps 5 and 6; phi0 and N0 stop it;
// reruns are byte-identical; the same cube scaled by 2^+-60 gives the same spheres scaled.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>

#include "core/geometry/tet_mesh_container.hpp"
#include "fill/tet_mesh_fill.hpp"
#include "tests/front/front_checks.hpp"

namespace fptest {
namespace {

using fp::Packing;
using fp::TetFillOptions;

const std::string kCube = std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/meshes/msh/cube_kuhn4.msh";

/// A mean edge of the jittered cube of about 0.33: radii about l / 8 as the paper sizes them.
fp::Scene cube_scene(double scale = 1.0, const std::string& extra = "") {
  char text[600];
  std::snprintf(text, sizeof text,
                "dimension: 3\nseed: 3\ncontainer: {type: mesh, file: %s, scale: %.17g}\n"
                "particles: {radius: {distribution: uniform, min: %.17g, max: %.17g}}\npacker: {method: tet_mesh}\n%s",
                kCube.c_str(), scale, 0.012 * scale, 0.084 * scale, extra.c_str());
  return scene_from_yaml(text);
}

struct Filled {
  Packing<3> packing;
  fp::TetFillReport report;
};

Filled fill(const fp::Scene& scene, const TetFillOptions& o) {
  Filled f;
  f.report = fp::fill_tet_mesh(*scene.tet_mesh, *scene.container3, *scene.radii, o, scene.seed, 1e-9, f.packing);
  return f;
}

TEST(TetMeshFill, StepsTwoToSevenAFillTheCubeWithoutOverlap) {
  const fp::Scene scene = cube_scene();
  ASSERT_TRUE(scene.tet_mesh);
  EXPECT_EQ(scene.tet_mesh->tets.size(), 384u);
  const Filled f = fill(scene, TetFillOptions{});
  const auto sd = box_distance<3>(Vec3(0, 0, 0), Vec3(1, 1, 1));
  expect_valid<3>(f.packing, sd, 0.012, 0.084, "cube");
  const fp::TetFillReport& r = f.report;
  EXPECT_EQ(r.tets, 384u);
  EXPECT_EQ(r.nodes, 125u);
  EXPECT_EQ(static_cast<long>(r.nodes) - static_cast<long>(r.edges) + static_cast<long>(r.faces) - static_cast<long>(r.tets), 1)
      << "Euler: V - E + F - T = 1 for a ball";
  EXPECT_GT(r.edge_spheres, r.edges / 2);
  EXPECT_GT(r.face_spheres, 0u);
  EXPECT_GT(r.tet_spheres, 0u);
  EXPECT_GT(r.midway_spheres, 0u);
  EXPECT_GT(r.removed_boundary, 0u) << "spheres at boundary nodes and edges stick out";
  EXPECT_EQ(f.packing.size(), r.edge_spheres + r.node_spheres + r.face_spheres + r.tet_spheres + r.midway_spheres -
                                  r.removed_boundary);
  // Paper: N about 10 N_t, phi below 0.55, after step 6 (before the boundary cut: somewhat fewer here).
  EXPECT_GT(f.packing.size(), 5u * 384u);
  double solid = 0;
  for (const double x : f.packing.radii) solid += 4.0 / 3.0 * std::numbers::pi * x * x * x;
  EXPECT_GT(solid, 0.35);
  EXPECT_LT(solid, 0.60);
}

TEST(TetMeshFill, EdgeSpheresSitAtMidpointsWithAnEighthOfTheEdge) {
  const fp::Scene scene = cube_scene();
  const Filled f = fill(scene, TetFillOptions{});
  // Every edge of the mesh whose l / 8 is in range has its midpoint sphere, radius l / 8 or reduced.
  const fp::TetMesh& m = *scene.tet_mesh;
  std::size_t exact = 0, found = 0;
  for (const auto& t : m.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Vec3 a = m.nodes[t[static_cast<std::size_t>(i)]], b = m.nodes[t[static_cast<std::size_t>(j)]];
        const double l8 = (b - a).norm() / 8;
        if (l8 < 0.012 || l8 > 0.084) continue;
        for (std::size_t k = 0; k < f.packing.size(); ++k)
          if ((f.packing.centers[k] - (a + b) / 2).norm() < 1e-12) {
            ++found;
            EXPECT_LE(f.packing.radii[k], l8 * (1 + 1e-12));
            exact += f.packing.radii[k] == l8;
            break;
          }
      }
  EXPECT_GT(found, 300u);
  EXPECT_GT(exact, found * 3 / 4) << "most midpoint spheres keep l / 8";
}

TEST(TetMeshFill, GeometricProcedureSpheresHaveZMinContacts) {
  for (const int z_min : {2, 3, 4}) {
    TetFillOptions o;
    o.z_min = z_min;
    const Filled f = fill(cube_scene(), o);
    EXPECT_GT(f.report.face_spheres + f.report.tet_spheres + f.report.midway_spheres, 500u) << "z_min " << z_min;
    // The spheres of steps 4-6 follow those of steps 2-3 (7a keeps the order). Those deeper than
    // their radius plus 2 r_max lost no neighbour in 7a: they touch at least z_min spheres
    // (counted by brute force; later spheres only add contacts).
    const std::vector<int> z = particle_contacts<3>(f.packing, 1e-9);
    const auto sd = box_distance<3>(Vec3(0, 0, 0), Vec3(1, 1, 1));
    std::size_t deep = 0;
    for (std::size_t i = f.report.mesh_spheres_kept; i < f.packing.size(); ++i) {
      if (sd(f.packing.centers[i], f.packing.origin) > -(f.packing.radii[i] + 2 * 0.084)) continue;
      ++deep;
      EXPECT_GE(z[i], z_min) << "sphere " << i << ", z_min " << z_min;
    }
    EXPECT_GT(deep, 100u);
  }
}

TEST(TetMeshFill, LooseSkipsStepsFiveAndSix) {
  TetFillOptions o;
  o.loose = true;
  const Filled loose = fill(cube_scene(), o), dense = fill(cube_scene(), TetFillOptions{});
  EXPECT_EQ(loose.report.tet_spheres, 0u);
  EXPECT_EQ(loose.report.midway_spheres, 0u);
  EXPECT_LT(loose.packing.size(), dense.packing.size());
}

TEST(TetMeshFill, AllowedOverlapStaysWithinEpsilonRMin) {
  TetFillOptions o;
  o.overlap = 0.1;
  const Filled f = fill(cube_scene(), o);
  const OverlapReport ov = overlaps<3>(f.packing);
  const double smallest = *std::min_element(f.packing.radii.begin(), f.packing.radii.end());
  EXPECT_LE(ov.max_over_rmin * smallest, 0.1 * 0.012 * (1 + 1e-9));
  EXPECT_GT(ov.max_over_rmin * smallest, 0.01 * 0.012) << "the allowance is used";
}

TEST(TetMeshFill, StopsAtPhi0AndN0) {
  TetFillOptions o;
  o.max_particles = 1000;
  const Filled n = fill(cube_scene(), o);
  EXPECT_TRUE(n.report.reached_target);
  EXPECT_LE(n.packing.size(), 1000u);  // 7a removes some of the 1,000
  o.max_particles.reset();
  o.target_volume_fraction = 0.2;
  const Filled phi = fill(cube_scene(), o);
  EXPECT_TRUE(phi.report.reached_target);
  EXPECT_EQ(phi.report.midway_spheres, 0u) << "stopped before step 6";
}

TEST(TetMeshFill, RerunsAreByteIdenticalAndScaledMeshesGiveScaledSpheres) {
  const Filled a = fill(cube_scene(), TetFillOptions{}), b = fill(cube_scene(), TetFillOptions{});
  ASSERT_EQ(a.packing.size(), b.packing.size());
  EXPECT_EQ(0, std::memcmp(a.packing.centers.data(), b.packing.centers.data(), a.packing.size() * sizeof(Vec3)));
  EXPECT_EQ(0, std::memcmp(a.packing.radii.data(), b.packing.radii.data(), a.packing.size() * sizeof(double)));
  for (const int e : {-60, 60}) {
    const double s = std::ldexp(1.0, e);
    const Filled f = fill(cube_scene(s), TetFillOptions{});
    ASSERT_EQ(f.packing.size(), a.packing.size()) << e;
    for (std::size_t i = 0; i < f.packing.size(); ++i) {
      ASSERT_EQ(f.packing.radii[i], a.packing.radii[i] * s) << e << " sphere " << i;
      ASSERT_EQ(f.packing.centers[i], a.packing.centers[i] * s) << e << " sphere " << i;
    }
  }
}

}  // namespace
}  // namespace fptest
