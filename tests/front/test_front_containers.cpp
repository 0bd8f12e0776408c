// The advancing front in every container kind, checked independently of the library's metrics:
// no overlap, every particle inside (closed-form distances; brute force for meshes), a dense
// contact network in the bulk, and particles touching the walls (walls are bodies by default).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/geometry/mesh_container.hpp"
#include "front_checks.hpp"

namespace fptest {
namespace {

struct Expectations {
  double min_bulk_coordination;  ///< mean particle contacts of the bulk must exceed this
  double bulk_depth;             ///< particles deeper than this from the boundary are the bulk
  double min_volume_fraction;    ///< sanity: the front filled the container
  double min_bulk_share = 0.2;   ///< the bulk is at least this share of the particles
};

template <int D>
void pack_and_check(const std::string& name, const std::string& yaml, const SignedDistance<D>& sd, double measure,
                    const Expectations& e) {
  const fp::Scene scene = scene_from_yaml(yaml);
  const fp::PackResult<D> res = fp::pack<D>(scene);
  const fp::Packing<D>& P = res.packing;
  SCOPED_TRACE(name + ": " + std::to_string(P.size()) + " particles");
  EXPECT_EQ(res.stop, fp::StopReason::FrontExhausted);
  EXPECT_GE(P.size(), 300u);
  EXPECT_LE(P.size(), 6000u);  // keeps the suite fast

  const Validity v = expect_valid<D>(P, sd, scene.radii->r_min(), scene.radii->r_max(), name);
  // Walls are bodies: some particles sit tangent to the container. (Few in round containers:
  // growth from the centre meets a concentric wall everywhere at once, leaving a thin annulus.)
  EXPECT_GE(v.containment.touching_walls, 5u) << name;

  // Every particle is placed tangent to D bodies (s0 and D-1 particles or walls), so apart from
  // the initial cluster(s) a particle that touches no wall (brute-force distance) touches at
  // least D particles. (A facet's plane touched beyond the facet's edges is no contact: placing
  // particles there was a bug.)
  const std::vector<int> z_particles = particle_contacts<D>(P, 1e-8);
  std::size_t under = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const bool wall = sd(P.centers[i], P.origin) + P.radii[i] >= -1e-8 * P.radii[i];
    if (!wall && z_particles[i] < D) ++under;
  }
  EXPECT_LE(under, static_cast<std::size_t>(D) * (1 + res.counters.voids_seeded)) << name << ": particles with < D contacts";

  std::size_t bulk = 0;
  const double z = bulk_mean_coordination<D>(P, sd, e.bulk_depth, bulk);
  EXPECT_GE(static_cast<double>(bulk), e.min_bulk_share * static_cast<double>(P.size())) << name;
  EXPECT_GT(z, e.min_bulk_coordination) << name << ": bulk of " << bulk << " particles";

