// The advancing front for general shapes (front/shape_front.hpp): every shape family in 2D and 3D
// where it exists, in a box and in a non-convex container (an L-shaped polygon, an L-shaped
// prism mesh; growth starts next to the reflex corner / edge so that it is exercised), checked
// by the independent code of shape_test_checks.hpp (no narrow phase, no FCL), and against
// contact/shape_validation.hpp. Runs are small (tens of particles) to keep the suite fast.
#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "contact/shape_validation.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/local_frame.hpp"
#include "core/geometry/mesh_container.hpp"
#include "core/metrics/orientation_fit.hpp"
#include "core/geometry/polygon_container.hpp"
#include "core/sampling/ks_test.hpp"
#include "front/pack_shapes_scene.hpp"
#include "front/shape_front.hpp"
#include "front/shape_template.hpp"
#include "shape_test_checks.hpp"

namespace fptest {
namespace {

/// The packer's overlap / containment tolerance (MinimisationOptions::gap_tolerance, relative to
/// the smaller circumscribed radius), and the slack the independent checks allow on top of it
/// (their own rounding: long double for swept spheres and polytopes).
constexpr double kTol = 1e-6;
constexpr double kCheckTol = kTol * (1 + 1e-6) + 1e-12;
/// "Touches": a lower bound of the gap within this fraction of R (the solver's contacts are
/// exact to kTol; the support-function bound is refined to ~1e-9).
constexpr double kTouchTol = 1e-5;

enum class Where { Box, NonConvex, CubeStl };

template <int D>
struct PackSetup {
  fp::ContainerPtr<D> container;
  SignedDistance<D> sd;                   ///< independent of the container classes
  std::vector<Vec<D>> wall_normals;       ///< inward normals of the planar walls
  std::vector<Vec<D>> boundary_points;    ///< non-convex containers: vertices and points along edges
  std::optional<std::vector<double>> seed_point;
  const char* name = "";
};

template <int D>
PackSetup<D> make_setup(Where where) {
  PackSetup<D> s;
  if (where == Where::Box) {
    Vec<D> lo = Vec<D>::Zero(), hi = Vec<D>::Constant(D == 2 ? 6.0 : 2.5);
    s.container = std::make_shared<fp::BoxContainer<D>>(lo, hi);
    s.sd = box_distance<D>(lo, hi);
    s.name = D == 2 ? "box [0,6]^2" : "box [0,2.5]^3";
    return s;
  }
  if constexpr (D == 2) {
    // The L [0,6]^2 minus [3,6]^2; its reflex corner is (3, 3); growth starts next to it.
    const std::vector<Vec2> v = {Vec2(0, 0), Vec2(6, 0), Vec2(6, 3), Vec2(3, 3), Vec2(3, 6), Vec2(0, 6)};
    s.container = std::make_shared<fp::PolygonContainer>(v);
    s.sd = polygon_distance(v);
    std::vector<std::pair<Vec2, Vec2>> edges;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Vec2 a = v[i], b = v[(i + 1) % v.size()];
      edges.push_back({a, b});
      s.wall_normals.push_back(Vec2(-(b - a).y(), (b - a).x()));
    }
    s.boundary_points = points_along<2>(edges, 64);
    s.seed_point = std::vector<double>{2.7, 2.7};
    s.name = "L polygon";
  } else {
    std::shared_ptr<fp::MeshContainer> mesh;
    if (where == Where::CubeStl) {
      mesh = fp::MeshContainer::from_file(std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/meshes/cube.stl");
      s.name = "cube.stl";
    } else {
      // tests/data/scenes-e2e/l_prism.off x 7.5: the L [0,3]^2 minus [1.5,3]^2, height 2.25; its
      // reflex edge is x = y = 1.5; growth starts next to it.
      mesh = fp::MeshContainer::from_file(std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/scenes-e2e/l_prism.off", 7.5);
      s.seed_point = std::vector<double>{1.35, 1.35, 1.1};
      s.name = "L prism mesh";
    }
    const auto& V = mesh->vertices();
    const auto& T = mesh->triangles();
    s.sd = mesh_distance(V, T);
    std::vector<std::pair<Vec3, Vec3>> edges;
    for (const auto& t : T) {
      const Vec3 a = V[static_cast<std::size_t>(t[0])], b = V[static_cast<std::size_t>(t[1])], c = V[static_cast<std::size_t>(t[2])];
      s.wall_normals.push_back(-(b - a).cross(c - a));  // triangles are outward
      edges.push_back({a, b});
      edges.push_back({b, c});
      edges.push_back({c, a});
    }
    s.boundary_points = points_along<3>(edges, 48);
    s.container = mesh;
  }
  return s;
}

template <int D>
struct PackRun {
  std::vector<fp::ShapeTemplate<D>> templates;
  fp::ShapePackResult<D> res;
  double seconds = 0;
};

/// Packs `particles` (the YAML of a scene's particles list) in the setup's container.
template <int D>
PackRun<D> pack_run(const std::string& particles, const PackSetup<D>& setup, std::uint64_t max_particles, std::uint64_t seed,
                const std::function<void(fp::PackerOptions&)>& tweak = {}) {
  const std::string container = D == 2 ? "container: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
                                       : "container: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n";
  const fp::Scene scene = scene_from_yaml("dimension: " + std::to_string(D) + "\n" + container + "particles:\n" + particles);
  PackRun<D> run;
  run.templates = fp::resolve_templates<D>(scene);
  fp::PackerOptions opt = scene.packer;
  opt.seed_point = setup.seed_point;
  if (tweak) tweak(opt);
  fp::StopCriteria stop;
  stop.max_particles = max_particles;
  const auto t0 = std::chrono::steady_clock::now();
  run.res = fp::pack_shapes<D>(*setup.container, run.templates, opt, stop, seed);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return run;
}

/// Every independent check of one packing.
template <int D>
void check_packing(const PackRun<D>& run, const PackSetup<D>& setup, std::uint64_t expect_n) {
  const fp::ShapePacking<D>& P = run.res.packing;
  const auto& ps = P.particles;
  SCOPED_TRACE(std::string(setup.name) + ", " + std::to_string(ps.size()) + " particles");
  ASSERT_EQ(ps.size(), expect_n) << "stop: " << fp::to_string(run.res.stop);
  EXPECT_EQ(run.res.stop, fp::StopReason::ParticleCount);
  EXPECT_EQ(run.res.contact_tolerance, kTol);

  // Sizes: within the template's range, the shape scaled by size * scale_per_size.
  double measure = 0;
  for (const auto& p : ps) {
    ASSERT_GE(p.template_id, 0);
    ASSERT_LT(p.template_id, static_cast<int>(run.templates.size()));
    const auto& t = run.templates[static_cast<std::size_t>(p.template_id)];
    EXPECT_GE(p.size, t.size->r_min());
    EXPECT_LE(p.size, t.size->r_max());
    EXPECT_NEAR(p.bounding_radius(), p.size * t.scale_per_size, 1e-12 * p.bounding_radius());
    EXPECT_STREQ(p.shape->kind(), t.prototype.shape->kind());
    measure += p.shape->measure();
  }
  EXPECT_NEAR(run.res.solid_measure, measure, 1e-9 * measure);

  // No overlap beyond the tolerance (independent).
  const ShapeOverlapReport ov = shape_overlaps(P, kTol);
  EXPECT_LE(ov.max_overlap_rel, kCheckTol) << "pair " << ov.worst_i << "-" << ov.worst_j;
  EXPECT_LE(ov.max_loose_overlap_rel, 1e-2) << "support-function bound of a cylinder pair far off";
  EXPECT_EQ(ov.max_intrusion_rel, 0.0) << "a sampled surface point is inside another particle";

  // Inside the container (independent), and no boundary point of a non-convex container inside a particle.
  const ShapeContainmentReport<D> in = shape_containment(P, setup.sd, setup.wall_normals, setup.boundary_points, kTol);
  EXPECT_LE(in.max_outside_rel, kCheckTol) << "particle " << in.worst;
  EXPECT_EQ(in.boundary_points_inside, 0u) << "e.g. into particle " << in.worst_boundary_particle;
  // The library's validation agrees.
  std::vector<fp::RequestedTemplate> requested;
  for (const auto& t : run.templates) requested.push_back({t.size.get(), t.fraction, &t.orientation});
  const fp::ValidationReport v = fp::validate_shapes<D>(P, *setup.container, run.res.contact_tolerance, requested);
  EXPECT_TRUE(v.ok) << v.summary();
  EXPECT_EQ(v.overlap_count, 0u);
  EXPECT_EQ(v.outside_count, 0u);
  EXPECT_LE(v.max_overlap_rel, kTol);
  EXPECT_LE(v.max_outside_rel, kTol);

  // Counters; every particle touches another one or a wall, but the first of each cluster.
  const fp::FrontCounters& c = run.res.counters;
  EXPECT_GT(c.solves, 0u);
  EXPECT_GE(c.solves, ps.size() - static_cast<std::size_t>(D) * (1 + c.voids_seeded));
  EXPECT_GE(c.candidates, c.rejected_overlap + c.rejected_container);
  EXPECT_GE(c.radii_drawn, ps.size());
  EXPECT_EQ(c.radii_drawn, ps.size() + c.radii_unplaced);
  EXPECT_GT(run.res.solver.minimisation_solves + run.res.solver.analytic_solves, 0u);
  EXPECT_EQ(c.solves, run.res.solver.minimisation_solves + run.res.solver.analytic_solves);
  std::size_t loose = 0, wall_touch = 0, particle_touch = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const bool touches_particle = ov.nearest_gap_rel[i] <= kTouchTol;
    const bool touches_wall = in.wall_gap_rel[i] <= kTouchTol;
    particle_touch += touches_particle;
    wall_touch += touches_wall;
    if (!touches_particle && !touches_wall) ++loose;
  }
  EXPECT_LE(loose, 1 + c.voids_seeded);
  EXPECT_GE(particle_touch, ps.size() - 1 - c.voids_seeded);

  std::printf("  [%s] %zu particles in %.3f s: %llu solves (%llu analytic), %llu minimisations, %llu FCL queries; "
              "max overlap %.3g (validation %.3g; cylinder pairs' loose bound %.3g), max outside %.3g, %zu touching a wall, %zu pairs checked\n",
              setup.name, ps.size(), run.seconds, static_cast<unsigned long long>(c.solves),
              static_cast<unsigned long long>(run.res.solver.analytic_solves),
              static_cast<unsigned long long>(run.res.solver.minimisations),
              static_cast<unsigned long long>(run.res.solver.fcl_queries), ov.max_overlap_rel, v.max_overlap_rel,
              ov.max_loose_overlap_rel, in.max_outside_rel, wall_touch, ov.pairs);
}

template <int D>
bool bitwise_same(const fp::ShapePacking<D>& a, const fp::ShapePacking<D>& b) {
  if (a.size() != b.size()) return false;
  auto same = [](double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); };
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto &p = a.particles[i], &q = b.particles[i];
    if (p.template_id != q.template_id || !same(p.size, q.size)) return false;
    for (int k = 0; k < D; ++k)
      if (!same(p.pose.position[k], q.pose.position[k])) return false;
    for (int r = 0; r < D; ++r)
      for (int k = 0; k < D; ++k)
        if (!same(p.pose.rotation(r, k), q.pose.rotation(r, k))) return false;
  }
  return true;
}

