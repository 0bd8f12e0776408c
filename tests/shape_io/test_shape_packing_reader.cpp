// The reader of the json output of shape packings (shapes/io/shape_packing_reader.hpp): every
// built-in family in 2D and 3D written by the json writer and read back gives the same
// particles — positions bit for bit (also 1e9 from the origin: the origin subtracted on the
// text), rotations to rounding, shapes of the same kind, size and geometry (circumscribed radius,
// measure, support points) — and bad input names the file and the key.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/sampling/rng.hpp"
#include "shapes/io/shape_packing_reader.hpp"
#include "shapes/io/shape_packing_writers.hpp"
#include "shapes/shape_registry.hpp"
#include "tests/io/io_test_util.hpp"

namespace fp {
namespace {

using test::slurp;
using test::TempDir;

template <int D>
ShapePtr<D> family(const std::string& name, const ShapeParameters& parameters = {}) {
  ParticleTemplateSpec spec;
  spec.family = name;
  spec.parameters = parameters;
  return ShapeFamilies::builtin().prototype<D>(spec).shape;
}

/// One template per built-in family of the dimension, particles of random sizes, poses and
/// templates, in a frame at `origin`.
template <int D>
ShapePacking<D> every_family(int n, std::uint64_t seed, const Vec<D>& origin) {
  ShapeParameters capsule, ellipsoid, cluster, polytope, cylinder;
  capsule.numbers["aspect_ratio"] = 0.4;
  ellipsoid.lists["axes"] = D == 2 ? std::vector<double>{1, 0.6} : std::vector<double>{1, 0.7, 0.5};
  cluster.point_lists["centers"] = {std::vector<double>(D, 0.0), std::vector<double>(D, 0.6)};
  cluster.lists["radii"] = {0.5, 0.3};
  if constexpr (D == 2) polytope.numbers["sides"] = 6;
  else polytope.numbers["platonic"] = 20;
  cylinder.numbers["aspect_ratio"] = 0.7;
  std::vector<ShapePtr<D>> prototypes = {family<D>("sphere"), family<D>("spherocylinder", capsule),
                                         family<D>(D == 2 ? "ellipse" : "ellipsoid", ellipsoid), family<D>("cluster", cluster),
                                         family<D>(D == 2 ? "polygon" : "polyhedron", polytope)};
  if constexpr (D == 3) prototypes.push_back(family<D>("cylinder", cylinder));
  Rng rng(seed);
  ShapePacking<D> p;
  p.origin = origin;
  for (const auto& s : prototypes) p.template_names.push_back(s->kind());
  for (int i = 0; i < n; ++i) {
    Particle<D> q;
    q.template_id = static_cast<int>(rng.below(prototypes.size()));
    q.size = rng.uniform(0.5, 2.0);
    q.shape = prototypes[static_cast<std::size_t>(q.template_id)]->scaled(q.size);
    for (int k = 0; k < D; ++k) q.pose.position[k] = rng.uniform(-10, 10) + 1e3 / 3;
    if constexpr (D == 2) q.pose.rotation = rotation_2d(rng.uniform(-kPi, kPi));
    else q.pose.rotation = Eigen::Quaterniond(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
                               .normalized()
                               .toRotationMatrix();
    p.particles.push_back(q);
  }
  return p;
}

template <int D>
void round_trip(const Vec<D>& origin) {
  TempDir dir;
  const ShapePacking<D> p = every_family<D>(60, 70 + D, origin);
  RunRecord rec;
  rec.dimension = D;
  const std::string path = dir.file("p.json");
  write_packing<D>(OutputFormat::Json, path, p, rec);
  const std::string text = slurp(path);
  ASSERT_TRUE(is_shape_packing_json(text));
  const ShapePacking<D> q = read_shape_packing_json<D>(text, path, origin);
  ASSERT_EQ(q.size(), p.size());
  EXPECT_EQ(q.template_names, p.template_names);
  Rng rng(5);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Particle<D>& a = p.particles[i];
    const Particle<D>& b = q.particles[i];
    EXPECT_EQ(b.template_id, a.template_id);
    EXPECT_EQ(b.size, a.size);
    EXPECT_TRUE(b.pose.position == a.pose.position) << i << ": " << b.pose.position.transpose() << " vs " << a.pose.position.transpose();
    EXPECT_LE((b.pose.rotation - a.pose.rotation).norm(), 1e-14) << i;
    EXPECT_STREQ(b.shape->kind(), a.shape->kind());
    const double r = a.shape->bounding_radius();
    EXPECT_NEAR(b.shape->bounding_radius(), r, 1e-14 * r) << i;
    EXPECT_NEAR(b.shape->measure(), a.shape->measure(), 1e-12 * a.shape->measure()) << i << " " << a.shape->kind();
    for (int k = 0; k < 8; ++k) {
      Vec<D> u;
      for (int c = 0; c < D; ++c) u[c] = rng.uniform(-1, 1);
      EXPECT_LE((b.shape->support(u) - a.shape->support(u)).norm(), 1e-13 * r) << i << " " << a.shape->kind();
    }
  }
}

TEST(ShapePackingReader, EveryFamilyReadsBack2D) { round_trip<2>(Vec2::Zero()); }
TEST(ShapePackingReader, EveryFamilyReadsBack3D) { round_trip<3>(Vec3::Zero()); }
// 1e9 from the origin a double holds 1.2e-7: the text is origin + local exactly, and the reader
// subtracts the origin before rounding, so the local positions come back bit for bit.
TEST(ShapePackingReader, FarFromTheOriginPositionsComeBackBitForBit) {
  round_trip<2>(Vec2(1e9, -2e9));
  round_trip<3>(Vec3(1e9, -1e9, 3e9));
}

void expect_refused(const std::string& text, const std::string& fragment) {
  try {
    read_shape_packing_json<3>(text, "bad.json", Vec3::Zero());
    ADD_FAILURE() << "accepted: " << text;
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.json"), std::string::npos) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
  }
}

TEST(ShapePackingReader, BadInputNamesTheFileAndTheKey) {
  const std::string shapes =
      R"("shapes": [{"shape_id": 0, "name": "c", "count": 1, "kind": "spherocylinder", "representative_id": 0,
         "representative_size": 1, "definition": {"kind": "spherocylinder", "segment_half_length": 0.5, "radius": 0.5}}])";
  const std::string good_particle = R"({"id": 0, "shape_id": 0, "position": [1, 2, 3], "quaternion": [1, 0, 0, 0], "size": 1})";
  const auto file = [&](const std::string& s, const std::string& particle) {
    return "{\"dimension\": 3, " + s + ", \"particles\": [" + particle + "]}";
  };
  EXPECT_NO_THROW(read_shape_packing_json<3>(file(shapes, good_particle), "bad.json", Vec3::Zero()));
  expect_refused("{", "invalid JSON");
  expect_refused(R"({"dimension": 2, "shapes": [], "particles": []})", "not a 3D packing");
  expect_refused(file(shapes, R"({"shape_id": 1, "position": [1, 2, 3], "quaternion": [1, 0, 0, 0], "size": 1})"),
                 "particles[0].shape_id");
  expect_refused(file(shapes, R"({"shape_id": 0, "position": [1, 2], "quaternion": [1, 0, 0, 0], "size": 1})"),
                 "particles[0].position");
  expect_refused(file(shapes, R"({"shape_id": 0, "position": [1, 2, 3], "quaternion": [2, 0, 0, 0], "size": 1})"),
                 "not a unit quaternion");
  expect_refused(file(shapes, R"({"shape_id": 0, "position": [1, 2, 3], "quaternion": [1, 0, 0, 0], "size": -1})"),
                 "particles[0].size");
  std::string unknown = shapes;
  unknown.replace(unknown.rfind("spherocylinder"), 14, "dodecahedron");
  expect_refused(file(unknown, good_particle), "unknown shape kind 'dodecahedron'");
  std::string negative = shapes;
  negative.replace(negative.find("0.5, \"radius\""), 3, "-0.5");
  expect_refused(file(negative, good_particle), "segment_half_length: must not be negative");
  std::string no_radius = shapes;
  no_radius.replace(no_radius.find(", \"radius\": 0.5"), 15, "");
  expect_refused(file(no_radius, good_particle), "shapes[0].definition: missing key 'radius'");
}

TEST(ShapePackingReader, RecognisesItsFormat) {
  EXPECT_TRUE(is_shape_packing_json(R"({"dimension": 3, "shapes": [], "particles": []})"));
  EXPECT_FALSE(is_shape_packing_json(R"({"dimension": 3, "particles": {"x": [], "y": [], "z": [], "r": []}})"));
  EXPECT_FALSE(is_shape_packing_json("not json"));
}

}  // namespace
}  // namespace fp
