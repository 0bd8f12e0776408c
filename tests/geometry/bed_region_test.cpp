// BedRegion: a container cut at a fill height, against closed forms worked out by hand and
// against Monte Carlo over the container's own inside test.
#include "core/geometry/bed_region.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/cylinder_container.hpp"
#include "core/geometry/mesh_container.hpp"
#include "core/geometry/polygon_container.hpp"
#include "core/sampling/rng.hpp"
#include "tests/geometry/reference_geometry.hpp"

namespace fp {
namespace {

/// The measure of {x in base : up . x <= level} by Monte Carlo in the base's bounds, and the
/// estimate's standard deviation.
template <int D>
std::pair<double, double> monte_carlo_below(const Container<D>& base, const Vec<D>& up, double level, int n = 400000) {
  Rng rng(7);
  const Aabb<D> b = base.bounds();
  const double box = b.size().prod();
  int hits = 0;
  for (int i = 0; i < n; ++i) {
    Vec<D> p;
    for (int a = 0; a < D; ++a) p[a] = rng.uniform(b.lo[a], b.hi[a]);
    hits += base.inside(p) && up.normalized().dot(p) <= level ? 1 : 0;
  }
  const double f = static_cast<double>(hits) / n;
  return {box * f, box * std::sqrt(f * (1 - f) / n)};
}

/// A unit cube [0, 1]^3 as a closed triangle surface, outward.
std::shared_ptr<MeshContainer> cube_mesh() {
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const std::vector<std::array<int, 3>> t = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                             {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return MeshContainer::from_triangles(v, t, "unit cube");
}

TEST(BedRegion, BoxFilledAlongAnAxisIsTheShorterBox) {
  const auto box = std::make_shared<const BoxContainer<3>>(Vec3(0, 0, 0), Vec3(2, 3, 5));
  const BedRegion<3> bed(box, Vec3(0, 0, 7), 1.25, BedSurface::Free);  // any length of up
  EXPECT_DOUBLE_EQ(bed.measure(), 2 * 3 * 1.25);
  EXPECT_DOUBLE_EQ(bed.floor_level(), 0.0);
  EXPECT_DOUBLE_EQ(bed.level(), 1.25);
  EXPECT_DOUBLE_EQ(bed.bounds().hi.z(), 1.25);
  EXPECT_DOUBLE_EQ(bed.measure_up_to(0.5), 3.0);
  // Inside, the distance to the shorter box's boundary.
  const BoxContainer<3> shorter(Vec3(0, 0, 0), Vec3(2, 3, 1.25));
  Rng rng(3);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p(rng.uniform(0, 2), rng.uniform(0, 3), rng.uniform(0, 1.25));
    EXPECT_NEAR(bed.signed_distance(p), shorter.signed_distance(p), 1e-15);
    EXPECT_EQ(bed.inside(p), true);
  }
  EXPECT_FALSE(bed.inside(Vec3(1, 1, 1.3)));
  EXPECT_TRUE(bed.contains_ball(Vec3(1, 1, 1.0), 0.25));
  EXPECT_FALSE(bed.contains_ball(Vec3(1, 1, 1.01), 0.25));
  // The seed: the deepest point on the vertical through the box's centre, half way up the bed.
  EXPECT_NEAR(bed.interior_point().z(), 0.625, 1.25 / 65);
  EXPECT_NE(bed.describe().find("filled to height 1.25 along [0,0,1] (free surface)"), std::string::npos);
  // Filled past its top, it is the box.
  EXPECT_DOUBLE_EQ(BedRegion<3>(box, Vec3(0, 0, 1), 9.0, BedSurface::Free).measure(), 30.0);
}

TEST(BedRegion, ADiagonalCutHalvesACubeOfEveryKind) {
  // The plane x + y + z = 3/2 through the centre: the two halves are congruent (point symmetry).
  const Vec3 up = Vec3::Ones().normalized();
  const double half_diagonal = std::sqrt(3.0) / 2;
  const ContainerPtr<3> kinds[] = {std::make_shared<const BoxContainer<3>>(Vec3::Zero(), Vec3::Ones()), cube_mesh()};
  for (const auto& c : kinds) {
    const BedRegion<3> bed(c, up, half_diagonal, BedSurface::Free);
    EXPECT_NEAR(bed.floor_level(), 0.0, 1e-15);
    EXPECT_NEAR(bed.measure(), 0.5, 1e-14) << c->describe();
    // A third of the diagonal: the corner tetrahedron x + y + z <= 1, volume 1/6.
    EXPECT_NEAR(bed.measure_up_to(1 / std::sqrt(3.0)), 1.0 / 6, 1e-14);
  }
  const Vec2 up2 = Vec2::Ones().normalized();
  const ContainerPtr<2> squares[] = {std::make_shared<const BoxContainer<2>>(Vec2::Zero(), Vec2::Ones()),
                                     std::make_shared<const PolygonContainer>(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}})};
  for (const auto& c : squares) {
    const BedRegion<2> bed(c, up2, std::sqrt(2.0) / 2, BedSurface::Free);
    EXPECT_NEAR(bed.measure(), 0.5, 1e-15) << c->describe();
    EXPECT_NEAR(bed.measure_up_to(std::sqrt(2.0) / 4), 0.125, 1e-15);
  }
}