// ---- the families --------------------------------------------------------------------------

const std::string kSize = "    size: {distribution: uniform, min: 0.25, max: 0.4}\n";

const std::map<std::string, std::string> kFamilies2 = {
    {"sphere", "  - shape: sphere\n" + kSize},
    {"spherocylinder", "  - shape: spherocylinder\n    aspect_ratio: 0.5\n" + kSize},
    {"cluster", "  - shape: cluster\n    centers: [[-0.5, 0], [0.5, 0], [0.5, 0.8]]\n    radii: [0.5, 0.5, 0.4]\n" + kSize},
    {"polygon", "  - shape: polygon\n    sides: 5\n" + kSize + "    fraction: 2\n" +
                    "  - shape: polygon\n    vertices: [[0, 0], [2, 0], [0, 1]]\n" + kSize},
    {"ellipse", "  - shape: ellipse\n    axes: [1, 0.5]\n" + kSize},
};

const std::map<std::string, std::string> kFamilies3 = {
    {"sphere", "  - shape: sphere\n" + kSize},
    {"spherocylinder", "  - shape: spherocylinder\n    aspect_ratio: 0.5\n" + kSize},
    {"cluster", "  - shape: cluster\n    centers: [[-0.5, 0, 0], [0.5, 0, 0], [0.5, 0.8, 0]]\n    radii: [0.5, 0.5, 0.4]\n" + kSize},
    {"polyhedron", "  - shape: polyhedron\n    preset: cube\n" + kSize + "    fraction: 2\n" +
                       "  - shape: polyhedron\n    platonic: 4\n" + kSize},
    {"ellipsoid", "  - shape: ellipsoid\n    axes: [1, 0.7, 0.5]\n" + kSize},
    {"cylinder", "  - shape: cylinder\n    aspect_ratio: 1\n" + kSize},
};

