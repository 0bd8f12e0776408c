// Bounded plane walls (mesh facets, polygon edges): over_face() and face_reaches() against brute
// force, barycentric coordinates and dense sampling of the circle, on the femur's facets and a
// polygon's edges. face_reaches() prunes the front's pair scans: it must never say no where a
// point of the circle lies over the face.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include "core/geometry/mesh_container.hpp"
#include "core/geometry/polygon_container.hpp"
#include "core/sampling/rng.hpp"

namespace fp {
namespace {

std::string data(const std::string& name) { return std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/meshes/" + name; }

/// Barycentric coordinates of p's foot on the plane of abc; the smallest one (< 0: outside).
double min_barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double area2 = n.squaredNorm();
  const double u = (c - b).cross(p - b).dot(n) / area2, v = (a - c).cross(p - c).dot(n) / area2;
  return std::min({u, v, 1 - u - v});
}

struct Facet {
  Wall<3> wall;
  Vec3 a, b, c;
};

std::vector<Facet> femur_facets(const MeshContainer& m) {
  std::vector<Facet> out;
  std::vector<Wall<3>> walls;
  m.walls_near(m.interior_point(), 10.0, walls);  // every facet
  for (const Wall<3>& w : walls) {
    const auto& t = m.triangles()[static_cast<std::size_t>(w.id)];
    out.push_back({w, m.vertices()[t[0]], m.vertices()[t[1]], m.vertices()[t[2]]});
  }
  return out;
}

TEST(WallFace, MeshFacetsKnowTheirTriangle) {
  const auto m = MeshContainer::from_file(data("femur.off"));
  const auto facets = femur_facets(*m);
  ASSERT_EQ(facets.size(), m->num_facets());
  Rng rng(5);
  int checked = 0;
  for (const Facet& f : facets) {
    ASSERT_EQ(f.wall.face_edges, 3);
    for (int k = 0; k < 20; ++k) {
      // A point around the facet, off its plane.
      const double u = rng.uniform(-0.5, 1.5), v = rng.uniform(-0.5, 1.5);
      const Vec3 p = f.a + u * (f.b - f.a) + v * (f.c - f.a) + rng.uniform(-0.02, 0.02) * f.wall.normal;
      const double beta = min_barycentric(p, f.a, f.b, f.c);
      if (std::abs(beta) < 1e-9) continue;
      EXPECT_EQ(f.wall.over_face(p, 0.0), beta > 0) << "facet " << f.wall.id;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100000);
}

TEST(WallFace, CircleReachesTheFacetWheneverOneOfItsPointsIsOverIt) {
  const auto m = MeshContainer::from_file(data("femur.off"));
  const auto facets = femur_facets(*m);
  Rng rng(9);
  int agree = 0, total = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Facet& f = facets[static_cast<std::size_t>(rng.uniform(0, double(facets.size())))];
    const Vec3 e1 = (f.b - f.a).normalized(), e2 = f.wall.normal.cross(e1);
    const double size = (f.b - f.a).norm();
    const Vec3 q = f.a + rng.uniform(-2, 2) * size * e1 + rng.uniform(-2, 2) * size * e2;
    const double rho = rng.uniform(0, 2.5) * size;
    bool brute = false;
    for (int s = 0; s < 4096 && !brute; ++s) {
      const double phi = 2 * M_PI * s / 4096;
      brute = min_barycentric(q + rho * (std::cos(phi) * e1 + std::sin(phi) * e2), f.a, f.b, f.c) >= 0;
    }
    const bool reaches = f.wall.face_reaches(q, rho, 1e-12 * size);
    if (brute) ASSERT_TRUE(reaches) << "a point of the circle is over facet " << f.wall.id << " but face_reaches says no";
    agree += brute == reaches;
    ++total;
  }
  // The other way only near tangency, where 4,096 samples can miss the touching point.
  EXPECT_GT(agree, 0.995 * total);
}

TEST(WallFace, PolygonEdgesKnowTheirSegment) {
  const PolygonContainer l_shape({{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}});
  std::vector<Wall<2>> walls;
  l_shape.walls_near(Vec2(2, 2), 100.0, walls);
  Rng rng(3);
  int planes = 0;
  for (const Wall<2>& w : walls) {
    if (w.kind != WallKind::Plane) continue;
    ++planes;
    ASSERT_EQ(w.face_edges, 2);
    const Vec2 a = w.face[0].start, b = w.face[1].start;
    for (int k = 0; k < 200; ++k) {
      const double t = rng.uniform(-0.5, 1.5);
      const Vec2 p = a + t * (b - a) + rng.uniform(-1, 1) * w.normal;
      if (std::abs(t) < 1e-9 || std::abs(t - 1) < 1e-9) continue;
      EXPECT_EQ(w.over_face(p, 0.0), t >= 0 && t <= 1);
      // In 2D the "circle" is the two points at distance rho along the line.
      const Vec2 q = a + rng.uniform(-1, 2) * (b - a);
      const double rho = rng.uniform(0, 3);
      const Vec2 e = (b - a).normalized();
      const bool brute = w.over_face(q + rho * e, 0.0) || w.over_face(q - rho * e, 0.0);
      EXPECT_EQ(w.face_reaches(q, rho, 0.0), brute) << "edge " << w.id;
    }
  }
  EXPECT_EQ(planes, 6);
}

}  // namespace
}  // namespace fp
