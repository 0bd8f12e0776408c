// Kolmogorov-Smirnov figures (ks_result.hpp) and the homogeneity of centre coordinates
// (homogeneity.hpp, paper 002 Sect. 4) on samples whose D_n is known in closed form.
#include "core/metrics/homogeneity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/cylinder_container.hpp"
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

/// `n` centres uniform in `container` less `margin` (rejection from its bounding box).
template <int D>
Packing<D> uniform_in_core(const Container<D>& container, double margin, int n, std::uint64_t seed) {
  Rng rng(seed);
  const Aabb<D> b = container.bounds();
  Packing<D> p;
  while (static_cast<int>(p.size()) < n) {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = rng.uniform(b.lo[a], b.hi[a]);
    if (container.signed_distance(x) <= -margin) p.add(x, 0.01);
  }
  return p;
}

// The reference is the container's core, not its bounding box: centres uniform in a tilted
// cylinder, a ball and a disk pass (the bounding box's uniform law rejects them, the report users
// met on full cylinders); centres uniform in a half of the core fail; centres in the wall layer
// are not tested.
TEST(CentreHomogeneity, TheReferenceIsTheContainersCore) {
  const CylinderContainer cylinder(Vec3(0, 0, 0), Vec3(1, 0.5, 0.2), 1.0, 3.0);
  const BallContainer<3> ball(Vec3(1, 2, 3), 2.0);
  const BallContainer<2> disk(Vec2(0, 0), 1.0);
  const double margin = 0.1;
  for (const std::uint64_t seed : {1u, 2u}) {
    const Packing<3> in_cylinder = uniform_in_core<3>(cylinder, margin, 20000, seed);
    const CentreHomogeneity h = centre_homogeneity(in_cylinder, cylinder, margin);
    EXPECT_GT(h.reference_points, 10000u);
    for (const KsResult& k : h.axis) {
      EXPECT_EQ(k.n, 20000u);
      EXPECT_GT(k.p, 1e-3) << "seed " << seed << ": sqrt(n) D = " << k.sqrt_n_d;
    }
    const CentreHomogeneity boxed = centre_homogeneity(in_cylinder, cylinder.bounds(), margin);
    EXPECT_LT(boxed.axis[0].p, 1e-10);  // the bounding box's law: a full cylinder looks inhomogeneous
    for (const KsResult& k : centre_homogeneity(uniform_in_core<3>(ball, margin, 20000, seed), ball, margin).axis)
      EXPECT_GT(k.p, 1e-3) << "ball, seed " << seed;
    for (const KsResult& k : centre_homogeneity(uniform_in_core<2>(disk, margin, 20000, seed), disk, margin).axis)
      EXPECT_GT(k.p, 1e-3) << "disk, seed " << seed;
  }
  // Half the core: the centres with x below the cylinder's middle fail on x.
  Packing<3> half;
  const Packing<3> all = uniform_in_core<3>(cylinder, margin, 40000, 3);
  const double middle = (cylinder.bounds().lo[0] + cylinder.bounds().hi[0]) / 2;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all.centers[i][0] < middle) half.add(all.centers[i], all.radii[i]);
  EXPECT_LT(centre_homogeneity(half, cylinder, margin).axis[0].p, 1e-10);
  // A centre in the wall layer is left out of the test.
  Packing<3> layer = uniform_in_core<3>(cylinder, margin, 100, 4);
  layer.add(Vec3(0, 0, 0.01), 0.01);
  EXPECT_EQ(centre_homogeneity(layer, cylinder, margin).axis[0].n, 100u);
}

}  // namespace
}  // namespace fp
