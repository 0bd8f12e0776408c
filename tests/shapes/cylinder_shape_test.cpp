// The test of the "cylinder" family, the README's example of adding a shape: its own closed
// forms (the generic properties of every family run in shape_properties_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "shape_test_support.hpp"
#include "shapes/cylinder_shape.hpp"

namespace fp {
namespace {

TEST(CylinderFamily, AspectRatioIsDiameterOverHeight) {
  const auto p = test::prototype<3>("cylinder", test::numbers({{"aspect_ratio", 0.5}}));
  const double h = 1 / std::sqrt(1.25), r = 0.5 * h;  // r = 0.5 h, r^2 + h^2 = 1
  EXPECT_NEAR(p.dimensions.at("height"), 2 * h, 1e-15);
  EXPECT_NEAR(p.dimensions.at("diameter"), 2 * r, 1e-15);
  EXPECT_NEAR(p.dimensions.at("radius"), r, 1e-15);
  EXPECT_NEAR(p.shape->measure(), kPi * r * r * 2 * h, 1e-15);
  EXPECT_NEAR(p.shape->inscribed_radius(), r, 1e-15);
  // Axis along body x: the end face centre and a rim point.
  EXPECT_TRUE(p.shape->contains(Vec3(h, 0, 0)));
  EXPECT_FALSE(p.shape->contains(Vec3(h * (1 + 1e-9), 0, 0)));
  EXPECT_TRUE(p.shape->contains(Vec3(-h, 0, r)));
  EXPECT_FALSE(p.shape->contains(Vec3(0, r * (1 + 1e-9), 0)));
  const Vec3 corner = p.shape->support(Vec3(1, 1, 0));
  EXPECT_NEAR((corner - Vec3(h, r, 0)).norm(), 0.0, 1e-15);
  EXPECT_TRUE(p.shape->definition_json().find(R"("axis": "body x")") != std::string::npos);
}

}  // namespace
}  // namespace fp