TEST(BedRegion, BallsDisksAndCylindersAgainstIntegralsOfTheirSections) {
  // A ball: the disks of radius sqrt(r^2 - z^2) summed by the midpoint rule (2e5 of them).
  const double r = 1.3;
  const auto ball = std::make_shared<const BallContainer<3>>(Vec3(0.2, -0.4, 1.0), r);
  const auto disk = std::make_shared<const BallContainer<2>>(Vec2(0.2, -0.4), r);
  for (const double h : {0.3, 1.3, 2.1}) {
    double ball_sum = 0, disk_sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      const double z = -r + (i + 0.5) * h / n;  // the height over the lowest point is h at most
      ball_sum += kPi * (r * r - z * z) * h / n;
      disk_sum += 2 * std::sqrt(r * r - z * z) * h / n;
    }
    const Vec3 up3 = Vec3(1, -2, 2).normalized();  // any direction: a ball is round
    EXPECT_NEAR(BedRegion<3>(ball, up3, h, BedSurface::Free).measure(), ball_sum, 1e-6 * ball_sum);
    EXPECT_NEAR(BedRegion<2>(disk, Vec2(0.6, 0.8), h, BedSurface::Flat).measure(), disk_sum, 1e-6 * disk_sum);
  }
  // A horizontal drum (axis x) filled to 0.4 of its radius: length times the circular segment.
  const auto drum = std::make_shared<const CylinderContainer>(Vec3(1, 2, 3), Vec3(1, 0, 0), 1.0, 2.5);
  const BedRegion<3> low(drum, Vec3(0, 0, 1), 0.4, BedSurface::Free);
  EXPECT_NEAR(low.floor_level(), 2.0, 1e-15);
  const double d = 0.6;  // the chord's distance from the axis
  EXPECT_NEAR(low.measure(), 2.5 * (std::acos(d) - d * std::sqrt(1 - d * d)), 1e-13);
  // Along its axis, down: a shorter cylinder.
  const BedRegion<3> down(drum, Vec3(-1, 0, 0), 1.0, BedSurface::Free);
  EXPECT_NEAR(down.measure(), kPi * 1.0, 1e-13);
  EXPECT_NEAR(down.floor_level(), -3.5, 1e-15);
}