/// Particles per run: small enough for a fast suite, enough to reach the walls and the reflex
/// corner / edge.
/// Ellipsoids and cylinders take ~0.25 s per particle (FCL), polyhedra ~0.08 s: fewer of them.
std::uint64_t count_for(int D, const std::string& family) {
  if (D == 2) return family == "ellipse" ? 40 : family == "sphere" ? 50 : 60;
  if (family == "sphere") return 35;  // the front exhausts at ~40 in these small containers
  if (family == "spherocylinder" || family == "cluster") return 50;
  if (family == "polyhedron") return 30;
  return 20;
}

struct FamilyCase {
  int dimension;
  std::string family;
  Where where;
};

std::ostream& operator<<(std::ostream& os, const FamilyCase& c) { return os << c.dimension << "D " << c.family; }

class ShapeFrontFamily : public ::testing::TestWithParam<FamilyCase> {};

template <int D>
void pack_and_check(const FamilyCase& fc) {
  const std::string& particles = (D == 2 ? kFamilies2 : kFamilies3).at(fc.family);
  const PackSetup<D> setup = make_setup<D>(fc.where);
  const std::uint64_t n = count_for(D, fc.family);
  const PackRun<D> run = pack_run<D>(particles, setup, n, 7);
  check_packing<D>(run, setup, n);
}

TEST_P(ShapeFrontFamily, IndependentChecks) {
  if (GetParam().dimension == 2) pack_and_check<2>(GetParam());
  else pack_and_check<3>(GetParam());
}

std::vector<FamilyCase> all_family_cases() {
  std::vector<FamilyCase> out;
  for (const auto& [name, text] : kFamilies2)
    for (Where w : {Where::Box, Where::NonConvex}) out.push_back({2, name, w});
  for (const auto& [name, text] : kFamilies3)
    for (Where w : {Where::Box, Where::NonConvex}) out.push_back({3, name, w});
  return out;
}

INSTANTIATE_TEST_SUITE_P(AllFamilies, ShapeFrontFamily, ::testing::ValuesIn(all_family_cases()),
                         [](const auto& info) {
                           return std::to_string(info.param.dimension) + "D_" + info.param.family + "_" +
                                  (info.param.where == Where::Box ? "box" : "nonconvex");
                         });

TEST(ShapeFront, CapsulesInTheCubeStl) {
  const PackSetup<3> setup = make_setup<3>(Where::CubeStl);
  const PackRun<3> run = pack_run<3>("  - shape: spherocylinder\n    aspect_ratio: 0.4\n"
                                 "    size: {distribution: uniform, min: 0.1, max: 0.15}\n",
                                 setup, 40, 3);
  check_packing<3>(run, setup, 40);
}

TEST(ShapeFront, CapsulesSitAgainstTheFacetsOfARealMesh) {
  // The femur's 7,798 facets are smaller than the capsules. Each facet is a wall bounded to its
  // triangle: the front offers the facets a mobile can reach and drops positions tangent to a
  // facet's plane beyond it. Measured when this test was written: 812 capsules, 44 touching the
  // surface (5.4 %); with 4 planes kept and near-coplanar ones dropped, 11 of 805 (1.4 %).
  const fp::Scene scene = scene_from_yaml("dimension: 3\nseed: 1\ncontainer: {type: mesh, file: " +
                                          std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/meshes/femur.off}\n"
                                          "particles:\n  - shape: spherocylinder\n    aspect_ratio: 0.5\n"
                                          "    size: {distribution: uniform, min: 0.015, max: 0.025}\n");
  const fp::ShapePackResult<3> res = fp::pack_shape_scene<3>(scene);
  const fp::ValidationReport rep = fp::validate_shapes<3>(res.packing, *scene.container<3>(), res.contact_tolerance,
                                                          fp::requested_templates(scene));
  EXPECT_TRUE(rep.ok) << rep.summary();
  EXPECT_GT(res.packing.particles.size(), 700u);
  EXPECT_GE(static_cast<double>(rep.wall_contacts), 0.04 * static_cast<double>(res.packing.particles.size()))
      << rep.wall_contacts << " capsules touch the surface";
}

TEST(ShapeFront, MixedSpheresCapsulesClusters3D) {
  const PackSetup<3> setup = make_setup<3>(Where::NonConvex);
  const PackRun<3> run = pack_run<3>(kFamilies3.at("sphere") + kFamilies3.at("spherocylinder") + kFamilies3.at("cluster"), setup, 50, 5);
  check_packing<3>(run, setup, 50);
  std::set<int> ids;
  for (const auto& p : run.res.packing.particles) ids.insert(p.template_id);
  EXPECT_EQ(ids.size(), 3u);
}

// ---- the levers of the one front -------------------------------------------------------------

