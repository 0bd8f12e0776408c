// The orientation laws: their tabulated distributions against closed forms, the order <-> kappa
// inversion, and rotations drawn from them.
#include "core/sampling/orientation_law.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

namespace fp {
namespace {

// 3D fisher: P(a.n <= t) = (e^{k(t-1)} - e^{-2k}) / (1 - e^{-2k}); <P2> from <t> = coth k - 1/k and
// <t^2> = 1 - 2 <t> / k.
double fisher_cdf(double k, double t) { return (std::exp(k * (t - 1)) - std::exp(-2 * k)) / (1 - std::exp(-2 * k)); }
double fisher_order(double k) {
  const double mean = 1 / std::tanh(k) - 1 / k;
  return 1.5 * (1 - 2 * mean / k) - 0.5;
}

TEST(AxisAngleLaw, FisherMatchesItsClosedForms) {
  for (const double k : {0.5, 2.0, 30.0, 1000.0}) {
    const AxisAngleLaw law(OrientationKind::Fisher, 3, k);
    for (const double t : {-0.9, -0.3, 0.0, 0.5, 0.9, 0.99, 0.999})
      EXPECT_NEAR(law.cdf(t), fisher_cdf(k, t), 1e-9) << "kappa " << k << " t " << t;
    EXPECT_NEAR(law.order(), fisher_order(k), 1e-9) << k;
  }
  const AxisAngleLaw uniform(OrientationKind::Fisher, 3, 0.0);
  EXPECT_NEAR(uniform.cdf(0.25), 0.625, 1e-12);
  EXPECT_NEAR(uniform.order(), 0.0, 1e-12);
  // The noise of an isotropic sample's <P2>: Var P2(t) for t uniform is 1/5.
  EXPECT_NEAR(uniform.order_sd(), std::sqrt(0.2), 1e-9);
}

TEST(AxisAngleLaw, WatsonMatchesItsClosedForms) {
  // <t^2> = e^k / (2 k I) - 1 / (2k), I = int_0^1 e^{k t^2} dt; I(1) = sqrt(pi)/2 erfi(1).
  const double i1 = 1.4626517459071816;
  const double t2 = std::exp(1.0) / (2 * i1) - 0.5;
  EXPECT_NEAR(AxisAngleLaw(OrientationKind::Watson, 3, 1.0).order(), 1.5 * t2 - 0.5, 1e-9);
  // A girdle (kappa < 0): the folded |a.n| follows erf(sqrt(-k) t) / erf(sqrt(-k)).
  const double k = -9.0;
  const AxisAngleLaw girdle(OrientationKind::Watson, 3, k);
  for (const double t : {0.05, 0.2, 0.5, 0.9})
    EXPECT_NEAR(girdle.cdf(t), std::erf(std::sqrt(-k) * t) / std::erf(std::sqrt(-k)), 1e-9) << t;
  EXPECT_LT(girdle.order(), 0.0);
  EXPECT_GT(AxisAngleLaw(OrientationKind::Watson, 3, 1000).order(), 0.998);
}

TEST(AxisAngleLaw, TwoDimensionalOrdersAreBesselRatios) {
  // von Mises on psi: <cos 2 psi> = I2(k) / I0(k); axial (on 2 psi): I1(k) / I0(k).
  for (const double k : {0.3, 2.0, 25.0}) {
    EXPECT_NEAR(AxisAngleLaw(OrientationKind::Fisher, 2, k).order(), std::cyl_bessel_i(2.0, k) / std::cyl_bessel_i(0.0, k), 1e-9);
    EXPECT_NEAR(AxisAngleLaw(OrientationKind::Watson, 2, k).order(), std::cyl_bessel_i(1.0, k) / std::cyl_bessel_i(0.0, k), 1e-9);
  }
  const AxisAngleLaw uniform(OrientationKind::Fisher, 2, 0.0);
  EXPECT_NEAR(uniform.cdf(0.0), 0.5, 1e-12);
  EXPECT_NEAR(uniform.cdf(kPi / 2), 0.75, 1e-12);
}

TEST(AxisAngleLaw, QuantileInvertsTheCdf) {
  for (const auto& law : {AxisAngleLaw(OrientationKind::Watson, 3, 40.0), AxisAngleLaw(OrientationKind::Fisher, 2, 7.0)})
    for (const double p : {0.0, 1e-6, 0.01, 0.3, 0.5, 0.77, 0.999, 1.0}) EXPECT_NEAR(law.cdf(law.quantile(p)), p, 1e-12) << p;
  EXPECT_THROW(AxisAngleLaw(OrientationKind::Watson, 3, 1001.0), std::invalid_argument);
  EXPECT_THROW(AxisAngleLaw(OrientationKind::Isotropic, 3, 1.0), std::invalid_argument);
}

TEST(OrientationLaw, ConcentrationForOrderInvertsTheOrder) {
  for (const double s : {-0.4, -0.1, 0.0, 0.3, 0.8, 0.99}) {
    const double k = OrientationLaw<3>::concentration_for_order(OrientationKind::Watson, s);
    EXPECT_NEAR(AxisAngleLaw(OrientationKind::Watson, 3, k).order(), s, 1e-7) << s;
  }
  for (const double s : {0.1, 0.6}) {
    const double k = OrientationLaw<2>::concentration_for_order(OrientationKind::Fisher, s);
    EXPECT_GE(k, 0.0);
    EXPECT_NEAR(AxisAngleLaw(OrientationKind::Fisher, 2, k).order(), s, 1e-7) << s;
  }
  EXPECT_THROW(OrientationLaw<3>::concentration_for_order(OrientationKind::Watson, -0.6), std::invalid_argument);
  EXPECT_THROW(OrientationLaw<3>::concentration_for_order(OrientationKind::Fisher, -0.1), std::invalid_argument);
  EXPECT_THROW(OrientationLaw<3>::concentration_for_order(OrientationKind::Watson, 1.0), std::invalid_argument);
}

// Isotropic draws are the front's historical ones (Shoemake's quaternion from three uniforms), so
// packings of isotropic templates are unchanged by the laws.
TEST(OrientationLaw, IsotropicDrawsAreShoemakesQuaternions) {
  Rng a(11), b(11);
  const OrientationLaw<3> law = OrientationLaw<3>::isotropic();
  for (int i = 0; i < 100; ++i) {
    const Eigen::Matrix3d r = law.draw(a);
    const double u1 = b.uniform01(), u2 = b.uniform01(), u3 = b.uniform01();
    const double s = std::sqrt(1 - u1), t = std::sqrt(u1);
    const Eigen::Matrix3d ref = Eigen::Quaterniond(t * std::cos(2 * kPi * u3), s * std::sin(2 * kPi * u2), s * std::cos(2 * kPi * u2),
                                                   t * std::sin(2 * kPi * u3)).normalized().toRotationMatrix();
    EXPECT_EQ(r, ref);
  }
}

TEST(OrientationLaw, DrawsAreRotationsWithTheLawsAxisStatistics) {
  Rng rng(5);
  const Vec3 n = Vec3(1, 2, 2).normalized();
  const double kappa = 8.0;
  const OrientationLaw<3> watson = OrientationLaw<3>::about_axis(OrientationKind::Watson, Vec3(1, 2, 2), kappa);
  const OrientationLaw<3> fisher = OrientationLaw<3>::about_axis(OrientationKind::Fisher, Vec3(1, 2, 2), kappa);
  const int count = 20000;
  double p2_w = 0, t_w = 0, t_f = 0, p2_f = 0;
  for (int i = 0; i < count; ++i) {
    const Eigen::Matrix3d w = watson.draw(rng), f = fisher.draw(rng);
    for (const Eigen::Matrix3d* r : {&w, &f}) {
      EXPECT_NEAR((r->transpose() * *r - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
      EXPECT_NEAR(r->determinant(), 1.0, 1e-12);
    }
    const double tw = w.col(0).dot(n), tf = f.col(0).dot(n);
    p2_w += 1.5 * tw * tw - 0.5, t_w += tw, p2_f += 1.5 * tf * tf - 0.5, t_f += tf;
  }
  const AxisAngleLaw& lw = *watson.angle_law();
  const AxisAngleLaw& lf = *fisher.angle_law();
  // Means within 5 standard errors (deterministic seed: this is a check of the construction).
  EXPECT_NEAR(p2_w / count, lw.order(), 5 * lw.order_sd() / std::sqrt(count));
  EXPECT_NEAR(p2_f / count, lf.order(), 5 * lf.order_sd() / std::sqrt(count));
  EXPECT_NEAR(t_w / count, 0.0, 5.0 / std::sqrt(count));               // axial: a and -a alike
  EXPECT_NEAR(t_f / count, 1 / std::tanh(kappa) - 1 / kappa, 0.005);  // polar: along n
}

TEST(OrientationLaw, TwoDimensionalLawsTurnFromTheirAxis) {
  Rng rng(3);
  const OrientationLaw<2> law = OrientationLaw<2>::about_axis(OrientationKind::Fisher, Vec2(0, 1), 1000.0);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Matrix2d r = law.draw(rng);
    EXPECT_NEAR(std::atan2(r(1, 0), r(0, 0)), kPi / 2, 0.2);
  }
  const OrientationLaw<2> fixed = OrientationSpec{OrientationKind::Fixed, {30.0}, {}, 0.0}.law<2>();
  EXPECT_NEAR(std::atan2(fixed.draw(rng)(1, 0), fixed.draw(rng)(0, 0)), kPi / 6, 1e-15);
  EXPECT_EQ(fixed.describe(), "fixed 30 degrees");
  EXPECT_EQ(OrientationLaw<3>::isotropic().describe(), "isotropic");
  EXPECT_EQ(OrientationLaw<3>::about_axis(OrientationKind::Watson, Vec3(0, 0, 2), 0.0).describe(),
            "watson about [0, 0, 1], kappa 0 (order S 0)");
}

}  // namespace
}  // namespace fp