TEST(BedRegion, TiltedCylinderAndLShapeAgainstMonteCarlo) {
  const auto cyl = std::make_shared<const CylinderContainer>(Vec3(0.3, -0.2, 0.5), Vec3(1, 2, -0.5), 0.4, 1.3);
  const Vec3 up = Vec3(0.3, -0.5, 1).normalized();
  // The lowest point lies on a rim: the minimum over both rims, sampled finely.
  const Vec3 a = Vec3(1, 2, -0.5).normalized(), e1 = a.unitOrthogonal(), e2 = a.cross(e1);
  double rim_low = 1e300;
  for (int k = 0; k < 200000; ++k) {
    const double phi = 2 * kPi * k / 200000;
    for (const double t : {0.0, 1.3})
      rim_low = std::min(rim_low, up.dot(Vec3(0.3, -0.2, 0.5) + t * a + 0.4 * (std::cos(phi) * e1 + std::sin(phi) * e2)));
  }
  for (const double h : {0.2, 0.6, 1.0}) {
    const BedRegion<3> bed(cyl, up, h, BedSurface::Free);
    EXPECT_NEAR(bed.floor_level(), rim_low, 1e-9);
    const auto [mc, sd] = monte_carlo_below<3>(*cyl, up, bed.level());
    EXPECT_NEAR(bed.measure(), mc, 4 * sd) << "h " << h;
  }
  // An L-shaped polygon (non-convex, area 5), by hand: along x, the column x < 1 is 3 high and
  // the foot beyond it 1 high; along y, the foot is 3 wide and the column above it 1 wide.
  const auto ell = std::make_shared<const PolygonContainer>(std::vector<Vec2>{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}});
  EXPECT_NEAR(BedRegion<2>(ell, Vec2(1, 0), 0.5, BedSurface::Free).measure(), 1.5, 1e-15);
  EXPECT_NEAR(BedRegion<2>(ell, Vec2(1, 0), 2.0, BedSurface::Free).measure(), 4.0, 1e-15);
  EXPECT_NEAR(BedRegion<2>(ell, Vec2(0, 1), 2.0, BedSurface::Free).measure(), 4.0, 1e-15);
  const Vec2 slant = Vec2(1, 2).normalized();
  const BedRegion<2> slanted(ell, slant, 1.7, BedSurface::Free);
  const auto [mc, sd] = monte_carlo_below<2>(*ell, slant, slanted.level());
  EXPECT_NEAR(slanted.measure(), mc, 4 * sd);
  EXPECT_TRUE(slanted.inside(slanted.interior_point()));
}

TEST(BedRegion, AFlatSurfaceIsAWallAndAFreeOneIsNot) {
  const auto box = std::make_shared<const BoxContainer<3>>(Vec3(0, 0, 0), Vec3(1, 1, 1));
  for (const BedSurface s : {BedSurface::Free, BedSurface::Flat}) {
    const BedRegion<3> bed(box, Vec3(0, 0, 1), 0.5, s);
    std::vector<Wall<3>> walls;
    bed.walls_near(Vec3(0.5, 0.5, 0.45), 0.1, walls);  // 0.05 under the level, far from the box's walls
    if (s == BedSurface::Free) {
      EXPECT_TRUE(walls.empty());
    } else {
      ASSERT_EQ(walls.size(), 1u);
      EXPECT_EQ(walls[0].id, BedRegion<3>::kLidWall);
      EXPECT_NEAR((walls[0].normal - Vec3(0, 0, -1)).norm(), 0.0, 1e-15);
      EXPECT_NEAR(walls[0].normal.dot(Vec3(0.5, 0.5, 0.45) - walls[0].point), 0.05, 1e-15);
    }
  }
}

TEST(BedRegion, RefusesWhatIsNoBed) {
  const auto box = std::make_shared<const BoxContainer<3>>(Vec3(0, 0, 0), Vec3(1, 1, 1));
  testref::expect_invalid([&] { BedRegion<3>(box, Vec3(0, 0, 1), 0.0, BedSurface::Free); }, {"height", "positive"});
  testref::expect_invalid([&] { BedRegion<3>(box, Vec3(0, 0, 1), -1.0, BedSurface::Free); }, {"height"});
  testref::expect_invalid([&] { BedRegion<3>(box, Vec3(0, 0, 1), std::nan(""), BedSurface::Free); }, {"height"});
  testref::expect_invalid([&] { BedRegion<3>(box, Vec3(0, 0, 0), 0.5, BedSurface::Free); }, {"up", "non-zero"});
  testref::expect_invalid([&] { BedRegion<3>(box, Vec3(0, std::nan(""), 1), 0.5, BedSurface::Free); }, {"up", "finite"});
}

}  // namespace
}  // namespace fp
