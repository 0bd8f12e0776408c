// Randomised QMC (core/metrics/qmc.hpp; the error bars of the VF of paper 000 Eq. 16): the Halton
// sequence digit by digit, the shifts, and the standard error of the replicates.
#include "core/metrics/qmc.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fp {
namespace {

TEST(Qmc, RadicalInverseMirrorsTheDigits) {
  EXPECT_EQ(radical_inverse(0, 2), 0.0);
  EXPECT_EQ(radical_inverse(1, 2), 0.5);
  EXPECT_EQ(radical_inverse(6, 2), 0.375);  // 110 -> 0.011
  EXPECT_NEAR(radical_inverse(7, 3), 1.0 / 3.0 + 2.0 / 9.0, 1e-15);  // 21 -> 0.12
  EXPECT_NEAR(radical_inverse(13, 5), 3.0 / 5.0 + 2.0 / 25.0, 1e-15);  // 23 -> 0.32
}

TEST(Qmc, HaltonPointsFillTheUnitCubeEvenly) {
  const auto pts = halton_points<3>(4096);
  ASSERT_EQ(pts.size(), 4096u);
  EXPECT_EQ(pts[0], Vec3(0.5, 1.0 / 3.0, 0.2));
  // Low discrepancy: the fraction in [0, 0.3)^3 is within a few 1e-3 of 0.027.
  int in = 0;
  for (const Vec3& p : pts) {
    ASSERT_TRUE((p.array() >= 0.0).all() && (p.array() < 1.0).all());
    in += (p.array() < 0.3).all() ? 1 : 0;
  }
  EXPECT_NEAR(in / 4096.0, 0.027, 2e-3);
}

TEST(Qmc, ShiftsAreReproducibleAndWrapIntoTheCube) {
  QmcOptions o;
  o.replicates = 5;
  const auto a = qmc_shifts<2>(o), b = qmc_shifts<2>(o);
  ASSERT_EQ(a.size(), 5u);
  EXPECT_EQ(a, b);
  o.seed += 1;
  EXPECT_NE(qmc_shifts<2>(o), a);
  EXPECT_EQ(shifted<2>(Vec2(0.75, 0.25), Vec2(0.5, 0.5)), Vec2(0.25, 0.75));
  o.replicates = 0;
  EXPECT_THROW(qmc_shifts<2>(o), std::invalid_argument);
}

TEST(Qmc, MeanAndStandardErrorOfTheReplicates) {
  const Estimate e = mean_and_error({1.0, 2.0, 3.0, 4.0});
  EXPECT_DOUBLE_EQ(e.value, 2.5);
  EXPECT_DOUBLE_EQ(e.std_error, std::sqrt(5.0 / 3.0 / 4.0));
  EXPECT_EQ(mean_and_error({7.0}).std_error, 0.0);
  EXPECT_EQ(mean_and_error({}).value, 0.0);
}

TEST(Qmc, ShiftedEstimatesOfTheQuarterDiskBracketPiOverFour) {
  // Integrand 1[x^2 + y^2 <= 1] on the unit square: every replicate is unbiased.
  const auto pts = halton_points<2>(2048);
  QmcOptions o;
  o.replicates = 16;
  std::vector<double> reps;
  for (const Vec2& s : qmc_shifts<2>(o)) {
    int in = 0;
    for (const Vec2& u : pts) in += shifted<2>(u, s).squaredNorm() <= 1.0 ? 1 : 0;
    reps.push_back(in / 2048.0);
  }
  const Estimate e = mean_and_error(reps);
  EXPECT_GT(e.std_error, 0.0);
  EXPECT_LT(e.std_error, 2e-3);
  EXPECT_NEAR(e.value, kPi / 4.0, 4.0 * e.std_error);
}

}  // namespace
}  // namespace fp