// The front is one manager for every shape: each lever of the sphere front gives a packing of
// shapes that passes every independent check, differs from the default one (the lever reached
// the packer) and is reproducible (front: random draws s0 from the seed's stream).
template <int D>
void expect_every_lever_valid(const std::string& family) {
  SCOPED_TRACE(std::to_string(D) + "D " + family);
  const std::string& particles = (D == 2 ? kFamilies2 : kFamilies3).at(family);
  const PackSetup<D> setup = make_setup<D>(Where::NonConvex);
  const std::uint64_t n = 30;
  const PackRun<D> base = pack_run<D>(particles, setup, n, 9);
  check_packing<D>(base, setup, n);
  const std::vector<std::pair<const char*, std::function<void(fp::PackerOptions&)>>> levers = {
      {"front: random", [](fp::PackerOptions& o) { o.front_pick = fp::FrontPick::Random; }},
      {"front: fifo", [](fp::PackerOptions& o) { o.front_pick = fp::FrontPick::Fifo; }},
      {"candidate: first", [](fp::PackerOptions& o) { o.candidate = fp::CandidateChoice::First; o.pair_order = fp::PairOrder::Index; }},
      {"probe_smallest: true, radius_pool: 6", [](fp::PackerOptions& o) { o.probe_smallest = true; o.radius_pool = 6; }},
      {"radius_pool: 1", [](fp::PackerOptions& o) { o.radius_pool = 1; }},
  };
  for (const auto& [name, tweak] : levers) {
    SCOPED_TRACE(name);
    const PackRun<D> run = pack_run<D>(particles, setup, n, 9, tweak);
    check_packing<D>(run, setup, n);
    EXPECT_FALSE(bitwise_same<D>(run.res.packing, base.res.packing));
    EXPECT_TRUE(bitwise_same<D>(run.res.packing, pack_run<D>(particles, setup, n, 9, tweak).res.packing));
  }
}

TEST(ShapeFrontLevers, EveryLeverGivesAValidPacking2D) {
  expect_every_lever_valid<2>("spherocylinder");
  expect_every_lever_valid<2>("polygon");
}
TEST(ShapeFrontLevers, EveryLeverGivesAValidPacking3D) {
  expect_every_lever_valid<3>("spherocylinder");
  expect_every_lever_valid<3>("cluster");
}

// A container one particle thick: random directions almost never find the slab's plane, so the
// initial cluster needs the search for the direction with the most room (shared with the sphere
// front). Spheres of one size as a shape (they go through the shape model) and capsules lying in
// the slab's plane fill a slab 1.001 diameters thick with a monolayer.
TEST(ShapeFrontThin, SlabOneParticleThick) {
  const double r = 0.25;
  for (const bool capsules : {false, true}) {
    SCOPED_TRACE(capsules ? "capsules" : "spheres");
    PackSetup<3> setup;
    // Capsules of aspect ratio 0.5 lying flat (fixed orientation: axis along x) are 2 x 0.5 r thick.
    const double thickness = (capsules ? 1.0 : 2.0) * r * 1.001;
    const Vec3 lo(0, 0, 0), hi(4, 4, thickness);
    setup.container = std::make_shared<fp::BoxContainer<3>>(lo, hi);
    setup.sd = box_distance<3>(lo, hi);
    setup.name = "slab one particle thick";
    const std::string particles =
        capsules ? "  - shape: spherocylinder\n    aspect_ratio: 0.5\n    size: {distribution: constant, value: 0.25}\n"
                   "    orientation: {fixed: [1, 0, 0, 0]}\n"
                 : "  - shape: sphere\n    size: {distribution: constant, value: 0.25}\n";
    const std::uint64_t n = 40;
    const PackRun<3> run = pack_run<3>(particles, setup, n, 4);
    check_packing<3>(run, setup, n);
  }
}

// ---- reproducibility -------------------------------------------------------------------------

template <int D>
void expect_reproducible(const std::string& family, Where where) {
  SCOPED_TRACE(std::to_string(D) + "D " + family);
  const std::string& particles = (D == 2 ? kFamilies2 : kFamilies3).at(family);
  const PackSetup<D> setup = make_setup<D>(where);
  const bool slow = family == "ellipsoid" || family == "cylinder" || family == "polyhedron";
  const std::uint64_t n = slow ? 6 : 20;
  const PackRun<D> a = pack_run<D>(particles, setup, n, 11);
  const PackRun<D> b = pack_run<D>(particles, setup, n, 11);
  const PackRun<D> c = pack_run<D>(particles, setup, n, 12);
  ASSERT_EQ(a.res.packing.size(), n);
  EXPECT_TRUE(bitwise_same<D>(a.res.packing, b.res.packing));
  EXPECT_EQ(a.res.counters.solves, b.res.counters.solves);
  EXPECT_EQ(a.res.solver.fcl_queries, b.res.solver.fcl_queries);
  EXPECT_FALSE(bitwise_same<D>(a.res.packing, c.res.packing));
}

TEST(ShapeFrontReproducible, SameSeedSamePackingEveryFamily) {
  for (const auto& [name, text] : kFamilies2) expect_reproducible<2>(name, Where::NonConvex);
  for (const auto& [name, text] : kFamilies3) expect_reproducible<3>(name, Where::Box);
}

// ---- far and scaled scenes --------------------------------------------------------------------

/// The particles' YAML of a family with every size (and length) scaled by `s` (a power of two).
std::string scaled_particles(const std::string& text, double s) {
  char size[160];
  std::snprintf(size, sizeof size, "    size: {distribution: uniform, min: %.17g, max: %.17g}\n", 0.25 * s, 0.4 * s);
  std::string out = text;
  for (std::size_t at = out.find(kSize); at != std::string::npos; at = out.find(kSize, at + 1)) out.replace(at, kSize.size(), size);
  return out;
}

