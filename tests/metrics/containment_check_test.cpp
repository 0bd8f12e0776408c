// The validator's containment check (containment_check.hpp) for every container kind: against
// the container classes on random points, against brute-force references of the tests (none of
// whose code it shares), at points 1e-12 off faces, edges, corners and reflex vertices, and the
// refusal of a container kind it does not know.
#include "core/metrics/containment_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/cylinder_container.hpp"
#include "core/geometry/mesh_container.hpp"
#include "core/geometry/polygon_container.hpp"
#include "core/metrics/validate.hpp"
#include "core/sampling/rng.hpp"
#include "tests/geometry/reference_geometry.hpp"
#include "tests/metrics/analysis_test_util.hpp"

namespace fp {
namespace {

template <int D>
Vec<D> random_in(Rng& rng, const Aabb<D>& b, double pad) {
  Vec<D> p;
  for (int a = 0; a < D; ++a) p[a] = rng.uniform(b.lo[a] - pad * b.size()[a], b.hi[a] + pad * b.size()[a]);
  return p;
}

// Random points in the padded bounds: the check against the container and against `reference`;
// returns how many were inside.
template <int D>
int compare_on_random_points(const Container<D>& c, const std::function<double(const Vec<D>&)>& reference,
                             std::uint64_t seed, int n = 3000) {
  const ContainmentCheck<D> check(c);
  const double scale = c.bounds().size().norm();
  Rng rng(seed);
  int inside = 0;
  for (int i = 0; i < n; ++i) {
    const Vec<D> p = random_in<D>(rng, c.bounds(), 0.2);
    const double sd = check.signed_distance(p);
    EXPECT_NEAR(sd, reference(p), 4e-16 * scale) << c.describe() << " at " << p.transpose();
    EXPECT_NEAR(sd, c.signed_distance(p), 4e-16 * scale) << c.describe() << " at " << p.transpose();
    inside += sd < 0;
  }
  EXPECT_GT(inside, n / 100) << c.describe();  // some inside (the femur fills ~3 % of its padded box)
  EXPECT_LT(inside, n) << c.describe();
  return inside;
}

TEST(ContainmentCheck, BoxesAndRectangles) {
  const BoxContainer<3> box(Vec3(-1, 2, 0.5), Vec3(3, 2.5, 4));
  compare_on_random_points<3>(box, [](const Vec3& p) {
    // Inside: the nearest of the six faces; outside: the nearest point of the clamped box.
    const Vec3 lo(-1, 2, 0.5), hi(3, 2.5, 4);
    const Vec3 q = p.cwiseMax(lo).cwiseMin(hi);
    if (q == p) return -std::min((p - lo).minCoeff(), (hi - p).minCoeff());
    return (p - q).norm();
  }, 1);
  const BoxContainer<2> rect(Vec2(0, 0), Vec2(1, 5));
  compare_on_random_points<2>(rect, [](const Vec2& p) {
    const Vec2 q = p.cwiseMax(Vec2(0, 0)).cwiseMin(Vec2(1, 5));
    if (q == p) return -std::min({p.x(), p.y(), 1 - p.x(), 5 - p.y()});
    return (p - q).norm();
  }, 2);
  // 1e-12 off a face, an edge and a corner, both sides.
  const ContainmentCheck<3> c(box);
  EXPECT_NEAR(c.signed_distance(Vec3(3 + 1e-12, 2.2, 1)), 1e-12, 1e-15);
  EXPECT_NEAR(c.signed_distance(Vec3(3 - 1e-12, 2.2, 1)), -1e-12, 1e-15);
  EXPECT_NEAR(c.signed_distance(Vec3(3 + 1e-12, 2.5 + 1e-12, 1)), std::sqrt(2.0) * 1e-12, 1e-15);
  EXPECT_NEAR(c.signed_distance(Vec3(-1 - 1e-12, 2 - 1e-12, 0.5 - 1e-12)), std::sqrt(3.0) * 1e-12, 1e-15);
  EXPECT_LT(c.signed_distance(Vec3(-1 + 1e-12, 2 + 1e-12, 0.5 + 1e-12)), 0.0);
}

TEST(ContainmentCheck, BallsAndDisks) {
  const BallContainer<3> ball(Vec3(1, -2, 3), 0.7);
  compare_on_random_points<3>(ball, [](const Vec3& p) { return std::sqrt((p - Vec3(1, -2, 3)).squaredNorm()) - 0.7; }, 3);
  const BallContainer<2> disk(Vec2(5, 5), 2.0);
  compare_on_random_points<2>(disk, [](const Vec2& p) { return std::hypot(p.x() - 5, p.y() - 5) - 2.0; }, 4);
}

TEST(ContainmentCheck, ObliqueCylinder) {
  const Vec3 base(0.3, -0.2, 1.0), axis = Vec3(1, 2, 2) / 3.0;
  const double R = 0.4, H = 1.5;
  const CylinderContainer cyl(base, 3.0 * axis, R, H);  // a non-unit axis: the container normalises it
  // Reference in the cylinder's own frame, built from an orthonormal basis (e1, e2, axis).
  const Vec3 e1 = Vec3(2, -1, 0).normalized(), e2 = axis.cross(e1);
  auto reference = [&](const Vec3& p) {
    const Vec3 d = p - base;
    const double t = d.dot(axis), rho = std::hypot(d.dot(e1), d.dot(e2));
    const double dt = t < 0 ? -t : (t > H ? t - H : 0.0), dr = rho > R ? rho - R : 0.0;
    if (dt == 0 && dr == 0) return -std::min({t, H - t, R - rho});
    return std::sqrt(dt * dt + dr * dr);
  };
  compare_on_random_points<3>(cyl, reference, 5);
  const ContainmentCheck<3> c(cyl);
  // 1e-12 off the lateral surface, a cap and the rim; on the axis (rho = 0 keeps its digits).
  const Vec3 on_side = base + 0.7 * axis + R * e1, rim = base + H * axis + R * e2;
  EXPECT_NEAR(c.signed_distance(on_side + 1e-12 * e1), 1e-12, 2e-16);
  EXPECT_NEAR(c.signed_distance(on_side - 1e-12 * e1), -1e-12, 2e-16);
  EXPECT_NEAR(c.signed_distance(base - 1e-12 * axis), 1e-12, 2e-16);
  EXPECT_NEAR(c.signed_distance(rim + 1e-12 * (axis + e2)), std::sqrt(2.0) * 1e-12, 2e-16);
  EXPECT_NEAR(c.signed_distance(base + 1e-3 * axis), -1e-3, 1e-15);
}

TEST(ContainmentCheck, NonConvexPolygons) {
  std::vector<Vec2> l = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)};
  std::vector<Vec2> star;  // clockwise, 7 reflex vertices
  for (int k = 13; k >= 0; --k) {
    const double phi = kPi * k / 7, r = k % 2 ? 0.45 : 1.0;
    star.emplace_back(3 + r * std::cos(phi), -1 + r * std::sin(phi));
  }
  for (const std::vector<Vec2>* poly : {&l, &star}) {
    const PolygonContainer pc(*poly);
    compare_on_random_points<2>(pc, [&](const Vec2& p) {
      const double d = testref::polygon_boundary_distance(*poly, p);
      return testref::winding_by_angles(*poly, p) != 0 ? -d : d;
    }, 6);
  }
  // Around the reflex vertex (1, 1) of the L, 1e-12 away: outside only in the missing quadrant,
  // where the nearest point is the vertex; horizontal rays through vertices count once.
  const ContainmentCheck<2> c{PolygonContainer(l)};
  for (int deg = 5; deg < 360; deg += 10) {
    const double th = deg * kPi / 180.0;
    const Vec2 p = Vec2(1, 1) + 1e-12 * Vec2(std::cos(th), std::sin(th));
    EXPECT_EQ(c.signed_distance(p) > 0, deg < 90) << deg;
    if (deg < 90) EXPECT_NEAR(c.signed_distance(p), 1e-12 * std::min(std::cos(th), std::sin(th)), 3e-16) << deg;
  }
  int through_vertices = 0;
  for (const double y : {0.0, 1.0, 2.0})
    for (const double x : {-0.5, 0.5, 1.5, 2.5}) {
      const Vec2 p(x, y);  // the ray along +x passes through vertices of the L
      if (testref::polygon_boundary_distance(l, p) == 0.0) continue;
      EXPECT_EQ(c.signed_distance(p) < 0, testref::winding_by_angles(l, p) != 0) << p.transpose();
      ++through_vertices;
    }
  EXPECT_GE(through_vertices, 6);
}

