// The validator against a real mesh container (the femur): a planted overlap of 1e-8 of the
// (equal) radii and a ball 1e-8 r outside the surface are found and named; the clean packing
// passes (the overlap allowance eps x the smaller radius, here eps = 1e-9).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/geometry/mesh_container.hpp"
#include "core/geometry/triangle_closest_point.hpp"
#include "core/metrics/validate.hpp"
#include "tests/metrics/analysis_test_util.hpp"

namespace fp {
namespace {

// The report names exactly one issue: of this kind, on ball i (and j for an overlap, else -1),
// of relative size 1e-8.
void expect_one_issue(const ValidationReport& rep, const std::string& kind, std::size_t i, std::int64_t j) {
  EXPECT_FALSE(rep.ok);
  EXPECT_EQ(rep.overlap_count, kind == "overlap" ? 1u : 0u);
  EXPECT_EQ(rep.outside_count, kind == "outside" ? 1u : 0u);
  ASSERT_EQ(rep.worst.size(), 1u);
  EXPECT_EQ(rep.worst[0].kind, kind);
  EXPECT_EQ(rep.worst[0].i, static_cast<std::int64_t>(i));
  EXPECT_EQ(rep.worst[0].j, j);
  EXPECT_NEAR(rep.worst[0].value_rel, 1e-8, 1e-11);
}

class ValidateInFemur : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    femur_ = MeshContainer::from_file(test::mesh_path("femur.off"));
    const Aabb<3> b = femur_->bounds();
    r_ = 0.03 * b.size().minCoeff();
    // Balls of radius r on a lattice of spacing 2.2 r: those inside the femur.
    for (double x = b.lo.x(); x < b.hi.x(); x += 2.2 * r_)
      for (double y = b.lo.y(); y < b.hi.y(); y += 2.2 * r_)
        for (double z = b.lo.z(); z < b.hi.z(); z += 2.2 * r_)
          if (femur_->contains_ball(Vec3(x, y, z), r_, 0.0)) clean_.add(Vec3(x, y, z), r_);
  }
  static void TearDownTestSuite() { femur_.reset(); }

  static std::shared_ptr<MeshContainer> femur_;
  static Packing<3> clean_;
  static double r_;
};

std::shared_ptr<MeshContainer> ValidateInFemur::femur_;
Packing<3> ValidateInFemur::clean_;
double ValidateInFemur::r_ = 0.0;

TEST_F(ValidateInFemur, CleanPackingPasses) {
  ASSERT_GT(clean_.size(), 500u);
  const ValidationReport rep = validate_packing<3>(clean_, *femur_, nullptr);
  EXPECT_TRUE(rep.ok) << rep.summary();
  EXPECT_LE(rep.max_outside_rel, 0.0);
}

TEST_F(ValidateInFemur, CountsAsWallContactsExactlyTheBallsTouchingTheSurface) {
  // Brute force: the distance to every facet. The lattice's balls are mostly deep inside; a few
  // are moved to touch the surface (along the direction to their nearest surface point).
  Packing<3> p = clean_;
  std::size_t touching = 0;
  for (std::size_t i = 0; i < p.size(); i += 7) {
    const Vec3 c = p.centers[i];
    double best = std::numeric_limits<double>::infinity();
    Vec3 nearest = c;
    for (const auto& t : femur_->triangles()) {
      const Vec3 q = detail::closest_on_triangle(c, femur_->vertices()[t[0]], femur_->vertices()[t[1]], femur_->vertices()[t[2]]);
      if ((q - c).norm() < best) best = (q - c).norm(), nearest = q;
    }
    // Keep it inside: move it so that its distance to that point is r (it may now overlap a
    // neighbour or come nearer another facet: only the wall count is checked here).
    p.centers[i] = nearest + (c - nearest) * (r_ / best);
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : femur_->triangles())
      best = std::min(best, (detail::closest_on_triangle(p.centers[i], femur_->vertices()[t[0]], femur_->vertices()[t[1]],
                                                       femur_->vertices()[t[2]]) - p.centers[i]).norm());
    touching += femur_->inside(p.centers[i]) && best <= r_ * (1 + 1e-9);
  }
  ASSERT_GT(touching, 50u);
  ASSERT_LT(touching, p.size() / 2);
  const ValidationReport rep = validate_packing<3>(p, *femur_, nullptr);
  EXPECT_EQ(rep.wall_contacts, touching);
}

TEST_F(ValidateInFemur, FindsAPlantedOverlapOf1e8RMin) {
  // Two lattice neighbours along x; the second moved to 2r - 1e-8 r of the first, where it still
  // lies inside the femur and 0.2 r or more from every other ball.
  Packing<3> p = clean_;
  std::size_t i = 0, j = 0;
  Vec3 moved = Vec3::Zero();
  for (std::size_t a = 0; a < p.size() && j == 0; ++a) {
    const Vec3 target = p.centers[a] + Vec3(2.0 * r_ - 1e-8 * r_, 0.0, 0.0);
    if (!femur_->contains_ball(target, r_, 0.0)) continue;
    for (std::size_t b = 0; b < p.size(); ++b)
      if ((p.centers[b] - p.centers[a] - Vec3(2.2 * r_, 0.0, 0.0)).norm() < 1e-6 * r_) {
        i = a, j = b, moved = target;
        break;
      }
  }
  ASSERT_NE(j, 0u);
  p.centers[j] = moved;
  expect_one_issue(validate_packing<3>(p, *femur_, nullptr), "overlap", i, static_cast<std::int64_t>(j));
}

TEST_F(ValidateInFemur, FindsABall1e8ROutsideTheSurface) {
  // A ball within 0.1 r of the surface grown until it pokes out by 1e-8 of its radius: it still
  // keeps clear of its neighbours (2.2 r away).
  Packing<3> p = clean_;
  std::size_t k = p.size();
  double depth = 0.0;
  for (std::size_t n = 0; n < p.size() && k == p.size(); ++n) {
    depth = -femur_->signed_distance(p.centers[n]);
    if (depth < 1.1 * r_) k = n;
  }
  ASSERT_LT(k, p.size());
  p.radii[k] = depth / (1.0 - 1e-8);  // signed_distance + r = 1e-8 r
  const ValidationReport rep = validate_packing<3>(p, *femur_, nullptr);
  expect_one_issue(rep, "outside", k, -1);
  EXPECT_NEAR(rep.max_outside_rel, 1e-8, 1e-11);
  // Tangent to the surface instead: fine.
  p.radii[k] = depth;
  EXPECT_TRUE(validate_packing<3>(p, *femur_, nullptr).ok);
}

}  // namespace
}  // namespace fp