/// The same scene in a box shifted by 1e9 (its frame origin: the box's corner) and scaled by
/// 2^60 and 2^-60 packs the same particles: positions, orientations and sizes bit for bit the
/// reference's (shifted: in the local frame; scaled: times 2^k), and the same count; every
/// scaled packing, brought back by 2^-k (exactly), passes the independent checks in the plain box.
/// `fcl_scaled`: the family's contacts go through FCL distance queries (3D polyhedra beyond the
/// separating axes, cylinders); FCL works in a power-of-two unit about the scene's size (libccd's
/// tolerances are absolute: before that, cylinders at 2^-60 overlapped by 0.4 of their radius and
/// passed validation), not the plain scene's unit, so such packings are valid with the same count
/// but not bit for bit the plain one.
template <int D>
void expect_far_and_scaled_same(const std::string& family, bool fcl_scaled) {
  const std::string& text = (D == 2 ? kFamilies2 : kFamilies3).at(family);
  const std::uint64_t n = std::min<std::uint64_t>(count_for(D, family), 20);
  const Vec<D> hi = Vec<D>::Constant(D == 2 ? 6.0 : 2.5);
  PackSetup<D> plain;
  plain.container = std::make_shared<fp::BoxContainer<D>>(Vec<D>::Zero(), hi);
  plain.sd = box_distance<D>(Vec<D>::Zero(), hi);
  plain.name = "plain box";
  const PackRun<D> ref = pack_run<D>(text, plain, n, 11);
  ASSERT_EQ(ref.res.packing.size(), n) << family;

  const Vec<D> lo_far = Vec<D>::Constant(1e9), hi_far = lo_far + hi;
  fp::Aabb<D> bounds;
  bounds.extend(lo_far), bounds.extend(hi_far);
  PackSetup<D> far;
  const Vec<D> origin = fp::frame_origin<D>(bounds);
  far.container = std::make_shared<fp::BoxContainer<D>>(lo_far, hi_far, origin);
  const PackRun<D> shifted = pack_run<D>(text, far, n, 11);
  EXPECT_EQ(shifted.res.packing.origin, origin) << family;
  EXPECT_TRUE(bitwise_same<D>(ref.res.packing, shifted.res.packing)) << D << "D " << family << " shifted by 1e9";

  for (const int k : {60, -60}) {
    SCOPED_TRACE(std::to_string(D) + "D " + family + " scaled by 2^" + std::to_string(k));
    const double s = std::ldexp(1.0, k);
    PackSetup<D> big;
    big.container = std::make_shared<fp::BoxContainer<D>>(Vec<D>::Zero(), Vec<D>(hi * s));
    const PackRun<D> scaled = pack_run<D>(scaled_particles(text, s), big, n, 11);
    PackRun<D> back = scaled;  // scaled back by 2^-k: exact
    for (auto& p : back.res.packing.particles) p.pose.position /= s, p.size /= s, p.shape = p.shape->scaled(1 / s);
    back.res.solid_measure /= std::pow(s, D);
    back.templates = ref.templates;
    check_packing<D>(back, plain, n);
    if (!fcl_scaled) EXPECT_TRUE(bitwise_same<D>(ref.res.packing, back.res.packing)) << D << "D " << family << " scaled by 2^" << k;
  }
}

TEST(ShapeFrontExtremes, FarAndScaledScenesPackTheSameParticles) {
  for (const auto& [name, text] : kFamilies2) expect_far_and_scaled_same<2>(name, false);
  for (const auto& [name, text] : kFamilies3) expect_far_and_scaled_same<3>(name, name == "polyhedron" || name == "cylinder");
}

// ---- distributions ---------------------------------------------------------------------------

double angle_of(const fp::Mat<2>& R) {
  double t = std::atan2(R(1, 0), R(0, 0));
  return t < 0 ? t + 2 * fp::kPi : t;
}

TEST(ShapeFrontDistributions, SizesAndAnglesKs2D) {
  // 150 stadiums, sizes U[0.3, 0.5] on the circumscribed radius, random orientation.
  const PackSetup<2> setup = [] {
    PackSetup<2> s;
    s.container = std::make_shared<fp::BoxContainer<2>>(Vec2(0, 0), Vec2(10, 10));
    s.sd = box_distance<2>(Vec2(0, 0), Vec2(10, 10));
    s.name = "box [0,10]^2";
    return s;
  }();
  const PackRun<2> run = pack_run<2>("  - shape: spherocylinder\n    aspect_ratio: 0.5\n"
                                 "    size: {distribution: uniform, min: 0.3, max: 0.5}\n",
                                 setup, 150, 21);
  check_packing<2>(run, setup, 150);
  std::vector<double> sizes, angles;
  for (const auto& p : run.res.packing.particles) {
    sizes.push_back(p.size);
    angles.push_back(angle_of(p.pose.rotation));
  }
  const auto& dist = *run.templates[0].size;
  const double ps = fp::ks_pvalue(fp::ks_statistic(sizes, [&](double x) { return dist.cdf(x); }), sizes.size());
  const double pa = fp::ks_pvalue(fp::ks_statistic(angles, [](double x) { return x / (2 * fp::kPi); }), angles.size());
  std::printf("  K-S p-values: sizes %.4g, angles %.4g\n", ps, pa);
  EXPECT_GT(ps, 0.001);
  EXPECT_GT(pa, 0.001);
}

TEST(ShapeFrontDistributions, SizesAndAxesKs3D) {
  // 150 capsules in a box; Haar-random rotations: the body x axis' z component is U[-1, 1].
  const PackSetup<3> setup = [] {
    PackSetup<3> s;
    s.container = std::make_shared<fp::BoxContainer<3>>(Vec3(0, 0, 0), Vec3(3, 3, 3));
    s.sd = box_distance<3>(Vec3(0, 0, 0), Vec3(3, 3, 3));
    s.name = "box [0,3]^3";
    return s;
  }();
  const PackRun<3> run = pack_run<3>(kFamilies3.at("spherocylinder"), setup, 150, 8);
  check_packing<3>(run, setup, 150);
  std::vector<double> sizes, axis_z;
  for (const auto& p : run.res.packing.particles) {
    sizes.push_back(p.size);
    axis_z.push_back(p.pose.rotation(2, 0));
  }
  const auto& dist = *run.templates[0].size;
  const double ps = fp::ks_pvalue(fp::ks_statistic(sizes, [&](double x) { return dist.cdf(x); }), sizes.size());
  const double pz = fp::ks_pvalue(fp::ks_statistic(axis_z, [](double x) { return (x + 1) / 2; }), axis_z.size());
  std::printf("  K-S p-values: sizes %.4g, axis z %.4g\n", ps, pz);
  EXPECT_GT(ps, 0.001);
  EXPECT_GT(pz, 0.001);
}

