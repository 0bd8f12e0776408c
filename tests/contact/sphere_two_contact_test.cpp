// Positions touching two bodies (contact/sphere_two_contact.hpp): every sample lies on both
// centre loci to rounding, for each kind of body, near the origin and far from it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/sphere_two_contact.hpp"

namespace fp {
namespace {

constexpr double kTol = 1e-12;  // relative to r: about 100 ulps of the coordinates

// Gap of the ball (x, r) to the body: 0 = tangent (the wall kinds as in core/geometry/wall.hpp).
double gap(const Body<3>& b, const Vec3& x, double r) {
  if (!b.is_wall()) return (x - b.center).norm() - b.radius - r;
  return b.wall->gap(x, r);
}

void expect_touching(const Vec3& c0, double r0, const Body<3>& b, double r, std::size_t want, const char* what) {
  std::vector<Vec3> xs;
  two_contact_positions(c0, r0, b, r, 24, xs);
  EXPECT_EQ(xs.size(), want) << what;
  for (const Vec3& x : xs) {
    EXPECT_NEAR((x - c0).norm() - r0 - r, 0.0, kTol * r) << what;
    EXPECT_NEAR(gap(b, x, r), 0.0, kTol * r) << what;
  }
}

TEST(SphereTwoContact, EveryBodyKindAwayFromTheOrigin) {
  // The front works in the container's local frame, so coordinates stay of the container's size.
  for (const double o : {0.0, 5.0, -40.0}) {
    const Vec3 shift = Vec3::Constant(o);
    const Vec3 c0 = shift + Vec3(0.1, 0.2, 0.3);
    const double r0 = 0.02, r = 0.015;
    expect_touching(c0, r0, Body<3>::sphere(c0 + Vec3(0.03, 0.01, 0.0), 0.01), r, 24, "particle");
    const Wall<3> plane = Wall<3>::plane(shift + Vec3(0, 0, 0.29), Vec3::UnitZ());
    expect_touching(c0, r0, Body<3>::of_wall(plane), r, 24, "plane");
    const Wall<3> ball = Wall<3>::sphere(shift + Vec3(0.1, 0.2, 0.25), 0.09);
    expect_touching(c0, r0, Body<3>::of_wall(ball), r, 24, "sphere wall");
    const Wall<3> corner = Wall<3>::vertex(c0 + Vec3(0.02, 0.02, 0.0));
    expect_touching(c0, r0, Body<3>::of_wall(corner), r, 24, "vertex");
    // A needle along (1,1,1) of radius 0.03 through s0's centre: two points per angle.
    const Wall<3> needle = Wall<3>::cylinder(c0, Vec3::Ones().normalized(), 0.03);
    expect_touching(c0, r0, Body<3>::of_wall(needle), r, 48, "cylinder");
  }
}

TEST(SphereTwoContact, DisjointLociGiveNothing) {
  const Vec3 c0 = Vec3::Zero();
  std::vector<Vec3> xs;
  two_contact_positions(c0, 0.02, Body<3>::sphere(Vec3(1, 0, 0), 0.01), 0.015, 24, xs);  // far away
  const Wall<3> plane = Wall<3>::plane(Vec3(0, 0, -1), Vec3::UnitZ());
  two_contact_positions(c0, 0.02, Body<3>::of_wall(plane), 0.015, 24, xs);
  const Wall<3> thin = Wall<3>::cylinder(c0, Vec3::UnitZ(), 0.01);  // narrower than the ball
  two_contact_positions(c0, 0.02, Body<3>::of_wall(thin), 0.015, 24, xs);
  EXPECT_TRUE(xs.empty());
}

}  // namespace
}  // namespace fp
