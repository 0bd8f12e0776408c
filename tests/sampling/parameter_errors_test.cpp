// Every invalid parameter throws std::invalid_argument naming the class and the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/sampling/constant_radius.hpp"
#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/gradation_radius.hpp"
#include "core/sampling/histogram_radius.hpp"
#include "core/sampling/lognormal_radius.hpp"
#include "core/sampling/truncated_normal_radius.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "sampling_test_util.hpp"

namespace fp {
namespace {

using test::expect_invalid;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ParameterErrors, ConstantAndUniform) {
  expect_invalid([] { (void)ConstantRadius(0.0); }, {"ConstantRadius", "radius (0)", "positive"});
  expect_invalid([] { (void)ConstantRadius(-1.0); }, {"radius (-1)"});
  expect_invalid([] { (void)ConstantRadius(kInf); }, {"radius (inf)"});
  expect_invalid([] { (void)UniformRadius(0.03, 0.02); }, {"UniformRadius", "min (0.03) must be < max (0.02)"});
  expect_invalid([] { (void)UniformRadius(0.02, 0.02); }, {"min (0.02) must be < max (0.02)"});
  expect_invalid([] { (void)UniformRadius(0.0, 0.02); }, {"min (0)"});
  expect_invalid([] { (void)UniformRadius(0.01, kNan); }, {"max (nan)"});
}

TEST(ParameterErrors, TruncatedNormal) {
  expect_invalid([] { (void)TruncatedNormalRadius(kNan, 1, 1, 2); }, {"TruncatedNormalRadius", "mean (nan)"});
  expect_invalid([] { (void)TruncatedNormalRadius(1, 0, 1, 2); }, {"stddev (0)"});
  expect_invalid([] { (void)TruncatedNormalRadius(1, -1, 1, 2); }, {"stddev (-1)"});
  expect_invalid([] { (void)TruncatedNormalRadius(1, 1, 2, 1); }, {"min (2) must be < max (1)"});
  expect_invalid([] { (void)TruncatedNormalRadius(1, 1, -1, 2); }, {"min (-1)"});
  expect_invalid([] { (void)TruncatedNormalRadius(0, 1, 40, 41); }, {"[min, max] = [40, 41]", "tail"});
  expect_invalid([] { (void)TruncatedNormalRadius(0.015, 1e-320, 0.01, 0.02); }, {"stddev (1e-320) is too small"});
  // Accepted: the parent mean may lie outside [min, max], even far (30 sd) from it.
  EXPECT_NO_THROW(TruncatedNormalRadius(-1.0, 0.1, 2.0, 3.0));
}

TEST(ParameterErrors, Lognormal) {
  expect_invalid([] { (void)LognormalRadius(kInf, 1, 1, 2); }, {"LognormalRadius", "mu_log (inf)"});
  expect_invalid([] { (void)LognormalRadius(0, 0, 1, 2); }, {"sigma_log (0)"});
  expect_invalid([] { (void)LognormalRadius(0, 1, 3, 2); }, {"min (3) must be < max (2)"});
  expect_invalid([] { (void)LognormalRadius::from_median(-1, 1, 1, 2); }, {"median (-1)"});
  expect_invalid([] { (void)LognormalRadius(0, 0.01, 2, 3); }, {"[min, max] = [2, 3]"});
  expect_invalid([] { (void)LognormalRadius(0, 1e-310, 2, 3); }, {"sigma_log (1e-310) is too small"});
}

TEST(ParameterErrors, Discrete) {
  expect_invalid([] { (void)DiscreteRadius({}); }, {"DiscreteRadius", "radius_weight is empty"});
  expect_invalid([] { (void)DiscreteRadius({{0.01, 1}, {-0.02, 1}}); }, {"radius_weight[1]", "radius (-0.02)"});
  expect_invalid([] { (void)DiscreteRadius({{0.01, -1}}); }, {"radius_weight[0]", "weight (-1)"});
  expect_invalid([] { (void)DiscreteRadius({{0.01, kNan}}); }, {"weight (nan)"});
  expect_invalid([] { (void)DiscreteRadius({{0.01, 0}, {0.02, 0}}); }, {"positive finite sum"});
  expect_invalid([] { (void)DiscreteRadius({{0.01, 1}, {0.02, 1}, {0.01, 2}}); }, {"radius 0.01 is listed twice"});
}

TEST(ParameterErrors, Histogram) {
  expect_invalid([] { (void)HistogramRadius({1.0}, {}); }, {"HistogramRadius", "edges needs at least 2"});
  expect_invalid([] { (void)HistogramRadius({1, 2, 3}, {1}); }, {"weights needs one value per bin: 2 (got 1)"});
  expect_invalid([] { (void)HistogramRadius({1, 3, 2}, {1, 1}); }, {"edges[2] (2) must be > edges[1] (3)"});
  expect_invalid([] { (void)HistogramRadius({0, 1}, {1}); }, {"edges[0] (0)"});
  expect_invalid([] { (void)HistogramRadius({1, 2, 3}, {1, -1}); }, {"weights[1] (-1)"});
  expect_invalid([] { (void)HistogramRadius({1, 2, 3}, {0, 0}); }, {"positive finite sum"});
}

TEST(ParameterErrors, Gradation) {
  using B = GradationRadius::Basis;
  expect_invalid([] { (void)GradationRadius({{1, 0}}, B::Mass, 3); }, {"GradationRadius", "at least 2 points"});
  expect_invalid([] { (void)GradationRadius({{1, 0}, {2, 100}}, B::Mass, 4); }, {"dimension (4) must be 2 or 3"});
  expect_invalid([] { (void)GradationRadius({{1, 0}, {1, 100}}, B::Mass, 3); },
                 {"diameter_percent_passing[1]", "diameter (1) must be > the previous diameter (1)"});
  expect_invalid([] { (void)GradationRadius({{0, 0}, {1, 100}}, B::Count, 3); }, {"diameter_percent_passing[0]", "diameter (0)"});
  expect_invalid([] { (void)GradationRadius({{1, 0}, {2, 60}, {3, 50}, {4, 100}}, B::Mass, 3); },
                 {"diameter_percent_passing[2]", "percent passing (50) must be >= the previous one (60)"});
  expect_invalid([] { (void)GradationRadius({{1, 5}, {2, 100}}, B::Mass, 3); }, {"percent passing (5) must be 0"});
  expect_invalid([] { (void)GradationRadius({{1, 0}, {2, 99}}, B::Mass, 3); }, {"percent passing (99) must be 100"});
  expect_invalid([] { (void)GradationRadius({{1, 0}, {2, 120}}, B::Mass, 3); }, {"percent passing (120) must be in [0, 100]"});
}

}  // namespace
}  // namespace fp
