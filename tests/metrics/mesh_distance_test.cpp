// The validator's own mesh distance (mesh_distance.hpp, point_triangle.hpp) against references
// that share nothing with it: tests/geometry's point-triangle distance and a generalized winding
// number (sum of solid angles) over every triangle. Random points, points 1e-12 off faces, edges
// and vertices of the femur (where a face-normal sign is ambiguous), sharp and reflex edges with
// known answers, rays through edges and vertices of the cube and the octahedron, and the time to
// validate ~6000 spheres in the femur.
#include "core/metrics/mesh_distance.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/geometry/mesh_container.hpp"
#include "core/metrics/point_triangle.hpp"
#include "core/metrics/validate.hpp"
#include "core/sampling/rng.hpp"
#include "tests/geometry/reference_geometry.hpp"
#include "tests/metrics/analysis_test_util.hpp"

namespace fp {
namespace {

using Tris = std::vector<std::array<int, 3>>;

// Generalized winding number: (1 / 4 pi) sum of the signed solid angles of the triangles seen
// from p (Van Oosterom & Strackee); ~1 inside, ~0 outside a closed outward surface.
double winding_number(const std::vector<Vec3>& v, const Tris& tris, const Vec3& p) {
  double total = 0.0;
  for (const auto& t : tris) {
    const Vec3 a = v[t[0]] - p, b = v[t[1]] - p, c = v[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(num, den);
  }
  return total / (4.0 * kPi);
}

// The reference signed distance: brute-force distance, sign by the winding number.
double reference_sd(const std::vector<Vec3>& v, const Tris& tris, const Vec3& p) {
  const double d = testref::mesh_distance(v, tris, p);
  return winding_number(v, tris, p) > 0.5 ? -d : d;
}

TEST(PointTriangle, MatchesTheReferenceDistanceAndLiesOnTheTriangle) {
  Rng rng(5);
  auto rnd = [&] { return Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)); };
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a = rnd(), b = rnd(), c = i % 10 == 0 ? Vec3(a + 1e-3 * (b - a) + 1e-9 * rnd()) : rnd();  // some slivers
    const Vec3 p = 2.0 * rnd();
    const TriangleClosest q = closest_on_triangle(p, a, b, c);
    EXPECT_NEAR(q.distance, testref::triangle_distance(p, a, b, c), 1e-14);
    EXPECT_NEAR((p - q.point).norm(), q.distance, 1e-14);
    const Vec3 n = (b - a).cross(c - a);
    if (q.feature.kind == TriangleFeature::Face) {
      EXPECT_NEAR((q.point - a).dot(n.normalized()), 0.0, 1e-14);
    }
    if (q.feature.kind == TriangleFeature::Vertex) {
      EXPECT_EQ(q.point, (q.feature.index == 0 ? a : q.feature.index == 1 ? b : c));
    }
  }
  // Degenerate: three collinear points are their segments.
  const TriangleClosest s = closest_on_triangle(Vec3(0.5, 1, 0), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0));
  EXPECT_DOUBLE_EQ(s.distance, 1.0);
  EXPECT_NE(s.feature.kind, TriangleFeature::Face);
}

class FemurDistance : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    mesh_ = MeshContainer::from_file(test::mesh_path("femur.off"));
    dist_ = std::make_unique<MeshDistance>(mesh_->vertices(), mesh_->triangles());
  }
  static void TearDownTestSuite() {
    dist_.reset();
    mesh_.reset();
  }
  static double diag() { return mesh_->bounds().size().norm(); }
  static Vec3 random_point(Rng& rng) {
    const Aabb<3> b = mesh_->bounds();
    const Vec3 pad = 0.05 * b.size();
    return Vec3(rng.uniform(b.lo.x() - pad.x(), b.hi.x() + pad.x()), rng.uniform(b.lo.y() - pad.y(), b.hi.y() + pad.y()),
                rng.uniform(b.lo.z() - pad.z(), b.hi.z() + pad.z()));
  }
  static std::shared_ptr<MeshContainer> mesh_;
  static std::unique_ptr<MeshDistance> dist_;
};
std::shared_ptr<MeshContainer> FemurDistance::mesh_;
std::unique_ptr<MeshDistance> FemurDistance::dist_;