TEST(ShapeFrontDistributions, FixedOrientationIsExact) {
  {
    const PackSetup<2> setup = make_setup<2>(Where::Box);
    const PackRun<2> run = pack_run<2>("  - shape: polygon\n    sides: 3\n" + kSize + "    orientation: {fixed: 30}\n", setup, 40, 2);
    check_packing<2>(run, setup, 40);
    const fp::Mat<2> R = fp::rotation_2d(30 * fp::kPi / 180.0);
    for (const auto& p : run.res.packing.particles) EXPECT_EQ(p.pose.rotation, R);
    // Independent of the library's formula: 30 degrees.
    EXPECT_NEAR(R(0, 0), std::sqrt(3.0) / 2, 1e-15);
    EXPECT_NEAR(R(1, 0), 0.5, 1e-15);
  }
  {
    const PackSetup<3> setup = make_setup<3>(Where::Box);
    // 90 degrees about z: the capsules' axes all lie along y.
    const double h = std::sqrt(0.5);
    const PackRun<3> run = pack_run<3>("  - shape: spherocylinder\n    aspect_ratio: 0.5\n" + kSize +
                                       "    orientation: {fixed: [" + std::to_string(h) + ", 0, 0, " + std::to_string(h) + "]}\n",
                                   setup, 30, 2);
    check_packing<3>(run, setup, 30);
    const fp::Mat<3> R = run.res.packing.particles[0].pose.rotation;
    EXPECT_NEAR((R * Vec3::UnitX() - Vec3::UnitY()).norm(), 0.0, 1e-6);
    for (const auto& p : run.res.packing.particles) EXPECT_EQ(p.pose.rotation, R);
  }
}

// Laws about an axis are kept by the packing, with the roll (which turns a particle about its own
// axis only) and orientation trials (drawn from the law) on, and pocket trials asked for (which
// such a law refuses): the library's orientation tests pass, the sample's nematic order about the
// axis is the law's within its noise, and the same particles fail the test against the isotropic
// law (the test sees what differs).
TEST(ShapeFrontOrientation, LawsAboutAnAxisAreKept) {
  auto box = [](double side) {
    PackSetup<3> s;
    s.container = std::make_shared<fp::BoxContainer<3>>(Vec3::Zero(), Vec3::Constant(side));
    s.sd = box_distance<3>(Vec3::Zero(), Vec3::Constant(side));
    s.name = "box";
    return s;
  };
  const PackSetup<3> setup = box(3.5);
  for (const char* law : {"{law: watson, axis: [0, 0, 1], kappa: 6}", "{law: fisher, axis: [1, 1, 0], order: 0.5}"}) {
    SCOPED_TRACE(law);
    const PackRun<3> run = pack_run<3>(kFamilies3.at("spherocylinder") + "    orientation: " + law + "\n", setup, 200, 5,
                                       [](fp::PackerOptions& o) {
                                         o.orientation_trials = 2;
                                         o.pocket_trials = 32;
                                       });
    check_packing<3>(run, setup, 200);
    EXPECT_GT(run.res.counters.roll_kept, 0u);
    EXPECT_GT(run.res.counters.orientation_draws, 0u);
    EXPECT_EQ(run.res.counters.pocket_draws, 0u);  // they would bias a law about an axis
    const fp::OrientationSpec& spec = run.templates[0].orientation;
    std::vector<fp::Mat<3>> rotations;
    for (const auto& p : run.res.packing.particles) rotations.push_back(p.pose.rotation);
    const fp::OrientationFit fit = fp::orientation_fit<3>(rotations, spec.law<3>());
    EXPECT_TRUE(fit.passes(fp::kOrientationAlpha / 3)) << fit.describe();
    EXPECT_NEAR(fit.order, fit.law_order, 4 * fit.order_noise) << fit.describe();
    EXPECT_FALSE(fp::orientation_fit<3>(rotations, fp::OrientationLaw<3>::isotropic()).passes(1e-4));
  }
  // 2D: a law about an axis allows no turn (it would change the angle): no roll, no pocket
  // trials; the law kept.
  PackSetup<2> flat;
  flat.container = std::make_shared<fp::BoxContainer<2>>(Vec2::Zero(), Vec2(10, 10));
  flat.sd = box_distance<2>(Vec2::Zero(), Vec2(10, 10));
  flat.name = "box [0,10]^2";
  const PackRun<2> run = pack_run<2>(kFamilies2.at("spherocylinder") + "    orientation: {law: watson, axis: [1, 0], kappa: 3}\n", flat, 150, 5,
                                     [](fp::PackerOptions& o) { o.pocket_trials = 32; });
  check_packing<2>(run, flat, 150);
  EXPECT_EQ(run.res.counters.roll_turns, 0u);
  EXPECT_EQ(run.res.counters.pocket_draws, 0u);
  std::vector<fp::Mat<2>> angles;
  for (const auto& p : run.res.packing.particles) angles.push_back(p.pose.rotation);
  const fp::OrientationFit fit = fp::orientation_fit<2>(angles, run.templates[0].orientation.law<2>());
  EXPECT_TRUE(fit.passes(fp::kOrientationAlpha)) << fit.describe();
}

