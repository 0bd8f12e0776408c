// The solver registry (contact/solver_registry.cpp): which contact solver a problem goes to.
// A registered solver is used only when EVERY pair of the problem has it, the latest registered
// first: the analytic sphere solver for spheres and walls alone, the ball wrapper where clusters
// join them, the ellipsoid solver where ellipsoids do (with spheres and plane walls); what no
// closed form covers (an ellipsoid with a cluster) the gap Newton solver, registered first for
// every pair of built-in kinds; a kind no solver is registered for: minimisation, the default.
#include <gtest/gtest.h>

#include <atomic>

#include "contact/ball_wrapper_solver.hpp"
#include "contact/ellipsoid_contact_solver.hpp"
#include "contact/gap_newton_solver.hpp"
#include "contact/polygon_wrapper_solver.hpp"
#include "contact/solver_registry.hpp"
#include "contact/sphere_contact_solver.hpp"
#include "general_contact_support.hpp"

namespace fp::general_test {
namespace {

template <int D>
bool is_analytic(const ContactSolver<D>& s) {
  return dynamic_cast<const SphereContactSolver<D>*>(&s) != nullptr;
}
template <int D>
bool is_ball_wrapper(const ContactSolver<D>& s) {
  return dynamic_cast<const BallWrapperSolver<D>*>(&s) != nullptr;
}
template <int D>
bool is_ellipsoid_solver(const ContactSolver<D>& s) {
  return dynamic_cast<const EllipsoidContactSolver<D>*>(&s) != nullptr;
}
bool is_polygon_wrapper(const ContactSolver<2>& s) { return dynamic_cast<const PolygonWrapperSolver*>(&s) != nullptr; }
template <int D>
bool is_gap_newton(const ContactSolver<D>& s) {
  return dynamic_cast<const GapNewtonSolver<D>*>(&s) != nullptr;
}
template <int D>
bool is_minimisation(const ContactSolver<D>& s) {
  return dynamic_cast<const MinimisationSolver<D>*>(&s) != nullptr;
}

/// A solver that only counts its calls (for overrides).
template <int D>
struct CountingSolver final : ContactSolver<D> {
  mutable int calls = 0;
  int solve(std::span<const Body<D>>, const Mobile<D>&, std::span<Placement<D>>) const override {
    ++calls;
    return 0;
  }
};

template <int D>
Particle<D> particle(ShapePtr<D> s, const Vec<D>& x) {
  Particle<D> p;
  p.shape = std::move(s);
  p.pose.position = x;
  return p;
}

template <int D>
void picks_round() {
  NarrowPhase<D> np;
  const SolverRegistry<D> reg(np, MinimisationOptions{});
  ASSERT_TRUE(is_minimisation<D>(reg.default_solver()));
  const auto sphere = std::make_shared<SphereShape<D>>(1.0);
  const auto ellipsoid = std::make_shared<EllipsoidShape<D>>(Vec<D>::Constant(0.5));
  const Mobile<D> sphere_mobile = Mobile<D>::of_shape(sphere, Mat<D>::Identity());
  const Mobile<D> ellipsoid_mobile = Mobile<D>::of_shape(ellipsoid, Mat<D>::Identity());

  std::array<Particle<D>, D> spheres, ellipsoids;
  for (int i = 0; i < D; ++i) {
    Vec<D> x = Vec<D>::Zero();
    x[i % D] = 2.0 * (i + 1);
    spheres[i] = particle<D>(sphere, x);
    ellipsoids[i] = particle<D>(ellipsoid, x);
  }
  std::array<Body<D>, D> f;

  // Sphere mobile + sphere particles (shaped or plain centre + radius): analytic.
  for (int i = 0; i < D; ++i) f[i] = Body<D>::of_particle(spheres[i], i);
  EXPECT_TRUE(is_analytic<D>(reg.pick(f, sphere_mobile)));
  for (int i = 0; i < D; ++i) f[i] = Body<D>::sphere(spheres[i].pose.position, 1.0, i);
  EXPECT_TRUE(is_analytic<D>(reg.pick(f, sphere_mobile)));

  // An ellipsoid with spheres (mobile, one fixed body, all fixed bodies): the ellipsoid solver.
  EXPECT_TRUE(is_ellipsoid_solver<D>(reg.pick(f, ellipsoid_mobile)));
  f[D - 1] = Body<D>::of_particle(ellipsoids[D - 1], D - 1);
  EXPECT_TRUE(is_ellipsoid_solver<D>(reg.pick(f, sphere_mobile)));
  for (int i = 0; i < D; ++i) f[i] = Body<D>::of_particle(ellipsoids[i], i);
  EXPECT_TRUE(is_ellipsoid_solver<D>(reg.pick(f, sphere_mobile)));
  EXPECT_TRUE(is_ellipsoid_solver<D>(reg.pick(f, ellipsoid_mobile)));

  // A wall and spheres: analytic; a plane wall and an ellipsoid: the ellipsoid solver.
  const Wall<D> wall = Wall<D>::plane(Vec<D>::Zero(), Vec<D>::UnitX());
  for (int i = 0; i < D; ++i) f[i] = Body<D>::of_particle(spheres[i], i);
  f[0] = Body<D>::of_wall(wall);
  EXPECT_TRUE(is_analytic<D>(reg.pick(f, sphere_mobile)));
  EXPECT_TRUE(is_ellipsoid_solver<D>(reg.pick(f, ellipsoid_mobile)));
  f[D - 1] = Body<D>::of_particle(ellipsoids[D - 1], D - 1);
  EXPECT_TRUE(is_ellipsoid_solver<D>(reg.pick(f, sphere_mobile)));

  // A plain sphere mobile (radius only, the sphere fast path's form) against spheres: the
  // analytic solver, which needs no shape (the minimisation solver cannot solve it).
  for (int i = 0; i < D; ++i) f[i] = Body<D>::sphere(spheres[i].pose.position, 1.0, i);
  EXPECT_TRUE(is_analytic<D>(reg.pick(f, plain_sphere<D>(1.0))));

  // Clusters with spheres and walls: the ball wrapper, mobile or fixed; with an ellipsoid: gap Newton.
  std::vector<Ball<D>> members(2);
  members[1].center[0] = 1.0;
  members[0].radius = members[1].radius = 0.6;
  const auto cluster = std::make_shared<ClusterShape<D>>(members);
  const Mobile<D> cluster_mobile = Mobile<D>::of_shape(cluster, Mat<D>::Identity());
  std::array<Particle<D>, D> clusters;
  for (int i = 0; i < D; ++i) clusters[i] = particle<D>(cluster, spheres[i].pose.position);
  for (int i = 0; i < D; ++i) f[i] = Body<D>::of_particle(spheres[i], i);
  EXPECT_TRUE(is_ball_wrapper<D>(reg.pick(f, cluster_mobile)));
  f[0] = Body<D>::of_wall(wall);
  EXPECT_TRUE(is_ball_wrapper<D>(reg.pick(f, cluster_mobile)));
  f[D - 1] = Body<D>::of_particle(clusters[D - 1], D - 1);
  EXPECT_TRUE(is_ball_wrapper<D>(reg.pick(f, sphere_mobile)));
  EXPECT_TRUE(is_ball_wrapper<D>(reg.pick(f, plain_sphere<D>(1.0))));
  f[D - 1] = Body<D>::of_particle(ellipsoids[D - 1], D - 1);
  EXPECT_TRUE(is_gap_newton<D>(reg.pick(f, cluster_mobile)));  // no closed form takes ellipsoid and cluster
  EXPECT_TRUE(is_ellipsoid_solver<D>(reg.pick(f, sphere_mobile)));
}

TEST(SolverRegistry, Picks2D) { picks_round<2>(); }

// 2D stadiums and polygons, with disks, clusters and walls: the polygon wrapper; with an ellipse
// (no rounded cores): gap Newton.
TEST(SolverRegistry, PicksThePolygonWrapperIn2D) {
  NarrowPhase<2> np;
  const SolverRegistry<2> reg(np, MinimisationOptions{});
  const auto capsule = std::make_shared<SpherocylinderShape<2>>(0.5, 0.5);
  const auto disk = std::make_shared<SphereShape<2>>(1.0);
  const auto ellipse = std::make_shared<EllipsoidShape<2>>(Vec2(1.0, 0.5));
  const Particle<2> c = particle<2>(capsule, Vec2(2, 0)), d = particle<2>(disk, Vec2(0, 2)), e = particle<2>(ellipse, Vec2(2, 2));
  const Wall<2> wall = Wall<2>::plane(Vec2::Zero(), Vec2::UnitX());
  std::array<Body<2>, 2> f = {Body<2>::of_particle(c, 0), Body<2>::of_particle(d, 1)};
  EXPECT_TRUE(is_polygon_wrapper(reg.pick(f, Mobile<2>::of_shape(disk, Mat<2>::Identity()))));
  EXPECT_TRUE(is_polygon_wrapper(reg.pick(f, Mobile<2>::of_shape(capsule, Mat<2>::Identity()))));
  f[1] = Body<2>::of_wall(wall);
  EXPECT_TRUE(is_polygon_wrapper(reg.pick(f, Mobile<2>::of_shape(capsule, Mat<2>::Identity()))));
  f[1] = Body<2>::of_particle(e, 2);
  EXPECT_TRUE(is_gap_newton<2>(reg.pick(f, Mobile<2>::of_shape(capsule, Mat<2>::Identity()))));
}
TEST(SolverRegistry, Picks3D) { picks_round<3>(); }

/// A shape of a kind no solver is registered for (a family added without solvers): only its
/// kind is read by the registry.
template <int D>
struct UnregisteredShape final : Shape<D> {
  const char* kind() const override { return "unregistered"; }
  double measure() const override { return 1.0; }
  double bounding_radius() const override { return 0.5; }
  double inscribed_radius() const override { return 0.5; }
  Vec<D> support(const Vec<D>& u) const override { return 0.5 * u.normalized(); }
  bool contains(const Vec<D>& x) const override { return x.norm() <= 0.5; }
  std::vector<Ball<D>> hull_balls() const override { return {Ball<D>{Vec<D>::Zero(), 0.5}}; }
  SurfaceMesh<D> surface(int) const override { return {}; }
  std::vector<FclPart<D>> fcl_parts() const override { return {}; }
  ShapePtr<D> scaled(double) const override { return std::make_shared<UnregisteredShape>(); }
  std::string definition_json() const override { return "{}"; }
};

template <int D>
void override_round() {
  NarrowPhase<D> np;
  SolverRegistry<D> reg(np, MinimisationOptions{});
  const auto sphere = std::make_shared<SphereShape<D>>(1.0);
  const auto ellipsoid = std::make_shared<EllipsoidShape<D>>(Vec<D>::Constant(0.5));
  std::array<Particle<D>, D> spheres, ellipsoids;
  for (int i = 0; i < D; ++i) {
    Vec<D> x = Vec<D>::Zero();
    x[i % D] = 2.0 * (i + 1);
    spheres[i] = particle<D>(sphere, x);
    ellipsoids[i] = particle<D>(ellipsoid, x);
  }
  const Mobile<D> ellipsoid_mobile = Mobile<D>::of_shape(ellipsoid, Mat<D>::Identity());
  const Mobile<D> sphere_mobile = Mobile<D>::of_shape(sphere, Mat<D>::Identity());
  std::array<Body<D>, D> f;
  for (int i = 0; i < D; ++i) f[i] = Body<D>::of_particle(ellipsoids[i], i);

  // Capsule against ellipsoids registered: used for all-ellipsoid problems only.
  auto counting = std::make_shared<CountingSolver<D>>();
  reg.add_pair(EllipsoidShape<D>::kKind, EllipsoidShape<D>::kKind, counting);
  EXPECT_EQ(&reg.pick(f, ellipsoid_mobile), counting.get());
  std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> out;
  reg.pick(f, ellipsoid_mobile).solve(f, ellipsoid_mobile, out);
  EXPECT_EQ(counting->calls, 1);
  f[0] = Body<D>::of_particle(spheres[0], 0);
  EXPECT_TRUE(is_ellipsoid_solver<D>(reg.pick(f, ellipsoid_mobile)));  // sphere-ellipsoid has no override
  reg.add_pair("sphere", EllipsoidShape<D>::kKind, counting);            // now every pair has the same one
  EXPECT_EQ(&reg.pick(f, ellipsoid_mobile), counting.get());

  // A later solver for sphere-sphere takes the all-sphere problems; wall + spheres, which it does
  // not cover, stays with the analytic solver (registered for both pairs).
  auto other = std::make_shared<CountingSolver<D>>();
  reg.add_pair("sphere", "sphere", other);
  for (int i = 0; i < D; ++i) f[i] = Body<D>::of_particle(spheres[i], i);
  EXPECT_EQ(&reg.pick(f, sphere_mobile), other.get());
  const Wall<D> wall = Wall<D>::plane(Vec<D>::Zero(), Vec<D>::UnitX());
  f[0] = Body<D>::of_wall(wall);
  EXPECT_TRUE(is_analytic<D>(reg.pick(f, sphere_mobile)));
  reg.add_pair(kPlaneWall, "sphere", other);  // now it covers both
  EXPECT_EQ(&reg.pick(f, sphere_mobile), other.get());

  // A new default: what no registered solver covers (a kind no solver is registered for: a
  // cluster against such a body; against an ellipsoid, the gap Newton solver).
  auto fallback = std::make_shared<CountingSolver<D>>();
  reg.set_default(fallback);
  EXPECT_EQ(&reg.default_solver(), fallback.get());
  f[D - 1] = Body<D>::of_particle(ellipsoids[D - 1], D - 1);
  std::vector<Ball<D>> members(2);
  members[1].center[0] = 1.0;
  members[0].radius = members[1].radius = 0.6;
  const Mobile<D> cluster_mobile = Mobile<D>::of_shape(std::make_shared<ClusterShape<D>>(members), Mat<D>::Identity());
  EXPECT_TRUE(is_gap_newton<D>(reg.pick(f, cluster_mobile)));
  const Particle<D> odd = particle<D>(std::make_shared<UnregisteredShape<D>>(), spheres[D - 1].pose.position);
  f[D - 1] = Body<D>::of_particle(odd, D - 1);
  EXPECT_EQ(&reg.pick(f, cluster_mobile), fallback.get());
}

TEST(SolverRegistry, OverridesAPair2D) { override_round<2>(); }
TEST(SolverRegistry, OverridesAPair3D) { override_round<3>(); }

/// End to end: the picked solver solves a wall + spheres problem (analytic), a wall + spheres
/// problem of an ellipsoid (the ellipsoid solver) and one with a cluster too (gap Newton), and
/// every position passes the independent check.
template <int D>
void solves_round(std::uint64_t seed) {
  NarrowPhase<D> np;
  const SolverRegistry<D> reg(np, MinimisationOptions{});
  Rng rng(seed);
  int analytic = 0, smooth = 0, newton = 0, positions = 0;
  for (int t = 0; t < 30; ++t) {
    std::array<Kind, D> kinds;
    kinds.fill(Kind::Sphere);
    kinds[0] = Kind::Plane;
    const bool ellipsoid = t % 3 != 0, cluster = t % 3 == 2;
    if (cluster) kinds[D - 1] = Kind::Cluster;
    Problem<D> pb;
    if (!construct_problem<D>(pb, np, ellipsoid ? Kind::Ellipsoid : Kind::Sphere, kinds, Sizes{}, rng)) continue;
    const ContactSolver<D>& s = reg.pick(pb.span(), pb.mobile());
    EXPECT_EQ(is_analytic<D>(s), !ellipsoid);
    EXPECT_EQ(is_ellipsoid_solver<D>(s), ellipsoid && !cluster);
    EXPECT_EQ(is_gap_newton<D>(s), cluster);
    analytic += is_analytic<D>(s);
    smooth += is_ellipsoid_solver<D>(s);
    newton += is_gap_newton<D>(s);
    std::array<Placement<D>, ContactSolver<D>::kMaxSolutions> out;
    const int n = s.solve(pb.span(), pb.mobile(), out);
    positions += n;
    EXPECT_TRUE(check_placements<D>(pb, std::span<const Placement<D>>(out.data(), n), 1e-6));
    EXPECT_GT(n, 0) << pb.literal();
  }
  EXPECT_GT(analytic, 5);
  EXPECT_GT(smooth, 5);
  EXPECT_GT(newton, 5);
  EXPECT_GT(positions, 30);
}

TEST(SolverRegistry, PickedSolversSolve2D) { solves_round<2>(901); }
TEST(SolverRegistry, PickedSolversSolve3D) { solves_round<3>(902); }

}  // namespace
}  // namespace fp::general_test