TEST_F(FemurDistance, RandomPointsMatchBruteForceTheReferenceAndTheContainer) {
  Rng rng(61);
  const auto& v = mesh_->vertices();
  const auto& t = mesh_->triangles();
  int inside = 0;
  double worst_ref = 0.0, worst_container = 0.0;
  for (int i = 0; i < 200; ++i) {
    const Vec3 p = random_point(rng);
    const double sd = dist_->signed_distance(p);  // unbounded reach: exact everywhere
    const double ref = reference_sd(v, t, p);
    EXPECT_EQ(sd < 0, ref < 0) << p.transpose();
    worst_ref = std::max(worst_ref, std::abs(sd - ref));
    worst_container = std::max(worst_container, std::abs(sd - mesh_->signed_distance(p)));
    // The grid search finds what brute force over its own primitive finds, bit for bit.
    const double reach = 0.05 * diag();
    const double near = dist_->signed_distance(p, reach);
    if (std::abs(sd) <= reach) {
      EXPECT_EQ(near, sd);
    } else if (sd < 0) {
      EXPECT_EQ(near, -reach);
    } else {
      EXPECT_EQ(near, sd);
    }
    EXPECT_EQ(std::abs(sd), dist_->distance_brute_force(p));
    inside += sd < 0;
  }
  EXPECT_GT(inside, 10);  // the femur fills ~10 % of its padded box
  EXPECT_LT(worst_ref, 1e-15 * diag()) << worst_ref;
  EXPECT_LT(worst_container, 1e-15 * diag()) << worst_container;
  std::printf("[ info     ] femur: %d / 200 inside; |sd - reference| <= %.2g, |sd - container| <= %.2g (diag %.3g)\n",
              inside, worst_ref, worst_container, diag());
}

// 1e-12 diag off the middle of faces, the midpoints of edges and the vertices, on both sides
// (along the face normal, the mean normal of the edge, the angle-weighted vertex normal): the
// sign must be the winding number's and the distance brute force's. A sign from the face normal
// of a nearest triangle is ambiguous at edges and vertices (several triangles are nearest); this
// check has one answer.
TEST_F(FemurDistance, PointsWithin1e12OfFacesEdgesAndVertices) {
  const auto& v = mesh_->vertices();
  const auto& t = mesh_->triangles();
  const double delta = 1e-12 * diag();
  Rng rng(62);
  int checked = 0, container_wrong = 0, naive_wrong = 0;
  std::vector<Vec3> vertex_normal(v.size(), Vec3::Zero());
  for (const auto& T : t) {
    const Vec3 n = (v[T[1]] - v[T[0]]).cross(v[T[2]] - v[T[0]]).normalized();
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = v[T[(k + 1) % 3]] - v[T[k]], b = v[T[(k + 2) % 3]] - v[T[k]];
      vertex_normal[T[k]] += std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * n;
    }
  }
  for (int i = 0; i < 150; ++i) {
    const auto& T = t[rng.below(t.size())];
    const Vec3 n = (v[T[1]] - v[T[0]]).cross(v[T[2]] - v[T[0]]).normalized();
    const int kind = i % 3;
    Vec3 q, dir;
    if (kind == 0) {  // face centre
      q = (v[T[0]] + v[T[1]] + v[T[2]]) / 3.0;
      dir = n;
    } else if (kind == 1) {  // edge midpoint, along the mean of the two face normals
      q = 0.5 * (v[T[0]] + v[T[1]]);
      Vec3 other = Vec3::Zero();
      for (const auto& U : t)
        for (int k = 0; k < 3; ++k)
          if (U[k] == T[1] && U[(k + 1) % 3] == T[0]) other = (v[U[1]] - v[U[0]]).cross(v[U[2]] - v[U[0]]).normalized();
      dir = (n + other).normalized();
    } else {  // vertex
      q = v[T[0]];
      dir = vertex_normal[T[0]].normalized();
    }
    for (const double side : {-1.0, 1.0}) {
      const Vec3 p = q + side * delta * dir;
      const double ref = reference_sd(v, t, p);
      const double sd = dist_->signed_distance(p, 0.01 * diag());
      ++checked;
      EXPECT_EQ(sd < 0, ref < 0) << "kind " << kind << " side " << side << " p " << p.transpose();
      EXPECT_NEAR(sd, ref, 1e-16 * diag() + 1e-3 * delta);
      container_wrong += (mesh_->signed_distance(p) < 0) != (ref < 0);
      // Naive: the face normal of every triangle at the nearest distance; wrong if any disagrees.
      const double d = testref::mesh_distance(v, t, p);
      bool wrong = false;
      for (const auto& U : t)
        if (testref::triangle_distance(p, v[U[0]], v[U[1]], v[U[2]]) <= d * (1 + 1e-9)) {
          const Vec3 m = (v[U[1]] - v[U[0]]).cross(v[U[2]] - v[U[0]]);
          wrong |= ((p - v[U[0]]).dot(m) < 0) != (ref < 0);
        }
      naive_wrong += wrong;
    }
  }
  std::printf("[ info     ] femur, %d points 1e-12 diag off faces/edges/vertices: container sign wrong %d, "
              "nearest-face-normal sign wrong %d, this check 0\n",
              checked, container_wrong, naive_wrong);
}

