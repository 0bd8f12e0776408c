// The orientation test: samples of a law pass it, samples of another law fail it, in the part
// they differ in (axis, azimuth, spin), and a fixed law is matched exactly.
#include "core/metrics/orientation_fit.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

namespace fp {
namespace {

template <int D>
std::vector<Eigen::Matrix<double, D, D>> sample(const OrientationLaw<D>& law, int n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Eigen::Matrix<double, D, D>> out;
  for (int i = 0; i < n; ++i) out.push_back(law.draw(rng));
  return out;
}

double smallest_p(const OrientationFit& f) {
  double p = 1.0;
  for (const auto& t : f.tests) p = std::min(p, t.p);
  return p;
}
double p_of(const OrientationFit& f, const std::string& name) {
  for (const auto& t : f.tests)
    if (t.name == name) return t.p;
  ADD_FAILURE() << "no test " << name;
  return -1;
}

TEST(OrientationFit, SamplesOfEachLawPassItsTest) {
  const OrientationLaw<3> laws3[] = {OrientationLaw<3>::isotropic(),
                                     OrientationLaw<3>::about_axis(OrientationKind::Watson, Vec3(0, 1, 1), 6.0),
                                     OrientationLaw<3>::about_axis(OrientationKind::Watson, Vec3(1, 0, 0), -4.0),
                                     OrientationLaw<3>::about_axis(OrientationKind::Fisher, Vec3(0, 0, 1), 2.5)};
  for (const auto& law : laws3) {
    const OrientationFit f = orientation_fit<3>(sample(law, 5000, 17), law);
    ASSERT_EQ(f.tests.size(), 3u) << law.describe();
    EXPECT_GT(smallest_p(f), 1e-3) << law.describe() << ": " << f.describe();
    EXPECT_NEAR(f.order, f.law_order, 4 * f.order_noise) << law.describe();
    EXPECT_EQ(f.n, 5000u);
  }
  const OrientationLaw<2> laws2[] = {OrientationLaw<2>::isotropic(),
                                     OrientationLaw<2>::about_axis(OrientationKind::Watson, Vec2(1, 1), 3.0),
                                     OrientationLaw<2>::about_axis(OrientationKind::Fisher, Vec2(0, -1), 12.0)};
  for (const auto& law : laws2) {
    const OrientationFit f = orientation_fit<2>(sample(law, 5000, 23), law);
    ASSERT_EQ(f.tests.size(), 1u);
    EXPECT_GT(smallest_p(f), 1e-3) << law.describe() << ": " << f.describe();
    EXPECT_NEAR(f.order, f.law_order, 4 * f.order_noise) << law.describe();
  }
}

TEST(OrientationFit, SamplesOfAnotherLawFailInWhatDiffers) {
  const auto iso = OrientationLaw<3>::isotropic();
  const auto watson = OrientationLaw<3>::about_axis(OrientationKind::Watson, Vec3(0, 0, 1), 3.0);
  // An aligned sample against the isotropic law: its axis fails.
  EXPECT_LT(p_of(orientation_fit<3>(sample(watson, 3000, 1), iso), "polar"), 1e-6);
  // Against the wrong axis: the polar and azimuth tests fail.
  const auto tilted = OrientationLaw<3>::about_axis(OrientationKind::Watson, Vec3(1, 0, 0), 3.0);
  EXPECT_LT(smallest_p(orientation_fit<3>(sample(watson, 3000, 2), tilted)), 1e-6);
  // Axes isotropic, but every body turned to one spin about its axis: only the spin test fails.
  std::vector<Eigen::Matrix3d> spun = sample(iso, 3000, 3);
  for (Eigen::Matrix3d& r : spun) {
    const Vec3 a = r.col(0);
    const Vec3 ref = std::abs(a.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX();
    const Vec3 y = (ref - ref.dot(a) * a).normalized();
    r.col(1) = y;
    r.col(2) = a.cross(y);
  }
  const OrientationFit f = orientation_fit<3>(spun, iso);
  EXPECT_GT(p_of(f, "polar"), 1e-3);
  EXPECT_GT(p_of(f, "azimuth"), 1e-3);
  EXPECT_LT(p_of(f, "spin"), 1e-6);
  // 2D: angles bunched at 0 against isotropic.
  const auto aligned2 = OrientationLaw<2>::about_axis(OrientationKind::Fisher, Vec2(1, 0), 4.0);
  EXPECT_LT(smallest_p(orientation_fit<2>(sample(aligned2, 2000, 4), OrientationLaw<2>::isotropic())), 1e-6);
}

TEST(OrientationFit, FixedLawsAreMatchedExactly) {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const auto fixed = OrientationLaw<3>::fixed(r);
  std::vector<Eigen::Matrix3d> same(50, r);
  OrientationFit f = orientation_fit<3>(same, fixed);
  ASSERT_EQ(f.tests.size(), 1u);
  EXPECT_EQ(f.tests[0].name, "fixed");
  EXPECT_EQ(f.tests[0].p, 1.0);
  EXPECT_TRUE(f.passes(1e-3));
  same[7] = Eigen::AngleAxisd(1e-6, Vec3::UnitX()).toRotationMatrix() * r;
  f = orientation_fit<3>(same, fixed);
  EXPECT_EQ(f.tests[0].p, 0.0);
  EXPECT_NEAR(f.tests[0].statistic, 1e-6, 1e-9);
  EXPECT_FALSE(f.passes(1e-3));
  EXPECT_FALSE(orientation_fit<3>({}, fixed).computed());
}

}  // namespace
}  // namespace fp