// The roll, the orientation trials and the pocket trials are what the front's density for shapes
// rests on (experiments/shape-density): each must give a valid packing, and a denser one than
// without it, for the same drafts (cubes and capsules, a box of ~250 particles), in either frame.
TEST(ShapeFrontOrientation, RollAndTrialsPackDenserAndValid) {
  PackSetup<3> setup;
  setup.container = std::make_shared<fp::BoxContainer<3>>(Vec3::Zero(), Vec3::Constant(3.5));
  setup.sd = box_distance<3>(Vec3::Zero(), Vec3::Constant(3.5));
  setup.name = "box [0,3.5]^3";
  for (const char* family : {"polyhedron", "spherocylinder"}) {
    SCOPED_TRACE(family);
    const std::string particles = family == std::string("polyhedron") ? "  - shape: polyhedron\n    preset: cube\n" + kSize
                                                                      : kFamilies3.at(family);
    auto fill = [&](fp::OrientationFrame frame, int roll, int trials, int pocket) {
      // Until the front runs empty: the solid the container takes.
      return pack_run<3>(particles, setup, 100000, 3, [&](fp::PackerOptions& o) {
        o.orientation_frame = frame;
        o.roll_steps = roll;
        o.orientation_trials = trials;
        o.pocket_trials = pocket;
      });
    };
    const auto lab = fp::OrientationFrame::Lab, radial = fp::OrientationFrame::Radial;
    const PackRun<3> plain = fill(lab, 0, 1, 0), rolled = fill(lab, 60, 1, 0), both = fill(lab, 60, 3, 0),
                     pocket = fill(lab, 0, 1, 32), pocket_rolled = fill(lab, 60, 1, 32);
    const PackRun<3> radial_plain = fill(radial, 0, 1, 0), radial_rolled = fill(radial, 60, 1, 0),
                     radial_both = fill(radial, 60, 3, 32);
    for (const PackRun<3>* run : {&plain, &rolled, &both, &pocket, &pocket_rolled, &radial_plain, &radial_rolled, &radial_both}) {
      EXPECT_EQ(run->res.stop, fp::StopReason::FrontExhausted);
      PackRun<3> whole = *run;
      // check_packing asks for a count stop: the independent checks of the whole packing.
      whole.res.stop = fp::StopReason::ParticleCount;
      check_packing<3>(whole, setup, run->res.packing.size());
    }
    EXPECT_EQ(plain.res.counters.roll_turns, 0u);
    EXPECT_GT(rolled.res.counters.roll_kept, rolled.res.packing.size());  // most placements roll, some several times
    EXPECT_GT(both.res.counters.orientation_draws, 0u);
    EXPECT_EQ(rolled.res.counters.pocket_draws, 0u);
    EXPECT_GT(pocket.res.counters.pocket_kept, 0u);
    EXPECT_EQ(pocket.res.counters.roll_turns, 0u);
    EXPECT_EQ(rolled.res.counters.reframe_misses, 0u);  // the lab frame does not reframe
    EXPECT_GT(radial_rolled.res.counters.roll_kept, 0u);
    EXPECT_GT(radial_both.res.counters.pocket_kept, 0u);
    EXPECT_GT(radial_both.res.counters.orientation_draws, 0u);
    std::printf("  %s: solid %.4f plain, %.4f rolled, %.4f rolled with 3 trials, %.4f pocket trials, %.4f rolled with pocket "
                "trials; radial frame: %.4f plain, %.4f rolled, %.4f rolled with 3 trials and pocket trials\n",
                family, plain.res.solid_measure, rolled.res.solid_measure, both.res.solid_measure, pocket.res.solid_measure,
                pocket_rolled.res.solid_measure, radial_plain.res.solid_measure, radial_rolled.res.solid_measure,
                radial_both.res.solid_measure);
    EXPECT_GT(rolled.res.solid_measure, 1.03 * plain.res.solid_measure);
    EXPECT_GT(both.res.solid_measure, 1.03 * plain.res.solid_measure);
    EXPECT_GT(pocket.res.solid_measure, 1.02 * plain.res.solid_measure);
    EXPECT_GT(pocket_rolled.res.solid_measure, 1.01 * rolled.res.solid_measure);
    EXPECT_GT(radial_rolled.res.solid_measure, 1.01 * radial_plain.res.solid_measure);
    EXPECT_GT(radial_both.res.solid_measure, 1.01 * radial_rolled.res.solid_measure);
  }
  // Grown in blocks (threads), a front neither rolls nor tries pockets: a block's growth is a
  // plane's sweep, and choosing by it would lay elongated particles across one direction.
  const PackRun<3> blocks = pack_run<3>(kFamilies3.at("spherocylinder"), setup, 100000, 3, [](fp::PackerOptions& o) {
    o.block_edge = 3.5;
  });
  EXPECT_GT(blocks.res.counters.blocks, 0u);
  EXPECT_EQ(blocks.res.counters.roll_turns, 0u);
  EXPECT_EQ(blocks.res.counters.pocket_draws, 0u);
  EXPECT_GT(blocks.res.packing.size(), 100u);
}

/// The texture of the orientations about the seed point c, from the poses alone: over the
/// particles at least `margin` from c and from the box [0, side]^3's walls, the mean P2 of the
/// body x axis against the radius (0 when isotropic) with its standard error, and the mean of
/// sum_i (e_i . r)^4 over the body axes (3/5 when isotropic; a cube's faces along the radius raise
/// it, its edges lower it) with its standard error.
struct RadialTexture {
  double p2 = 0, p2_error = 0, c4 = 0, c4_error = 0;
  int n = 0;
};
RadialTexture radial_texture(const fp::ShapePacking<3>& packing, const Vec3& c, double side, double margin) {
  std::vector<double> p2, c4;
  for (const auto& p : packing.particles) {
    const Vec3 r = p.pose.position - c;
    if (r.norm() < margin || (p.pose.position.array() < margin).any() || (p.pose.position.array() > side - margin).any()) continue;
    const Vec3 u = r.normalized();
    const Vec3 dots = p.pose.rotation.transpose() * u;  // the radius in the body's axes
    p2.push_back(1.5 * dots.x() * dots.x() - 0.5);
    c4.push_back(dots.array().pow(4).sum());
  }
  auto mean_error = [](const std::vector<double>& v) {
    double m = 0, q = 0;
    for (double x : v) m += x;
    m /= static_cast<double>(v.size());
    for (double x : v) q += (x - m) * (x - m);
    return std::pair{m, std::sqrt(q / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()))};
  };
  RadialTexture t;
  t.n = static_cast<int>(p2.size());
  std::tie(t.p2, t.p2_error) = mean_error(p2);
  std::tie(t.c4, t.c4_error) = mean_error(c4);
  return t;
}