TEST(ContainmentCheck, MeshesAgreeWithTheContainerAndBruteForce) {
  for (const char* name : {"femur.off", "octahedron_binary.stl", "box_quads.obj"}) {
    const auto mesh = MeshContainer::from_file(test::mesh_path(name));
    const auto& v = mesh->vertices();
    const auto& t = mesh->triangles();
    compare_on_random_points<3>(*mesh, [&](const Vec3& p) {
      const double d = testref::mesh_distance(v, t, p);
      return testref::inside_by_ray_parity(v, t, p) ? -d : d;
    }, 7, std::string(name) == "femur.off" ? 200 : 1500);
  }
}

// A container whose own code says every ball is inside: the check does not know its kind, so it
// refuses to judge instead of passing the packing.
class TrustMe final : public Container<3> {
 public:
  bool inside(const Vec3&) const override { return true; }
  double signed_distance(const Vec3&) const override { return -1e300; }
  Aabb<3> bounds() const override { return {Vec3::Zero(), Vec3::Ones()}; }
  double measure() const override { return 1.0; }
  void walls_near(const Vec3&, double, std::vector<Wall<3>>&) const override {}
  Vec3 interior_point() const override { return Vec3::Constant(0.5); }
  std::string describe() const override { return "trust-me region"; }
};

TEST(ContainmentCheck, AnUnknownContainerKindIsAnErrorNotAPass) {
  testref::expect_invalid([] { ContainmentCheck<3> c{TrustMe()}; }, {"trust-me region", "cannot be validated"});
  Packing<3> p;
  p.add(Vec3(5, 5, 5), 0.1);  // far outside the unit cube its bounds claim
  testref::expect_invalid([&] { validate_packing<3>(p, TrustMe(), nullptr); }, {"trust-me region"});
}

// The ball criterion: centre inside and distance to the boundary >= r - tol r.
TEST(ContainmentCheck, ProtrusionOfBalls) {
  const BoxContainer<3> box(Vec3::Zero(), Vec3::Ones());
  const ContainmentCheck<3> c(box);
  EXPECT_NEAR(c.protrusion(Vec3(0.1, 0.5, 0.5), 0.1), 0.0, 1e-15);           // tangent
  EXPECT_NEAR(c.protrusion(Vec3(0.1 - 1e-10, 0.5, 0.5), 0.1), 1e-9, 1e-14);  // 1e-9 r beyond
  EXPECT_NEAR(c.protrusion(Vec3(-0.05, 0.5, 0.5), 0.1), 1.5, 1e-14);         // centre outside
  EXPECT_LT(c.protrusion(Vec3(0.5, 0.5, 0.5), 0.1), 0.0);
}

}  // namespace
}  // namespace fp
