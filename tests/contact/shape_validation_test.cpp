// validate_shapes: the verdict of shape packings is the one of sphere packings (one engine, one report):
// an empty packing fails, each template's sizes are tested against its size law (radii_fit) and
// the counts per template against the requested shares (chi-square), at a Bonferroni level.
#include "contact/shape_validation.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "core/geometry/box_container.hpp"
#include "core/metrics/validate.hpp"
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
  const ValidationReport v = validate_shapes<3>(ShapePacking<3>{}, kBox, 1e-6);
  EXPECT_FALSE(v.ok);
  EXPECT_TRUE(v.empty());
  EXPECT_NE(v.summary().find("no particles"), std::string::npos) << v.summary();
}

TEST(ShapeValidation, SizesAndMixAgainstTheRequest) {
  const UniformRadius law(0.2, 0.4);
  Rng rng(3);
  std::vector<std::pair<int, double>> items;
  for (int k = 0; k < 600; ++k) items.emplace_back(k % 3 == 0 ? 1 : 0, law.sample(rng));  // 2 : 1
  const std::vector<RequestedTemplate> asked = {{&law, 2.0}, {&law, 1.0}};
  const ValidationReport ok = validate_shapes<3>(lattice(items), kBox, 1e-6, asked);
  EXPECT_TRUE(ok.ok) << ok.summary();
  EXPECT_EQ(ok.tests(), 3);
  ASSERT_EQ(ok.sizes.size(), 2u);
  EXPECT_EQ(ok.sizes[0].test, "K-S");
  ASSERT_TRUE(ok.mix.has_value());
  EXPECT_NEAR(ok.mix->statistic, 0.0, 1e-12);  // exactly 400 / 200
  EXPECT_NE(ok.summary().find("fails below 0.000333"), std::string::npos) << ok.summary();
  // Without the request only geometry is judged.
  EXPECT_TRUE(validate_shapes<3>(lattice(items), kBox, 1e-6).ok);
  EXPECT_EQ(validate_shapes<3>(lattice(items), kBox, 1e-6).tests(), 0);

  // The same sizes asked as 1 : 1: the mix fails (X2 = 66.7).
  const std::vector<RequestedTemplate> even = {{&law, 1.0}, {&law, 1.0}};
  const ValidationReport mix = validate_shapes<3>(lattice(items), kBox, 1e-6, even);
  EXPECT_FALSE(mix.ok);
  ASSERT_TRUE(mix.mix.has_value());
  EXPECT_LT(mix.mix->p, 1e-10);
  // Sizes drawn from U[0.2, 0.4] asked as U[0.2, 0.5]: K-S fails.
  const UniformRadius wider(0.2, 0.5);
  const std::vector<RequestedTemplate> wide = {{&wider, 2.0}, {&law, 1.0}};
  EXPECT_FALSE(validate_shapes<3>(lattice(items), kBox, 1e-6, wide).ok);
  // One size beyond its law's range.
  auto stray = items;
  stray[5].second = 0.41;
  const ValidationReport out = validate_shapes<3>(lattice(stray), kBox, 1e-6, asked);
  EXPECT_FALSE(out.ok);
  EXPECT_EQ(out.radius_count, 1u);
  ASSERT_FALSE(out.worst.empty());
  EXPECT_EQ(out.worst[0].kind, "size_out_of_range");
  EXPECT_EQ(out.worst[0].i, 5);
}

TEST(ShapeValidation, DiscreteSizesUseTheirCounts) {
  const DiscreteRadius law({{0.3, 1.0}, {0.45, 1.0}});
  std::vector<std::pair<int, double>> items;
  for (int k = 0; k < 300; ++k) items.emplace_back(0, k < 140 ? 0.3 : 0.45);  // 140 / 160
  const ValidationReport v = validate_shapes<3>(lattice(items), kBox, 1e-6, {{&law, 1.0}});
  EXPECT_TRUE(v.ok) << v.summary();
  EXPECT_EQ(v.sizes[0].test, "chi-square");
  EXPECT_NEAR(v.sizes[0].statistic, 2.0 * 100.0 / 150.0, 1e-12);
  EXPECT_FALSE(v.mix.has_value());
}

// Spheres as shapes get the verdict of the same spheres as a sphere packing, figure for figure
// (one engine): contacts, overlaps, outside, worst offenders and the size test.
TEST(ShapeValidation, SpheresGetTheVerdictOfASpherePacking) {
  const DiscreteRadius law({{0.45, 1.0}, {0.5, 1.0}});
  Rng rng(11);
  std::vector<std::pair<int, double>> items;
  for (int k = 0; k < 1200; ++k) items.emplace_back(0, law.sample(rng));
  items[0].second = items[1].second = items[20].second = 0.5;  // 0-1 and 0-20 touch ...
  ShapePacking<3> shapes = lattice(items);
  shapes.particles[1].pose.position.x() -= 1e-3;  // ... then 0-1 overlap by 1e-3
  shapes.particles[77].pose.position.z() = 0.2;   // 77 pokes out of the box
  Packing<3> balls;
  for (const Particle<3>& p : shapes.particles) balls.add(p.pose.position, p.size);

  for (const double tol : {1e-9, 1e-2}) {
    const ValidationReport s = validate_shapes<3>(shapes, kBox, tol, {{&law, 1.0}});
    const ValidationReport b = validate_packing<3>(balls, kBox, &law, tol);
    EXPECT_EQ(s.ok, b.ok);
    EXPECT_EQ(s.pairs_checked, b.pairs_checked);
    EXPECT_EQ(s.overlap_count, b.overlap_count);
    EXPECT_EQ(s.outside_count, b.outside_count);
    EXPECT_EQ(s.contacts, b.contacts);
    EXPECT_EQ(s.wall_contacts, b.wall_contacts);
    EXPECT_NEAR(s.max_overlap_rel, b.max_overlap_rel, 1e-12);
    EXPECT_NEAR(s.max_outside_rel, b.max_outside_rel, 1e-12);
    ASSERT_EQ(s.worst.size(), b.worst.size());
    for (std::size_t k = 0; k < s.worst.size(); ++k) {
      EXPECT_EQ(s.worst[k].kind, b.worst[k].kind);
      EXPECT_EQ(s.worst[k].i, b.worst[k].i);
      EXPECT_EQ(s.worst[k].j, b.worst[k].j);
    }
    EXPECT_EQ(s.radii().statistic, b.radii().statistic);
    EXPECT_EQ(s.radii().p, b.radii().p);
  }
  const ValidationReport strict = validate_shapes<3>(shapes, kBox, 1e-9, {{&law, 1.0}});
  EXPECT_FALSE(strict.ok);
  EXPECT_EQ(strict.overlap_count, 1u);
  EXPECT_EQ(strict.outside_count, 1u);
  ASSERT_EQ(strict.worst.size(), 2u);
  EXPECT_EQ(strict.worst[0].kind, "outside");  // 0.3 / 0.45..0.5 beyond, more than the overlap's 2e-3
  EXPECT_EQ(strict.worst[0].i, 77);
  EXPECT_EQ(strict.worst[1].kind, "overlap");
  EXPECT_EQ(strict.worst[1].i, 0);
  EXPECT_EQ(strict.worst[1].j, 1);
  EXPECT_NEAR(strict.worst[1].value_rel, 2e-3, 1e-9);
  // Touching lattice neighbours (both of radius 0.5) are contacts; 0-20 is one of them.
  EXPECT_GT(strict.contacts, 100u);
}

}  // namespace
}  // namespace fp
