// g(r) (radial_distribution.hpp, paper 000 Sect. 3.3): neighbour shells of lattices counted
// exactly through the normalisation, and g = 1 for uncorrelated centres (the ideal gas that the
// normalisation is built on), in a box (exact reference measure) and in a polygon (QMC).
#include "core/metrics/radial_distribution.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/polygon_container.hpp"
#include "core/sampling/rng.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

// Neighbours per reference centre in each bin: g * rho * |shell|.
template <int D>
std::vector<double> neighbours_per_bin(const RadialDistribution& g) {
  std::vector<double> out;
  const double w = g.range / static_cast<double>(g.r.size()) * g.mean_diameter;
  for (std::size_t k = 0; k < g.g.size(); ++k)
    out.push_back(g.g[k] * g.density * (ball_measure<D>((k + 1) * w) - ball_measure<D>(k * w)));
  return out;
}

// Expects exactly shells[d] neighbours in the bin holding distance d (in mean diameters), none elsewhere.
template <int D>
void expect_shells(const RadialDistribution& g, const std::map<double, int>& shells) {
  const std::vector<double> n = neighbours_per_bin<D>(g);
  std::vector<double> expected(n.size(), 0.0);
  for (const auto& [d, count] : shells) expected[static_cast<std::size_t>(d / (g.range / g.r.size()))] += count;
  for (std::size_t k = 0; k < n.size(); ++k) EXPECT_NEAR(n[k], expected[k], 1e-9) << "bin " << k << ", r " << g.r[k];
}

TEST(RadialDistribution, SimpleCubicShells) {
  // Spacing 1 = mean diameter; 89 bins on [0, 4.7] keep every shell off the bin edges.
  const int n = 20;
  const auto lat = test::simple_cubic(n, 1.0, Vec3::Zero());
  const BoxContainer<3> box(Vec3::Constant(-0.5), Vec3::Constant(n - 0.5));
  RdfOptions o;
  o.range = 4.7;
  o.bins = 89;
  const RadialDistribution g = radial_distribution(lat.packing, box, o);
  EXPECT_DOUBLE_EQ(g.mean_diameter, 1.0);
  EXPECT_DOUBLE_EQ(g.reference_margin, 5.2);
  // Sites 5 .. 14 (at least 5.2 from the faces) in the reference box [4.7, 14.3]^3.
  EXPECT_EQ(g.eligible_particles, std::uint64_t((n - 10) * (n - 10) * (n - 10)));
  EXPECT_EQ(g.reference_particles, g.eligible_particles);
  EXPECT_NEAR(g.density, 1000.0 / std::pow(9.6, 3), 1e-12);
  const double s2 = std::sqrt(2.0), s3 = std::sqrt(3.0), s5 = std::sqrt(5.0), s6 = std::sqrt(6.0), s8 = std::sqrt(8.0);
  const std::map<double, int> shells{{1, 6}, {s2, 12}, {s3, 8}, {2, 6}, {s5, 24}, {s6, 24}, {s8, 12}, {3, 30},
                                     {std::sqrt(10.0), 24}, {std::sqrt(11.0), 24}, {std::sqrt(12.0), 8},
                                     {std::sqrt(13.0), 24}, {std::sqrt(14.0), 48}, {4, 6}, {std::sqrt(17.0), 48},
                                     {std::sqrt(18.0), 36}, {std::sqrt(19.0), 24}, {std::sqrt(20.0), 24},
                                     {std::sqrt(21.0), 48}, {std::sqrt(22.0), 24}};
  expect_shells<3>(g, shells);
}

TEST(RadialDistribution, FaceCentredCubicShellsAtMultiplesOfTheDiameter) {
  // Touching FCC: neighbours at d sqrt(k): 12, 6, 24, 12, 24 for k = 1 .. 5.
  const auto lat = test::fcc(8, 0.5, Vec3::Zero());
  const double d = 2.0 * lat.packing.radii[0];
  const BoxContainer<3> box(Vec3::Constant(-d / 2), Vec3::Constant(7.5 + d / 2));
  RdfOptions o;
  o.range = 2.3;
  o.bins = 97;
  const RadialDistribution g = radial_distribution(lat.packing, box, o);
  EXPECT_NEAR(g.mean_diameter, d, 1e-13);
  EXPECT_GT(g.reference_particles, 100u);
  expect_shells<3>(g, {{1, 12}, {std::sqrt(2.0), 6}, {std::sqrt(3.0), 24}, {2, 12}, {std::sqrt(5.0), 24}});
  const auto peak = std::max_element(g.g.begin(), g.g.end()) - g.g.begin();
  EXPECT_NEAR(g.r[peak], 1.0, 0.5 * g.range / g.r.size());
}