  // The container measure the library reports agrees with the closed form (or brute force).
  const fp::Container<D>* c = scene.template container<D>();
  EXPECT_NEAR(c->measure(), measure, 1e-9 * measure) << name;
  // The container's own distance agrees that every particle is inside (what the packer used).
  double worst = -1;
  for (std::size_t i = 0; i < P.size(); ++i)
    worst = std::max(worst, (c->signed_distance(P.centers[i]) + P.radii[i]) / P.radii[i]);
  EXPECT_LE(worst, kInsideTol) << name;
  EXPECT_GT(volume_fraction<D>(P, measure), e.min_volume_fraction) << name;
}

const Expectations k3d{4.0, 0.04, 0.45};
const Expectations k2d{3.0, 0.04, 0.65};

TEST(FrontContainers, Box3D) {
  pack_and_check<3>("box", R"(
dimension: 3
seed: 3
container: {type: box, min: [-0.1, 0, 0.2], max: [0.3, 0.4, 0.6]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)", box_distance<3>(Vec3(-0.1, 0, 0.2), Vec3(0.3, 0.4, 0.6)), 0.4 * 0.4 * 0.4, k3d);
}

TEST(FrontContainers, Sphere3D) {
  pack_and_check<3>("sphere", R"(
dimension: 3
seed: 4
container: {type: sphere, center: [1, -2, 0.5], radius: 0.25}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)", ball_distance<3>(Vec3(1, -2, 0.5), 0.25), 4.0 / 3.0 * fp::kPi * 0.25 * 0.25 * 0.25, k3d);
}

TEST(FrontContainers, TiltedCylinder3D) {
  // A tilted axis, so no wall is axis-aligned.
  const double R = 0.15, h = 0.5;
  pack_and_check<3>("cylinder", R"(
dimension: 3
seed: 5
container: {type: cylinder, base: [0.1, 0.2, 0.3], axis: [1, 2, 2], radius: 0.15, height: 0.5}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)", cylinder_distance(Vec3(0.1, 0.2, 0.3), Vec3(1, 2, 2), R, h), fp::kPi * R * R * h, k3d);
}

TEST(FrontContainers, NonConvexMeshLPrism) {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> t;
  read_off(std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/scenes-e2e/l_prism.off", v, t);
  EXPECT_NEAR(mesh_volume(v, t), 0.12 * 0.3, 1e-15);
  pack_and_check<3>("L prism mesh", R"(
dimension: 3
seed: 6
container: {type: mesh, file: l_prism.off}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)", mesh_distance(v, t), 0.12 * 0.3, k3d);
}

TEST(FrontContainers, RealMeshFemur) {
  // A real scanned surface (7,798 facets, genus 2): thin parts and curved walls.
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> t;
  read_off(std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/meshes/femur.off", v, t);
  const SignedDistance<3> sd = mesh_distance(v, t);
  pack_and_check<3>("femur mesh", R"(
dimension: 3
seed: 7
container: {type: mesh, file: ../meshes/femur.off}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.015}}
)", sd, mesh_volume(v, t), {4.0, 0.03, 0.35, 0.1});  // slender: a smaller bulk
}

TEST(FrontContainers, MeshCubeStl) {
  // The unit cube (ascii STL) scaled to 0.4: the mesh path against the box's closed form.
  pack_and_check<3>("cube mesh", R"(
dimension: 3
seed: 12
container: {type: mesh, file: ../meshes/cube.stl, scale: 0.4}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)", box_distance<3>(Vec3::Zero(), Vec3::Constant(0.4)), 0.064, k3d);
}

TEST(FrontContainers, MeshSignedDistanceAgreesWithBruteForce) {
  // The packer trusts the container's signed distance; check it where the particles are.
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> t;
  read_off(std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/scenes-e2e/l_prism.off", v, t);
  const SignedDistance<3> sd = mesh_distance(v, t);
  const fp::Scene scene = scene_from_yaml(R"(
dimension: 3
container: {type: mesh, file: l_prism.off}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
stop: {particles: 500}
)");
  const auto res = fp::pack<3>(scene);
  for (const Vec3& c : res.packing.centers) EXPECT_NEAR(scene.container3->signed_distance(c), sd(c, res.packing.origin), 1e-12);
}

TEST(FrontContainers, Rectangle2D) {
  pack_and_check<2>("rectangle", R"(
dimension: 2
seed: 8
container: {type: rectangle, min: [2, -1], max: [3.5, 0.2]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)", box_distance<2>(Vec2(2, -1), Vec2(3.5, 0.2)), 1.5 * 1.2, k2d);
}

TEST(FrontContainers, Disk2D) {
  pack_and_check<2>("disk", R"(
dimension: 2
seed: 9
container: {type: disk, center: [-0.5, 0.25], radius: 0.7}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)", ball_distance<2>(Vec2(-0.5, 0.25), 0.7), fp::kPi * 0.49, k2d);
}

TEST(FrontContainers, ConvexPolygonHexagon2D) {
  std::vector<Vec2> hex;
  for (int k = 0; k < 6; ++k) hex.emplace_back(0.8 * std::cos(k * fp::kPi / 3), 0.8 * std::sin(k * fp::kPi / 3));
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "dimension: 2\nseed: 10\ncontainer: {type: polygon, vertices: [";
  for (int k = 0; k < 6; ++k) yaml << (k ? ", " : "") << "[" << hex[k].x() << ", " << hex[k].y() << "]";
  yaml << "]}\nparticles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}\n";
  pack_and_check<2>("hexagon", yaml.str(), polygon_distance(hex), 1.5 * std::sqrt(3.0) * 0.64, k2d);
}

TEST(FrontContainers, NonConvexPolygonL2D) {
  // Clockwise on purpose (the container stores counter-clockwise); reflex corner at (0.8, 0.8).
  const std::vector<Vec2> L = {{0, 0}, {0, 1.6}, {0.8, 1.6}, {0.8, 0.8}, {1.6, 0.8}, {1.6, 0}};
  const std::string yaml = R"(
dimension: 2
seed: 11
container: {type: polygon, vertices: [[0, 0], [0, 1.6], [0.8, 1.6], [0.8, 0.8], [1.6, 0.8], [1.6, 0]]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";
  pack_and_check<2>("L polygon", yaml, polygon_distance(L), 3 * 0.64, k2d);

  // Particles crowd the reflex corner, so the containment check above is exercised there (a
  // disk covering the corner would stick out although its centre is far inside both edges).
  const fp::Scene scene = scene_from_yaml(yaml);
  const auto P = fp::pack<2>(scene).packing;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < P.size(); ++i)
    nearest = std::min(nearest, (P.centers[i] - Vec2(0.8, 0.8)).norm() - P.radii[i]);
  EXPECT_LT(nearest, 0.02);
}

}  // namespace
}  // namespace fptest
