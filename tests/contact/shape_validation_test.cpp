// validate_shapes: the verdict of shape packings is the one of sphere packings where it applies:
// an empty packing fails, each template's sizes are tested against its size law (radii_fit) and
// the counts per template against the requested shares (chi-square), at a Bonferroni level.
#include "contact/shape_validation.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "core/geometry/box_container.hpp"
#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/rng.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "shapes/sphere_shape.hpp"

namespace fp {
namespace {

// Spheres on a lattice of spacing 1 (no overlap for sizes <= 0.5), template k every k-th.
ShapePacking<3> lattice(const std::vector<std::pair<int, double>>& template_and_size) {
  ShapePacking<3> p;
  int k = 0;
  for (const auto& [t, size] : template_and_size) {
    Particle<3> q;
    q.shape = std::make_shared<SphereShape<3>>(size);
    q.pose.position = Vec3(1.0 + k % 20, 1.0 + (k / 20) % 20, 1.0 + k / 400);
    q.template_id = t;
    q.size = size;
    p.particles.push_back(q);
    ++k;
  }
  p.template_names = {"sphere", "sphere"};
  return p;
}

const BoxContainer<3> kBox(Vec3::Zero(), Vec3::Constant(22.0));

TEST(ShapeValidation, AnEmptyPackingFails) {
  const ShapeValidation v = validate_shapes<3>(ShapePacking<3>{}, kBox, 1e-6);
  EXPECT_FALSE(v.ok);
  EXPECT_TRUE(v.empty);
  EXPECT_NE(v.summary().find("no particles"), std::string::npos) << v.summary();
}

TEST(ShapeValidation, SizesAndMixAgainstTheRequest) {
  const UniformRadius law(0.2, 0.4);
  Rng rng(3);
  std::vector<std::pair<int, double>> items;
  for (int k = 0; k < 600; ++k) items.emplace_back(k % 3 == 0 ? 1 : 0, law.sample(rng));  // 2 : 1
  const std::vector<RequestedTemplate> asked = {{&law, 2.0}, {&law, 1.0}};
  const ShapeValidation ok = validate_shapes<3>(lattice(items), kBox, 1e-6, asked);
  EXPECT_TRUE(ok.ok) << ok.summary();
  EXPECT_EQ(ok.tests, 3);
  ASSERT_EQ(ok.sizes.size(), 2u);
  EXPECT_EQ(ok.sizes[0].test, "K-S");
  EXPECT_TRUE(ok.mix_tested);
  EXPECT_NEAR(ok.mix.statistic, 0.0, 1e-12);  // exactly 400 / 200
  EXPECT_NE(ok.summary().find("fails below 0.000333"), std::string::npos) << ok.summary();
  // Without the request only geometry is judged.
  EXPECT_TRUE(validate_shapes<3>(lattice(items), kBox, 1e-6).ok);
  EXPECT_EQ(validate_shapes<3>(lattice(items), kBox, 1e-6).tests, 0);

  // The same sizes asked as 1 : 1: the mix fails (X2 = 66.7).
  const std::vector<RequestedTemplate> even = {{&law, 1.0}, {&law, 1.0}};
  const ShapeValidation mix = validate_shapes<3>(lattice(items), kBox, 1e-6, even);
  EXPECT_FALSE(mix.ok);
  EXPECT_LT(mix.mix.p, 1e-10);
  // Sizes drawn from U[0.2, 0.4] asked as U[0.2, 0.5]: K-S fails.
  const UniformRadius wider(0.2, 0.5);
  const std::vector<RequestedTemplate> wide = {{&wider, 2.0}, {&law, 1.0}};
  EXPECT_FALSE(validate_shapes<3>(lattice(items), kBox, 1e-6, wide).ok);
  // One size beyond its law's range.
  auto stray = items;
  stray[5].second = 0.41;
  const ShapeValidation out = validate_shapes<3>(lattice(stray), kBox, 1e-6, asked);
  EXPECT_FALSE(out.ok);
  EXPECT_EQ(out.sizes_out_of_range, 1u);
}

TEST(ShapeValidation, DiscreteSizesUseTheirCounts) {
  const DiscreteRadius law({{0.3, 1.0}, {0.45, 1.0}});
  std::vector<std::pair<int, double>> items;
  for (int k = 0; k < 300; ++k) items.emplace_back(0, k < 140 ? 0.3 : 0.45);  // 140 / 160
  const ShapeValidation v = validate_shapes<3>(lattice(items), kBox, 1e-6, {{&law, 1.0}});
  EXPECT_TRUE(v.ok) << v.summary();
  EXPECT_EQ(v.sizes[0].test, "chi-square");
  EXPECT_NEAR(v.sizes[0].statistic, 2.0 * 100.0 / 150.0, 1e-12);
  EXPECT_FALSE(v.mix_tested);
}

}  // namespace
}  // namespace fp