// A regular tetrahedron: dihedral angle 70.5 deg, so 1e-12 off an edge along one face's normal
// (tilted a little toward the other face, so that the nearest point is on the edge) is outside,
// while the other face's normal says inside. The edge pseudo-normal gets it right.
TEST(MeshDistanceSharp, TetrahedronEdgesAndVertices) {
  const std::vector<Vec3> v = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  const Tris t = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};  // outward
  const MeshDistance m(v, t);
  int naive_wrong = 0, checked = 0;
  for (const auto& T : t) {
    const Vec3 n1 = (v[T[1]] - v[T[0]]).cross(v[T[2]] - v[T[0]]).normalized();
    for (int k = 0; k < 3; ++k) {
      const int a = T[k], b = T[(k + 1) % 3];
      Vec3 n2 = Vec3::Zero();  // the face across edge a-b
      for (const auto& U : t)
        for (int j = 0; j < 3; ++j)
          if (U[j] == b && U[(j + 1) % 3] == a) n2 = (v[U[1]] - v[U[0]]).cross(v[U[2]] - v[U[0]]).normalized();
      const Vec3 q = 0.5 * (v[a] + v[b]);
      for (const double w : {0.9, 0.5, 0.1}) {
        const Vec3 p = q + 1e-12 * (w * n1 + (1 - w) * n2 + 0.05 * (n2 - n1) * (w - 0.5)).normalized();
        const double ref = reference_sd(v, t, p);
        ASSERT_GT(ref, 0.0);
        EXPECT_NEAR(m.signed_distance(p, 0.5), ref, 1e-17);
        EXPECT_GT(m.signed_distance(p, 0.5), 0.0);
        naive_wrong += (p - v[T[0]]).dot(n2) < 0 || (p - v[T[0]]).dot(n1) < 0;
        ++checked;
      }
    }
    for (int k = 0; k < 3; ++k) {  // vertices, both sides of the vertex normal
      const Vec3 n = v[T[k]].normalized();
      EXPECT_GT(m.signed_distance(v[T[k]] + 1e-12 * n, 0.5), 0.0);
      EXPECT_LT(m.signed_distance(v[T[k]] - 1e-12 * n, 0.5), 0.0);
      EXPECT_NEAR(m.signed_distance(v[T[k]] + 1e-12 * n, 0.5), reference_sd(v, t, v[T[k]] + 1e-12 * n), 1e-27);
    }
  }
  EXPECT_GT(naive_wrong, 0) << "the cases are not hard enough to tell a face-normal sign from this one";
  EXPECT_EQ(checked, 36);
}

