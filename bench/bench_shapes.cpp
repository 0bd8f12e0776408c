// The general-shape machinery: narrow-phase gaps (analytic capsule and ellipsoid paths, the exact
// convex polygon and polytope-sphere paths, FCL polytope path), one capsule contact problem, by minimisation (per
// algorithm) and by the gap Newton solver, and one hexagon contact problem by the polygon wrapper.
// A separate executable: frontpack_bench (spheres) must link no FCL and no NLopt.
#include <benchmark/benchmark.h>

#include <array>
#include <vector>

#include "contact/gap_newton_solver.hpp"
#include "contact/minimisation_solver.hpp"
#include "contact/polygon_wrapper_solver.hpp"
#include "core/sampling/rng.hpp"
#include "shapes/shape_registry.hpp"
#include "shapes/ellipsoid_shape.hpp"
#include "shapes/sphere_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"

namespace {

using namespace fp;

Mat<3> random_rotation(Rng& rng) {
  const double u1 = rng.uniform01(), u2 = rng.uniform01(), u3 = rng.uniform01();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  return rotation_of<3>(Eigen::Vector4d(b * std::cos(2 * kPi * u3), a * std::sin(2 * kPi * u2), a * std::cos(2 * kPi * u2),
                                        b * std::sin(2 * kPi * u3)));
}

/// Particles of `shape` at random poses in a cube of side `side`.
std::vector<Particle<3>> scatter(const ShapePtr<3>& shape, int n, double side, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Particle<3>> out(static_cast<std::size_t>(n));
  for (auto& p : out) {
    p.shape = shape;
    p.pose.position = Vec3(rng.uniform(0, side), rng.uniform(0, side), rng.uniform(0, side));
    p.pose.rotation = random_rotation(rng);
  }
  return out;
}

ShapePtr<3> icosahedron() {
  ParticleTemplateSpec spec;
  spec.family = "polyhedron";
  spec.parameters.strings["preset"] = "icosahedron";
  return ShapeFamilies::builtin().prototype<3>(spec).shape;
}

/// The gap of consecutive particles of `ps` (1,024 of them), one per iteration.
template <int D>
void gap_loop(benchmark::State& state, const std::vector<Particle<D>>& ps) {
  NarrowPhase<D> np;
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(np.gap(ps[k & 1023], ps[(k + 1) & 1023]));
    ++k;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_GapCapsuleCapsule(benchmark::State& state) {
  const auto ps = scatter(std::make_shared<SpherocylinderShape<3>>(0.5, 0.5), 1024, 3.0, 1);
  gap_loop(state, ps);
}
BENCHMARK(BM_GapCapsuleCapsule);

/// FCL path: icosahedra (GJK apart, EPA on overlap); the cube side sets the overlapping share.
void BM_GapPolyhedronFcl(benchmark::State& state) {
  const auto ps = scatter(icosahedron(), 1024, static_cast<double>(state.range(0)) / 10.0, 2);
  gap_loop(state, ps);
}
BENCHMARK(BM_GapPolyhedronFcl)->Arg(15)->Arg(60);

/// Icosahedra against spheres of the same circumscribed radius, alternately: the exact
/// polytope-ball gap (face planes inside, nearest facet point outside; FCL's GJK before it).
void BM_GapPolyhedronSphere(benchmark::State& state) {
  const double side = static_cast<double>(state.range(0)) / 10.0;
  auto ps = scatter(icosahedron(), 1024, side, 4);
  const auto ball = std::make_shared<SphereShape<3>>(1.0);
  for (std::size_t k = 1; k < ps.size(); k += 2) ps[k].shape = ball;
  gap_loop(state, ps);
}
BENCHMARK(BM_GapPolyhedronSphere)->Arg(15)->Arg(60);

/// Ellipsoids [1, 0.7, 0.5] (contact/ellipsoid_gap.hpp: Newton on the support functions); the
/// cube side sets the overlapping share (15: most pairs overlap, 60: most are apart).
void BM_GapEllipsoid(benchmark::State& state) {
  const auto ps = scatter(std::make_shared<EllipsoidShape<3>>(Vec3(1, 0.7, 0.5)), 1024, static_cast<double>(state.range(0)) / 10.0, 3);
  gap_loop(state, ps);
}
BENCHMARK(BM_GapEllipsoid)->Arg(15)->Arg(60);

/// Contact problems: a capsule (aspect ratio 0.5, identity orientation) against three capsules
/// at random poses in a cube of side 2.5 (most have no solution, as in the front's pair scan);
/// one solve per iteration, cycling through 256 problems.
void capsule_solves(benchmark::State& state, const ContactSolver<3>& solver, const char* label) {
  const auto shape = std::make_shared<SpherocylinderShape<3>>(0.5, 0.5);
  auto fixed = scatter(shape, 3 * 256, 2.5, 3);
  std::vector<std::array<Body<3>, 3>> problems;
  for (int k = 0; k < 256; ++k)
    problems.push_back({Body<3>::of_particle(fixed[3 * k]), Body<3>::of_particle(fixed[3 * k + 1]),
                        Body<3>::of_particle(fixed[3 * k + 2])});
  const Mobile<3> mobile = Mobile<3>::of_shape(shape, Mat<3>::Identity());
  std::array<Placement<3>, 4> out;
  std::size_t k = 0;
  int found = 0;
  for (auto _ : state) found += solver.solve(problems[k++ & 255], mobile, out);
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(label);
  state.counters["solutions_per_solve"] = static_cast<double>(found) / static_cast<double>(state.iterations());
}

/// By minimisation; args: algorithm index (slsqp, lbfgs, nelder-mead).
void BM_MinimisationCapsules(benchmark::State& state) {
  const char* names[] = {"slsqp", "lbfgs", "nelder-mead"};
  MinimisationOptions o;
  o.algorithm = names[state.range(0)];
  if (o.algorithm == "nelder-mead") o.max_evaluations = 600;
  NarrowPhase<3> np;
  capsule_solves(state, MinimisationSolver<3>(np, o), names[state.range(0)]);
}
BENCHMARK(BM_MinimisationCapsules)->Arg(0)->Arg(1)->Arg(2);

/// The same problems by the gap Newton solver (the registry's choice for capsules).
void BM_GapNewtonCapsules(benchmark::State& state) {
  NarrowPhase<3> np;
  capsule_solves(state, GapNewtonSolver<3>(np, MinimisationOptions{}.gap_tolerance), "gap newton");
}
BENCHMARK(BM_GapNewtonCapsules);

/// Regular hexagons of circumscribed radius 1 at random poses in a square of side `side`.
std::vector<Particle<2>> scatter_hexagons(int n, double side, std::uint64_t seed) {
  ParticleTemplateSpec spec;
  spec.family = "polygon";
  spec.parameters.numbers["sides"] = 6;
  const ShapePtr<2> hexagon = ShapeFamilies::builtin().prototype<2>(spec).shape;
  Rng rng(seed);
  std::vector<Particle<2>> out(static_cast<std::size_t>(n));
  for (auto& p : out) {
    p.shape = hexagon;
    p.pose.position = Vec2(rng.uniform(0, side), rng.uniform(0, side));
    p.pose.rotation = rotation_2d(2 * kPi * rng.uniform01());
  }
  return out;
}

/// Two convex polygons (separating axes on overlap, nearest points apart: no FCL); the square's
/// side sets the overlapping share (15: most pairs overlap, 60: most are apart).
void BM_GapPolygons(benchmark::State& state) {
  gap_loop(state, scatter_hexagons(1024, static_cast<double>(state.range(0)) / 10.0, 4));
}
BENCHMARK(BM_GapPolygons)->Arg(15)->Arg(60);

/// Contact problems of the 2D front: a hexagon (fixed orientation) against two hexagons at random
/// poses in a square of side 4 (some without a solution), one solve per iteration, cycling
/// through 256 problems; the first body stays for 8 problems in a row, as s0 does in the front.
void BM_PolygonWrapperHexagons(benchmark::State& state) {
  const auto fixed = scatter_hexagons(2 * 256, 4.0, 5);
  std::vector<std::array<Body<2>, 2>> problems;
  for (int k = 0; k < 256; ++k)
    problems.push_back({Body<2>::of_particle(fixed[static_cast<std::size_t>(2 * (k / 8 * 8))]),
                        Body<2>::of_particle(fixed[static_cast<std::size_t>(2 * k + 1)])});
  const Mobile<2> mobile = Mobile<2>::of_shape(fixed[0].shape, rotation_2d(0.3));
  const PolygonWrapperSolver solver;
  std::array<Placement<2>, 4> out;
  std::size_t k = 0;
  int found = 0;
  for (auto _ : state) found += solver.solve(problems[k++ & 255], mobile, out);
  state.SetItemsProcessed(state.iterations());
  state.counters["solutions_per_solve"] = static_cast<double>(found) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_PolygonWrapperHexagons);

}  // namespace
