// Kolmogorov-Smirnov figures (ks_result.hpp) and the homogeneity of centre coordinates
// (homogeneity.hpp, paper 002 Sect. 4) on samples whose D_n is known in closed form.
#include "core/metrics/homogeneity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/sampling/rng.hpp"
#include "tests/metrics/metrics_test_util.hpp"

namespace fp {
namespace {

double uniform01(double x) { return std::clamp(x, 0.0, 1.0); }

TEST(KsResult, KnownSamples) {
  // Midpoints (k - 1/2) / n: D_n = 1 / (2n), the smallest possible.
  std::vector<double> mid;
  for (int k = 1; k <= 400; ++k) mid.push_back((k - 0.5) / 400);
  const KsResult a = ks_one_sample(mid, uniform01);
  EXPECT_EQ(a.n, 400u);
  EXPECT_NEAR(a.d, 1.0 / 800, 1e-15);
  EXPECT_NEAR(a.sqrt_n_d, 20.0 / 800, 1e-14);
  EXPECT_NEAR(a.p, 1.0, 1e-12);
  EXPECT_TRUE(a.below_critical());
  // All samples at 0.5: D = 1/2, far above the threshold.
  const KsResult b = ks_one_sample(std::vector<double>(100, 0.5), uniform01);
  EXPECT_DOUBLE_EQ(b.d, 0.5);
  EXPECT_DOUBLE_EQ(b.sqrt_n_d, 5.0);
  EXPECT_LT(b.p, 1e-15);
  EXPECT_FALSE(b.below_critical());
  // The empty sample: not computed.
  const KsResult c = ks_one_sample({}, uniform01);
  EXPECT_EQ(c.n, 0u);
  EXPECT_TRUE(std::isnan(c.d));
  EXPECT_FALSE(c.below_critical());
}

TEST(CentreHomogeneity, LatticeCoordinatesHaveDOfOneOverN) {
  // n sites per axis at 0 .. n-1, reference interval [0, n - 1] (box [-1/2, n - 1/2] shrunk by
  // r = 1/2): F_n jumps by 1/n at each site while F rises by 1/(n - 1), so D_n = 1/n.
  const int n = 10;
  const auto lat = test::simple_cubic(n, 1.0, Vec3::Zero());
  Aabb<3> box;
  box.extend(Vec3::Constant(-0.5));
  box.extend(Vec3::Constant(n - 0.5));
  const CentreHomogeneity h = centre_homogeneity(lat.packing, box, 0.5);
  ASSERT_EQ(h.axis.size(), 3u);
  EXPECT_EQ(h.lo, (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(h.hi, (std::vector<double>{9, 9, 9}));
  for (const KsResult& k : h.axis) {
    EXPECT_EQ(k.n, 1000u);
    EXPECT_NEAR(k.d, 0.1, 1e-15);
    EXPECT_NEAR(k.sqrt_n_d, std::sqrt(1000.0) * 0.1, 1e-12);
    EXPECT_FALSE(k.below_critical());  // a lattice is not a uniform sample
  }
}

TEST(CentreHomogeneity, UniformCentresPassAndAHalfEmptyBoxFails) {
  Rng rng(7);
  Packing<2> p;
  for (int k = 0; k < 20000; ++k) p.add(Vec2(rng.uniform(1.0, 9.0), rng.uniform(-2.0, 2.0)), 1.0);
  Aabb<2> box;
  box.extend(Vec2(0.0, -3.0));
  box.extend(Vec2(10.0, 3.0));
  const CentreHomogeneity h = centre_homogeneity(p, box, 1.0);
  for (const KsResult& k : h.axis) {
    EXPECT_TRUE(k.below_critical()) << k.sqrt_n_d;
    EXPECT_GT(k.p, 0.05);
  }
  // The same centres against a range twice as wide in x: D = 1/2.
  box.extend(Vec2(18.0, 0.0));
  const CentreHomogeneity wide = centre_homogeneity(p, box, 1.0);
  EXPECT_NEAR(wide.axis[0].d, 0.5, 0.01);
  EXPECT_FALSE(wide.axis[0].below_critical());
  // An empty interval: NaN figures.
  const CentreHomogeneity none = centre_homogeneity(p, box, 3.5);
  EXPECT_TRUE(std::isnan(none.axis[1].d));
}

}  // namespace
}  // namespace fp