// The lab frame's choices lay elongated particles across the radius from the seed point (the
// marginal law still passes); the radial frame (the default) leaves no texture about it: the
// radius seen from each body is the drawn orientation's, uniform. Capsules and cubes in a box of
// ~1,500, the texture measured here from the poses, the orientation tests passed in both frames.
TEST(ShapeFrontOrientation, RadialFrameLeavesNoTextureAboutTheSeed) {
  const double side = 5.5;
  PackSetup<3> setup;
  setup.container = std::make_shared<fp::BoxContainer<3>>(Vec3::Zero(), Vec3::Constant(side));
  setup.sd = box_distance<3>(Vec3::Zero(), Vec3::Constant(side));
  setup.seed_point = std::vector<double>{side / 2, side / 2, side / 2};
  setup.name = "box [0,5.5]^3";
  const Vec3 c = Vec3::Constant(side / 2);
  for (const char* family : {"spherocylinder", "polyhedron"}) {
    SCOPED_TRACE(family);
    const std::string particles = family == std::string("polyhedron") ? "  - shape: polyhedron\n    preset: cube\n" + kSize
                                                                      : kFamilies3.at(family);
    auto fill = [&](fp::OrientationFrame frame) {
      return pack_run<3>(particles, setup, 100000, 7, [&](fp::PackerOptions& o) { o.orientation_frame = frame; });
    };
    const PackRun<3> lab = fill(fp::OrientationFrame::Lab), radial = fill(fp::OrientationFrame::Radial);
    for (const PackRun<3>* run : {&lab, &radial}) {
      std::vector<fp::Mat<3>> rotations;
      for (const auto& p : run->res.packing.particles) rotations.push_back(p.pose.rotation);
      const fp::OrientationFit fit = fp::orientation_fit<3>(rotations, fp::OrientationLaw<3>::isotropic());
      EXPECT_TRUE(fit.passes(fp::kOrientationAlpha)) << fit.describe();
    }
    const RadialTexture tl = radial_texture(lab.res.packing, c, side, 0.8), tr = radial_texture(radial.res.packing, c, side, 0.8);
    std::printf("  %s: lab frame: %zu particles, P2(a.r) %+.4f +- %.4f, sum (e.r)^4 %.4f +- %.4f over %d; radial frame: %zu "
                "particles, P2(a.r) %+.4f +- %.4f, sum (e.r)^4 %.4f +- %.4f over %d\n",
                family, lab.res.packing.size(), tl.p2, tl.p2_error, tl.c4, tl.c4_error, tl.n, radial.res.packing.size(), tr.p2,
                tr.p2_error, tr.c4, tr.c4_error, tr.n);
    ASSERT_GT(tr.n, 300);
    EXPECT_LT(std::abs(tr.p2), 3.5 * tr.p2_error);
    EXPECT_LT(std::abs(tr.c4 - 0.6), 3.5 * tr.c4_error);
    EXPECT_GT(radial.res.counters.reframe_misses, 0u);  // some: the scan's orientation is kept there
    EXPECT_LT(radial.res.counters.reframe_misses, radial.res.packing.size() / 10);
    // The lab frame's texture, which the test would see: capsules across the radius, cubes' edges
    // along it.
    if (family == std::string("spherocylinder")) EXPECT_LT(tl.p2, -6 * tl.p2_error);
    else EXPECT_LT(tl.c4 - 0.6, -4 * tl.c4_error);
  }
}

TEST(ShapeFrontDistributions, SizeOnANamedDimension) {
  // Size drawn on the spherocylinder's radius: the shape's radius is the size, its
  // circumscribed radius size / aspect_ratio.
  const PackSetup<2> setup = make_setup<2>(Where::Box);
  const PackRun<2> run = pack_run<2>("  - shape: spherocylinder\n    aspect_ratio: 0.5\n"
                                 "    size: {distribution: uniform, min: 0.12, max: 0.2}\n    size_on: radius\n",
                                 setup, 40, 4);
  check_packing<2>(run, setup, 40);
  for (const auto& p : run.res.packing.particles) {
    const auto* c = dynamic_cast<const fp::SpherocylinderShape<2>*>(p.shape.get());
    ASSERT_NE(c, nullptr);
    EXPECT_NEAR(c->radius(), p.size, 1e-12);
    EXPECT_NEAR(p.bounding_radius(), 2 * p.size, 1e-12);
  }
}

// ---- the checks themselves catch what they should -----------------------------------------------

TEST(ShapeChecks, DetectOverlapsAndProtrusions) {
  const fp::Scene scene = scene_from_yaml("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\nparticles:\n" +
                                          kFamilies3.at("ellipsoid") + kFamilies3.at("polyhedron") + kFamilies3.at("spherocylinder") +
                                          kFamilies3.at("cylinder"));
  const auto T = fp::resolve_templates<3>(scene);
  const std::vector<Vec3> dirs = directions<3>(600);
  for (std::size_t a = 0; a < T.size(); ++a)
    for (std::size_t b = 0; b < T.size(); ++b) {
      SCOPED_TRACE(T[a].family + " / " + T[b].family);
      fp::Particle<3> A, B;
      A.shape = T[a].prototype.shape->scaled(0.3);
      B.shape = T[b].prototype.shape->scaled(0.3);
      B.pose.rotation = fp::rotation_of<3>(Eigen::Vector4d(0.9, 0.1, 0.3, 0.2));
      // B's extreme point along -x on A's extreme point along +x (touching, common normal x),
      // then pushed 1e-3 into A, then 1e-3 away.
      const Vec3 a_ext = A.support(Vec3::UnitX());
      const Vec3 b_off = B.support(-Vec3::UnitX()) - B.pose.position;
      B.pose.position = a_ext - b_off - 1e-3 * Vec3::UnitX();
      const PairCheck over = check_pair(A, B, dirs, 1e-7);
      EXPECT_LT(over.gap_lower, -1e-4) << over.method;
      if (T[a].family == "ellipsoid") {
        EXPECT_GT(over.intrusion, 0.0);
      }
      B.pose.position = a_ext - b_off + 1e-3 * Vec3::UnitX();
      const PairCheck apart = check_pair(A, B, dirs, 1e-7);
      EXPECT_EQ(apart.intrusion, 0.0);
      EXPECT_GT(apart.gap_lower, 0.0) << apart.method;
      EXPECT_LE(apart.gap_lower, 1e-3 * (1 + 1e-6)) << apart.method;
      if (apart.method != std::string("separating axes")) {
        EXPECT_GE(apart.gap_lower, 1e-3 * (1 - 1e-6)) << apart.method;
      }
    }
  // A particle across the reflex edge of the L prism: its hull is inside, the edge is in it.
  const PackSetup<3> setup = make_setup<3>(Where::NonConvex);
  fp::ShapePacking<3> P;
  fp::Particle<3> p;
  p.shape = T[0].prototype.shape->scaled(0.3);
  p.pose.position = Vec3(1.4, 1.4, 1.0);
  P.particles.push_back(p);
  const ShapeContainmentReport<3> rep = shape_containment(P, setup.sd, setup.wall_normals, setup.boundary_points, kTol);
  EXPECT_GT(rep.boundary_points_inside, 0u);
  EXPECT_GT(rep.max_outside_rel, 0.0);
}

}  // namespace
}  // namespace fptest

