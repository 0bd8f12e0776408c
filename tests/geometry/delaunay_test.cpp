// The Delaunay tetrahedra of paper 000's step 7b (CGAL): against brute force, every circumsphere
// is empty; a lattice's cells tile its box; the same cells whatever the input order; a point
// given twice keeps its first index; too few or coplanar points give none. The same for the
// triangles of 2D.
#include "core/geometry/delaunay_cgal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include <Eigen/Dense>

#include "core/sampling/rng.hpp"

namespace fp {
namespace {

double volume(const std::vector<Vec3>& p, const std::array<std::uint32_t, 4>& t) {
  return (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).dot(p[t[3]] - p[t[0]]) / 6.0;
}

// Centre of the sphere through the tetrahedron's four vertices.
Vec3 circumcentre(const std::vector<Vec3>& p, const std::array<std::uint32_t, 4>& t) {
  Eigen::Matrix3d A;
  Vec3 b;
  for (int i = 1; i < 4; ++i) {
    const Vec3 d = p[t[static_cast<std::size_t>(i)]] - p[t[0]];
    A.row(i - 1) = 2 * d.transpose();
    b[i - 1] = d.squaredNorm();
  }
  return p[t[0]] + A.fullPivLu().solve(b);
}

std::vector<Vec3> random_points(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Vec3> p(n);
  for (Vec3& x : p) x = Vec3(rng.uniform01(), rng.uniform01(), rng.uniform01());
  return p;
}

std::set<std::array<std::uint32_t, 4>> as_set(std::vector<std::array<std::uint32_t, 4>> tets) {
  std::set<std::array<std::uint32_t, 4>> s;
  for (auto t : tets) {
    std::sort(t.begin(), t.end());
    s.insert(t);
  }
  return s;
}

TEST(Delaunay, EveryCircumsphereIsEmptyAndEveryCellPositive) {
  const std::vector<Vec3> p = random_points(300, 1);
  const auto tets = delaunay_tetrahedra(p);
  ASSERT_GT(tets.size(), 1000u);
  for (const auto& t : tets) {
    EXPECT_GT(volume(p, t), 0);
    const Vec3 c = circumcentre(p, t);
    const double r = (p[t[0]] - c).norm();
    for (std::size_t k = 0; k < p.size(); ++k)
      EXPECT_GE((p[k] - c).norm(), r * (1 - 1e-9)) << "point " << k << " inside a circumsphere";
  }
  EXPECT_EQ(delaunay_tetrahedra(p), tets);  // reruns give the same list
}

TEST(Delaunay, ALatticeTilesItsBoxAndOrderDoesNotMatter) {
  std::vector<Vec3> lattice;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) lattice.emplace_back(i, j, k);
  const auto tets = delaunay_tetrahedra(lattice);
  double sum = 0;
  for (const auto& t : tets) sum += volume(lattice, t);
  EXPECT_NEAR(sum, 27.0, 1e-12);
  // Points in general position have one Delaunay triangulation: the same cells in any order.
  const std::vector<Vec3> p = random_points(200, 2);
  std::vector<std::uint32_t> perm(p.size());
  std::iota(perm.begin(), perm.end(), 0u);
  Rng rng(3);
  for (std::size_t k = perm.size() - 1; k > 0; --k) std::swap(perm[k], perm[static_cast<std::size_t>(rng.uniform01() * static_cast<double>(k + 1))]);
  std::vector<Vec3> shuffled(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) shuffled[k] = p[perm[k]];
  auto back = delaunay_tetrahedra(shuffled);
  for (auto& t : back)
    for (std::uint32_t& v : t) v = perm[v];
  EXPECT_EQ(as_set(back), as_set(delaunay_tetrahedra(p)));
}

TEST(Delaunay, DuplicatesFewAndCoplanarPoints) {
  std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 0, 0)};
  const auto tets = delaunay_tetrahedra(p);
  ASSERT_EQ(tets.size(), 1u);
  for (const std::uint32_t v : tets[0]) EXPECT_LT(v, 4u);  // the copy of point 1 is point 1
  EXPECT_TRUE(delaunay_tetrahedra({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}).empty());
  EXPECT_TRUE(delaunay_tetrahedra({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 3, 0)}).empty());
  EXPECT_TRUE(delaunay_tetrahedra({}).empty());
}

TEST(Delaunay, TrianglesIn2DAreEmptyCirclesCounterClockwiseAndTileTheHull) {
  Rng rng(4);
  std::vector<Vec2> p(400);
  for (Vec2& x : p) x = Vec2(rng.uniform01(), rng.uniform01());
  const auto tris = delaunay_triangles(p);
  ASSERT_GT(tris.size(), 700u);  // 2n - 2 - hull
  for (const auto& t : tris) {
    const Vec2 a = p[t[1]] - p[t[0]], b = p[t[2]] - p[t[0]];
    EXPECT_GT(a.x() * b.y() - a.y() * b.x(), 0);
    // Circumcentre: 2 d_i . c = |d_i|^2 relative to the first vertex.
    Eigen::Matrix2d A;
    A.row(0) = 2 * a.transpose();
    A.row(1) = 2 * b.transpose();
    const Vec2 c = p[t[0]] + A.fullPivLu().solve(Vec2(a.squaredNorm(), b.squaredNorm()));
    const double r = (p[t[0]] - c).norm();
    for (std::size_t k = 0; k < p.size(); ++k)
      if (k != t[0] && k != t[1] && k != t[2]) EXPECT_GT((p[k] - c).norm(), r * (1 - 1e-12));
  }
  // A 5 x 5 lattice (cocircular squares: any diagonal) tiles its 4 x 4 square.
  std::vector<Vec2> lattice;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) lattice.emplace_back(i, j);
  double area = 0;
  for (const auto& t : delaunay_triangles(lattice)) {
    const Vec2 a = lattice[t[1]] - lattice[t[0]], b = lattice[t[2]] - lattice[t[0]];
    area += (a.x() * b.y() - a.y() * b.x()) / 2;
  }
  EXPECT_NEAR(area, 16.0, 1e-12);
  EXPECT_TRUE(delaunay_triangles({Vec2(0, 0), Vec2(1, 1), Vec2(2, 2)}).empty());
  const auto dup = delaunay_triangles({Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(1, 0)});
  ASSERT_EQ(dup.size(), 1u);
  for (const std::uint32_t v : dup[0]) EXPECT_LT(v, 3u);
}

}  // namespace
}  // namespace fp