TEST(RadialDistribution, HexagonalDiskShells) {
  const auto lat = test::hexagonal(60, 60, 1.0, Vec2::Zero());
  const BoxContainer<2> rect(Vec2(-0.5, -0.5), Vec2(60.0, 51.6));  // the sites span [0, 59.5] x [0, 51.1]
  RdfOptions o;
  o.range = 3.1;
  o.bins = 97;
  const RadialDistribution g = radial_distribution(lat.packing, rect, o);
  EXPECT_GT(g.reference_particles, 2000u);
  EXPECT_NEAR(g.density, 2.0 / std::sqrt(3.0), 0.03);
  expect_shells<2>(g, {{1, 6}, {std::sqrt(3.0), 6}, {2, 6}, {std::sqrt(7.0), 12}, {3, 6}});
}

// Uniform random centres with overlapping "radii" 0.5: g(r) = 1 within the counting noise.
template <int D, class Inside>
Packing<D> ideal_gas(std::size_t n, const Aabb<D>& box, Inside&& inside, std::uint64_t seed) {
  Rng rng(seed);
  Packing<D> p;
  while (p.size() < n) {
    Vec<D> c;
    for (int a = 0; a < D; ++a) c[a] = rng.uniform(box.lo[a], box.hi[a]);
    if (inside(c)) p.add(c, 0.5);
  }
  return p;
}

TEST(RadialDistribution, IdealGasIsOneInABallAndInAPolygon) {
  const BallContainer<3> ball(Vec3::Zero(), 22.0);
  const auto p3 = ideal_gas<3>(45000, ball.bounds(), [&](const Vec3& c) { return ball.inside(c); }, 5);
  RdfOptions o;
  o.range = 4.0;
  o.bins = 20;
  const RadialDistribution g3 = radial_distribution(p3, ball, o);
  EXPECT_EQ(g3.reference_measure.std_error, 0.0);
  EXPECT_DOUBLE_EQ(g3.reference_measure.value, ball_measure<3>(22.0 - 4.5));
  for (std::size_t k = 4; k < g3.g.size(); ++k) EXPECT_NEAR(g3.g[k], 1.0, 0.05) << "r " << g3.r[k];

  // A pentagon: the reference region's area comes from QMC.
  const PolygonContainer pent({Vec2(0, 0), Vec2(120, 0), Vec2(140, 70), Vec2(60, 130), Vec2(-20, 70)});
  const auto p2 = ideal_gas<2>(40000, pent.bounds(), [&](const Vec2& c) { return pent.inside(c); }, 6);
  const RadialDistribution g2 = radial_distribution(p2, pent, o);
  EXPECT_GT(g2.reference_measure.std_error, 0.0);
  EXPECT_LT(g2.reference_measure.std_error, 1e-3 * g2.reference_measure.value);
  for (std::size_t k = 4; k < g2.g.size(); ++k) EXPECT_NEAR(g2.g[k], 1.0, 0.05) << "r " << g2.r[k];
}

TEST(RadialDistribution, ReferenceCapKeepsTheShape) {
  const auto lat = test::simple_cubic(20, 1.0, Vec3::Zero());
  const BoxContainer<3> box(Vec3::Constant(-0.5), Vec3::Constant(19.5));
  RdfOptions o;
  o.range = 4.7;
  o.bins = 89;
  const RadialDistribution all = radial_distribution(lat.packing, box, o);
  o.max_reference = 100;
  const RadialDistribution some = radial_distribution(lat.packing, box, o);
  EXPECT_EQ(some.eligible_particles, all.eligible_particles);
  EXPECT_LE(some.reference_particles, 100u);
  EXPECT_GT(some.reference_particles, 50u);
  for (std::size_t k = 0; k < all.g.size(); ++k) EXPECT_NEAR(some.g[k], all.g[k], 1e-9 * (1.0 + all.g[k]));
}

TEST(RadialDistribution, TooSmallAContainerHasNoReference) {
  const auto lat = test::simple_cubic(6, 1.0, Vec3::Zero());
  const BoxContainer<3> box(Vec3::Constant(-0.5), Vec3::Constant(5.5));
  const RadialDistribution g = radial_distribution(lat.packing, box);
  EXPECT_EQ(g.reference_particles, 0u);
  EXPECT_EQ(g.g, std::vector<double>(100, 0.0));
  EXPECT_EQ(g.r.size(), 100u);
  RdfOptions bad;
  bad.range = 0.0;
  EXPECT_THROW(radial_distribution(lat.packing, box, bad), std::invalid_argument);
}

}  // namespace
}  // namespace fp