// The L prism of tests/data/scenes-e2e: 1e-12 around its reflex edge x = y = 0.2, the exact
// signed distance is known: outside (the missing quadrant) the distance to the nearer of its two
// faces; inside, that of the nearer face where it is reachable, else the edge's, -delta.
TEST(MeshDistanceSharp, LPrismReflexEdge) {
  const auto mesh = MeshContainer::from_file(std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/scenes-e2e/l_prism.off");
  const MeshDistance m(mesh->vertices(), mesh->triangles());
  const double delta = 1e-12;
  for (int deg = 5; deg < 360; deg += 10) {
    const double th = deg * kPi / 180.0, c = std::cos(th), s = std::sin(th);
    const Vec3 p(0.2 + delta * c, 0.2 + delta * s, 0.15);
    double want;
    if (deg < 90) want = delta * std::min(c, s);  // the nearer of the two faces of the missing quadrant
    else if (deg < 180) want = -delta * std::abs(c);
    else if (deg < 270) want = -delta;
    else want = -delta * std::abs(s);
    EXPECT_NEAR(m.signed_distance(p, 0.05), want, 6e-17) << deg << " deg";  // 2 ulp of 0.2: p's own rounding
    EXPECT_EQ(m.signed_distance(p, 0.05) < 0, deg >= 90) << deg << " deg";
  }
}

// Rays along +x through the edges and vertices of the triangulated cube and of the octahedron
// (points on a 1/8 lattice): each crossing counted once.
TEST(MeshDistanceRay, ThroughEdgesAndVerticesCountsOnce) {
  const auto cube = MeshContainer::from_file(test::mesh_path("cube.stl"));
  const auto octa = MeshContainer::from_file(test::mesh_path("octahedron_binary.stl"));
  const MeshDistance mc(cube->vertices(), cube->triangles()), mo(octa->vertices(), octa->triangles());
  const Aabb<3> cb = cube->bounds();
  int n = 0;
  for (int i = -4; i <= 12; ++i)
    for (int j = -4; j <= 12; ++j)
      for (int k = -4; k <= 12; ++k) {
        const Vec3 u(i / 8.0, j / 8.0, k / 8.0);
        const Vec3 pc = cb.lo + u.cwiseProduct(cb.size());
        const Vec3 e = (pc - cb.lo).cwiseMin(cb.hi - pc);
        if (e.minCoeff() != 0.0 || (e.array() < 0).any()) {  // off the cube's surface
          EXPECT_EQ(mc.inside_by_ray(pc), (e.array() > 0).all()) << pc.transpose();
          EXPECT_EQ(mc.signed_distance(pc, 1e-3) < 0, (e.array() > 0).all()) << pc.transpose();
          ++n;
        }
        const Vec3 po = 2.0 * u - Vec3::Constant(0.5);  // [-1.5, 2.5]^3 in steps of 1/4
        const double l1 = po.cwiseAbs().sum();
        if (l1 != 1.0) {
          EXPECT_EQ(mo.inside_by_ray(po), l1 < 1.0) << po.transpose();
          EXPECT_NEAR(mo.signed_distance(po, 0.1), l1 < 1.0 ? std::max(-0.1, reference_sd(octa->vertices(), octa->triangles(), po))
                                                            : reference_sd(octa->vertices(), octa->triangles(), po),
                      1e-15);
          ++n;
        }
      }
  EXPECT_GT(n, 9000);
}

// ~6000 spheres in the femur (a lattice of balls inside it, r = 0.007 of the length) validate in
// well under a second.
TEST(MeshDistanceTiming, SixThousandSpheresInTheFemur) {
  const auto femur = MeshContainer::from_file(test::mesh_path("femur.off"));
  const Aabb<3> b = femur->bounds();
  const double r = 0.007 * b.size().maxCoeff();
  Packing<3> p;
  for (double x = b.lo.x(); x < b.hi.x(); x += 2.0 * r)
    for (double y = b.lo.y(); y < b.hi.y(); y += 2.0 * r)
      for (double z = b.lo.z(); z < b.hi.z(); z += 2.0 * r)
        if (femur->contains_ball(Vec3(x, y, z), r, 0.0)) p.add(Vec3(x, y, z), r);
  ASSERT_GT(p.size(), 5500u);
  const auto t0 = std::chrono::steady_clock::now();
  const ValidationReport rep = validate_packing<3>(p, *femur, nullptr);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[ perf     ] validate %zu spheres in the femur: %.3f s (grid %d x %d x %d)\n", p.size(), s,
              MeshDistance(femur->vertices(), femur->triangles()).grid_cells()[0],
              MeshDistance(femur->vertices(), femur->triangles()).grid_cells()[1],
              MeshDistance(femur->vertices(), femur->triangles()).grid_cells()[2]);
  EXPECT_TRUE(rep.ok) << rep.summary();
  EXPECT_LT(s, 1.0);
}

}  // namespace
}  // namespace fp
