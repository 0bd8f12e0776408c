// The scene parser, particle templates (`particles: [{shape: ..., size: ...}, ...]`) and the
// packer's minimisation options: every form parses into the right spec, every family parameter
// keeps where it was written (for errors raised later by shapes/), and every bad input is
// reported with the file, the line and the dotted key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/io/scene_yaml.hpp"
#include "core/sampling/constant_radius.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "tests/io/io_test_util.hpp"

namespace fp {
namespace {

const std::string kFile = "shapes_scene.yaml";

// Three lines; the `particles` content starts on line 4.
const std::string kBox3 =
    "dimension: 3\n"
    "container: {type: box, min: [0, 0, 0], max: [10, 10, 10]}\n"
    "particles:\n";
const std::string kRect2 =
    "dimension: 2\n"
    "container: {type: rectangle, min: [0, 0], max: [20, 20]}\n"
    "particles:\n";
// A valid one-template `particles` list (lines 4-5), for tests of the other sections.
const std::string kCapsules =
    "  - shape: spherocylinder\n"
    "    size: {distribution: uniform, min: 1, max: 2}\n";

std::string location(int line) { return kFile + ":" + std::to_string(line) + ":"; }

// Parses `yaml`, expects a SceneError at `line` for `key`, whose message contains `parts`.
void expect_error(const std::string& yaml, int line, const std::string& key, const std::vector<std::string>& parts = {}) {
  try {
    parse_scene(yaml, kFile);
    ADD_FAILURE() << "no error for:\n" << yaml;
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(location(line), 0), 0u) << what;
    EXPECT_EQ(e.file(), kFile);
    EXPECT_EQ(e.line(), line) << what;
    EXPECT_GE(e.column(), 1) << what;
    if (!key.empty()) {
      EXPECT_EQ(e.key(), key) << what;
      EXPECT_NE(what.find("key '" + key + "'"), std::string::npos) << what;
    }
    for (const auto& p : parts) EXPECT_NE(what.find(p), std::string::npos) << "missing '" << p << "' in: " << what;
  }
}

void expect_spot(const SourceSpot& s, const std::string& file, int line, int column, const std::string& key) {
  EXPECT_EQ(s.file, file);
  EXPECT_EQ(s.line, line) << s.key;
  EXPECT_EQ(s.column, column) << s.key;
  EXPECT_EQ(s.key, key);
}

// ---- valid scenes --------------------------------------------------------------------------

TEST(SceneYamlShapes, ListOfTemplatesWithEveryKindOfParameter) {
  const Scene s = parse_scene(kBox3 +
                                  "  - shape: spherocylinder\n"                          // 4
                                  "    aspect_ratio: 0.5\n"                              // 5
                                  "    size: {distribution: uniform, min: 1, max: 2}\n"  // 6
                                  "    fraction: 3\n"                                    // 7
                                  "  - shape: cluster\n"                                 // 8
                                  "    centers: [[0, 0, 0], [1, 0, 0], [0, 1.5, 0]]\n"   // 9
                                  "    radii: [1, 0.5, 0.25]\n"                          // 10
                                  "    size: {distribution: constant, value: 1}\n"       // 11
                                  "    size_on: radius\n",                               // 12
                              kFile);
  EXPECT_FALSE(s.radii);  // not a sphere scene
  ASSERT_EQ(s.particle_templates.size(), 2u);

  const ParticleTemplateSpec& a = s.particle_templates[0];
  EXPECT_EQ(a.family, "spherocylinder");
  EXPECT_EQ(a.size_on, "circumscribed_radius");  // default
  EXPECT_EQ(a.orientation.kind, OrientationSpec::Kind::Isotropic);  // default
  EXPECT_EQ(a.fraction, 3.0);
  const auto* uni = dynamic_cast<const UniformRadius*>(a.size.get());
  ASSERT_NE(uni, nullptr);
  EXPECT_EQ(uni->r_min(), 1.0);
  EXPECT_EQ(uni->r_max(), 2.0);
  EXPECT_EQ(a.parameters.numbers, (std::map<std::string, double>{{"aspect_ratio", 0.5}}));
  EXPECT_TRUE(a.parameters.lists.empty());
  EXPECT_TRUE(a.parameters.point_lists.empty());
  expect_spot(a.parameters.spots.at("aspect_ratio"), kFile, 5, 19, "particles[0].aspect_ratio");
  // Common keys have spots too (shapes/ reports an unknown family or size_on there), but no values.
  EXPECT_EQ(a.parameters.spots.size(), 4u);  // shape, aspect_ratio, size, fraction
  expect_spot(a.parameters.spots.at("shape"), kFile, 4, 12, "particles[0].shape");
  expect_spot(a.parameters.spots.at("size"), kFile, 6, 11, "particles[0].size");
  expect_spot(a.parameters.spots.at("fraction"), kFile, 7, 15, "particles[0].fraction");
  EXPECT_EQ(a.parameters.spots.count("size_on"), 0u);  // not written
  expect_spot(a.parameters.spot, kFile, 4, 5, "particles[0]");

  const ParticleTemplateSpec& b = s.particle_templates[1];
  EXPECT_EQ(b.family, "cluster");
  EXPECT_EQ(b.size_on, "radius");
  EXPECT_EQ(b.fraction, 1.0);  // default
  ASSERT_NE(dynamic_cast<const ConstantRadius*>(b.size.get()), nullptr);
  EXPECT_TRUE(b.parameters.numbers.empty());
  EXPECT_EQ(b.parameters.lists.at("radii"), (std::vector<double>{1, 0.5, 0.25}));
  EXPECT_EQ(b.parameters.point_lists.at("centers"),
            (std::vector<std::vector<double>>{{0, 0, 0}, {1, 0, 0}, {0, 1.5, 0}}));
  expect_spot(b.parameters.spots.at("centers"), kFile, 9, 14, "particles[1].centers");
  expect_spot(b.parameters.spots.at("radii"), kFile, 10, 12, "particles[1].radii");
  expect_spot(b.parameters.spot, kFile, 8, 5, "particles[1]");
  expect_spot(b.parameters.spots.at("size_on"), kFile, 12, 14, "particles[1].size_on");
}

TEST(SceneYamlShapes, SpotsNameTheSceneFileItWasLoadedFrom) {
  test::TempDir dir;
  const std::string path = dir.file("capsules.yaml");
  test::spit(path, kRect2 +
                       "  - shape: polygon\n"
                       "    size: {distribution: uniform, min: 0.5, max: 1}\n"
                       "    vertices:\n"
                       "      - [0, 0]\n"
                       "      - [1, 0]\n"
                       "      - [0, 1]\n");
  const Scene s = load_scene(path);
  ASSERT_EQ(s.particle_templates.size(), 1u);
  const ShapeParameters& p = s.particle_templates[0].parameters;
  EXPECT_EQ(p.point_lists.at("vertices"), (std::vector<std::vector<double>>{{0, 0}, {1, 0}, {0, 1}}));
  expect_spot(p.spots.at("vertices"), path, 7, 7, "particles[0].vertices");
  expect_spot(p.spot, path, 4, 5, "particles[0]");
}

TEST(SceneYamlShapes, OneTemplateMappingWithAShapeKey) {
  // Flow form: the template is `particles` itself, its parameters are `particles.<key>`.
  {
    const Scene s = parse_scene(kBox3.substr(0, kBox3.size() - 1) +
                                    " {shape: spherocylinder, aspect_ratio: 0.25, size: {distribution: constant, value: 2}}\n",
                                kFile);
    EXPECT_FALSE(s.radii);
    ASSERT_EQ(s.particle_templates.size(), 1u);
    const ParticleTemplateSpec& t = s.particle_templates[0];
    EXPECT_EQ(t.family, "spherocylinder");
    EXPECT_EQ(t.parameters.numbers.at("aspect_ratio"), 0.25);
    expect_spot(t.parameters.spots.at("aspect_ratio"), kFile, 3, 50, "particles.aspect_ratio");
    expect_spot(t.parameters.spot, kFile, 3, 12, "particles");
  }
  // Block form.
  {
    const Scene s = parse_scene(kRect2 +
                                    "  shape: ellipse\n"
                                    "  axes: [1, 0.5]\n"
                                    "  size: {distribution: uniform, min: 0.5, max: 1}\n"
                                    "  orientation: {fixed: 45}\n",
                                kFile);
    ASSERT_EQ(s.particle_templates.size(), 1u);
    const ParticleTemplateSpec& t = s.particle_templates[0];
    EXPECT_EQ(t.family, "ellipse");
    EXPECT_EQ(t.parameters.lists.at("axes"), (std::vector<double>{1, 0.5}));
    expect_spot(t.parameters.spots.at("axes"), kFile, 5, 9, "particles.axes");
    EXPECT_EQ(t.orientation.kind, OrientationSpec::Kind::Fixed);
    EXPECT_EQ(t.orientation.fixed, (std::vector<double>{45}));
  }
}

TEST(SceneYamlShapes, SphereFormIsUnchangedAndSphereTemplatesStayTemplates) {
  {
    const Scene s = parse_scene(kBox3 + "  radius: {distribution: uniform, min: 0.1, max: 0.2}\n", kFile);
    ASSERT_TRUE(s.radii);
    EXPECT_EQ(s.radii->r_max(), 0.2);
    EXPECT_TRUE(s.particle_templates.empty());
  }
  {
    // All-sphere templates are not converted into the sphere form: the lead's dispatch decides.
    const Scene s = parse_scene(kBox3 +
                                    "  - shape: sphere\n"
                                    "    size: {distribution: uniform, min: 0.1, max: 0.2}\n"
                                    "    size_on: radius\n",
                                kFile);
    EXPECT_FALSE(s.radii);
    ASSERT_EQ(s.particle_templates.size(), 1u);
    EXPECT_EQ(s.particle_templates[0].family, "sphere");
    EXPECT_EQ(s.particle_templates[0].size_on, "radius");
    const ShapeParameters& p = s.particle_templates[0].parameters;
    EXPECT_TRUE(p.numbers.empty() && p.lists.empty() && p.point_lists.empty());
  }
  {
    // A mixed scene: spheres next to capsules.
    const Scene s = parse_scene(kBox3 +
                                    "  - {shape: sphere, size: {distribution: constant, value: 1}, fraction: 0.25}\n" +
                                    kCapsules,
                                kFile);
    ASSERT_EQ(s.particle_templates.size(), 2u);
    EXPECT_EQ(s.particle_templates[0].fraction, 0.25);
    EXPECT_EQ(s.particle_templates[1].family, "spherocylinder");
  }
}

TEST(SceneYamlShapes, TemplateSizesAreNotCheckedAgainstTheContainer) {
  // The shape layer knows the shape's extent; the parser only checks that sizes are positive.
  const Scene s = parse_scene(kBox3 + "  - shape: spherocylinder\n    size: {distribution: uniform, min: 50, max: 60}\n", kFile);
  ASSERT_EQ(s.particle_templates.size(), 1u);
  EXPECT_EQ(s.particle_templates[0].size->r_min(), 50.0);
}

TEST(SceneYamlShapes, Orientation2D) {
  auto orientation = [](const std::string& line) {
    return parse_scene(kRect2 + kCapsules + line, kFile).particle_templates.at(0).orientation;
  };
  EXPECT_EQ(orientation("").kind, OrientationSpec::Kind::Isotropic);
  EXPECT_TRUE(orientation("").fixed.empty());
  EXPECT_EQ(orientation("    orientation: random\n").kind, OrientationSpec::Kind::Isotropic);
  const OrientationSpec f = orientation("    orientation: {fixed: 30}\n");
  EXPECT_EQ(f.kind, OrientationSpec::Kind::Fixed);
  EXPECT_EQ(f.fixed, (std::vector<double>{30}));
  EXPECT_EQ(orientation("    orientation:\n      fixed: -400.5\n").fixed, (std::vector<double>{-400.5}));
}

TEST(SceneYamlShapes, Orientation3D) {
  auto orientation = [](const std::string& line) {
    return parse_scene(kBox3 + kCapsules + line, kFile).particle_templates.at(0).orientation;
  };
  EXPECT_EQ(orientation("    orientation: random\n").kind, OrientationSpec::Kind::Isotropic);
  const OrientationSpec f = orientation("    orientation: {fixed: [0, 0, 0.6, 0.8]}\n");
  EXPECT_EQ(f.kind, OrientationSpec::Kind::Fixed);
  ASSERT_EQ(f.fixed.size(), 4u);
  EXPECT_DOUBLE_EQ(f.fixed[2], 0.6);
  EXPECT_DOUBLE_EQ(f.fixed[3], 0.8);
  // Within 1e-6 of unit: normalised.
  const OrientationSpec g = orientation("    orientation: {fixed: [0.5, 0.5, 0.5, 0.5000008]}\n");
  ASSERT_EQ(g.fixed.size(), 4u);
  double norm2 = 0;
  for (double c : g.fixed) norm2 += c * c;
  EXPECT_NEAR(norm2, 1.0, 1e-15);
  EXPECT_LT(g.fixed[0], 0.5);
}

TEST(SceneYamlShapes, MinimisationOptions) {
  const Scene d = parse_scene(kBox3 + kCapsules, kFile);
  const MinimisationOptions defaults;
  EXPECT_EQ(d.packer.minimisation.algorithm, defaults.algorithm);
  EXPECT_EQ(d.packer.minimisation.gap_tolerance, defaults.gap_tolerance);
  EXPECT_EQ(d.packer.minimisation.max_evaluations, defaults.max_evaluations);
  EXPECT_EQ(d.packer.minimisation.polish, defaults.polish);

  const Scene s = parse_scene(kBox3 + kCapsules +
                                  "packer:\n"
                                  "  front: random\n"
                                  "  minimisation:\n"
                                  "    algorithm: nelder-mead\n"
                                  "    gap_tolerance: 1e-4\n"
                                  "    max_evaluations: 1e3\n"
                                  "    polish: false\n",
                              kFile);
  EXPECT_EQ(s.packer.front_pick, FrontPick::Random);
  EXPECT_EQ(s.packer.minimisation.algorithm, "nelder-mead");
  EXPECT_EQ(s.packer.minimisation.gap_tolerance, 1e-4);
  EXPECT_EQ(s.packer.minimisation.max_evaluations, 1000);
  EXPECT_FALSE(s.packer.minimisation.polish);
  for (const char* a : {"slsqp", "lbfgs", "nelder-mead", "cobyla", "sbplx"})
    EXPECT_EQ(parse_scene(kRect2 + kCapsules + "packer: {minimisation: {algorithm: " + a + "}}\n", kFile).packer.minimisation.algorithm, a);
  // Only the given keys change.
  const Scene p = parse_scene(kBox3 + kCapsules + "packer: {minimisation: {max_evaluations: 10}}\n", kFile);
  EXPECT_EQ(p.packer.minimisation.max_evaluations, 10);
  EXPECT_EQ(p.packer.minimisation.algorithm, defaults.algorithm);
}

// packer.contact_tolerance means the same for every particle kind: for templates it is the
// minimisation's gap_tolerance (one setting, two names); two different values are refused.
TEST(SceneYamlShapes, ContactToleranceIsTheToleranceOfTemplatesToo) {
  const Scene s = parse_scene(kBox3 + kCapsules + "packer: {contact_tolerance: 1e-4}\n", kFile);
  EXPECT_EQ(s.packer.minimisation.gap_tolerance, 1e-4);
  EXPECT_EQ(s.packer.contact_tolerance, 1e-4);
  const Scene both = parse_scene(kBox3 + kCapsules + "packer: {contact_tolerance: 1e-5, minimisation: {gap_tolerance: 1e-5}}\n", kFile);
  EXPECT_EQ(both.packer.minimisation.gap_tolerance, 1e-5);
  expect_error(kBox3 + kCapsules + "packer: {minimisation: {gap_tolerance: 1e-5}, contact_tolerance: 1e-4}\n", 6,
               "packer.contact_tolerance", {"gap_tolerance", "give one of them"});
  EXPECT_EQ(parse_scene(kBox3 + kCapsules, kFile).packer.minimisation.gap_tolerance, MinimisationOptions{}.gap_tolerance);
}

TEST(SceneYamlShapes, StopPackerAndOutputSectionsStillApply) {
  const Scene s = parse_scene(kBox3 + kCapsules +
                                  "seed: 9\n"
                                  "packer: {seed_point: [5, 5, 5]}\n"
                                  "stop: {particles: 2000}\n"
                                  "output:\n  - path: out/capsules.vtu\n",
                              kFile);
  EXPECT_EQ(s.seed, 9u);
  EXPECT_EQ(*s.packer.seed_point, (std::vector<double>{5, 5, 5}));
  EXPECT_EQ(s.stop.max_particles, 2000u);
  ASSERT_EQ(s.outputs.size(), 1u);
  EXPECT_EQ(s.outputs[0].format, "vtu");
}

TEST(SceneYamlShapes, ShapeScenesOfTheRepositoryParse) {
  const std::string dir = std::string(FRONTPACK_SOURCE_DIR) + "/scenes/";
  struct Expected {
    const char* file;
    int dimension;
    const char* family;
  };
  for (const Expected& e : {Expected{"perez-capsules-2d.yaml", 2, "spherocylinder"}, Expected{"perez-capsules-3d.yaml", 3, "spherocylinder"},
                            Expected{"shapes-polyhedra.yaml", 3, "polyhedron"}, Expected{"shapes-ellipsoids.yaml", 3, "ellipsoid"},
                            Expected{"shapes-clusters.yaml", 3, "cluster"}, Expected{"shapes-polygons-2d.yaml", 2, "polygon"},
                            Expected{"shapes-ellipses-2d.yaml", 2, "ellipse"}, Expected{"shapes-capsules-mesh.yaml", 3, "spherocylinder"}}) {
    SCOPED_TRACE(e.file);
    const Scene s = load_scene(dir + e.file);
    EXPECT_EQ(s.dimension, e.dimension);
    EXPECT_FALSE(s.radii);
    ASSERT_FALSE(s.particle_templates.empty());
    for (const auto& t : s.particle_templates) EXPECT_EQ(t.family, e.family);
    EXPECT_FALSE(s.outputs.empty());
  }
  // Paper 004's 2D case: capsules of aspect ratio 0.5 with circumscribed radii U[1, 2] in a square of side 20.
  const Scene p = load_scene(dir + "perez-capsules-2d.yaml");
  ASSERT_EQ(p.particle_templates.size(), 1u);
  EXPECT_EQ(p.particle_templates[0].parameters.numbers.at("aspect_ratio"), 0.5);
  EXPECT_EQ(p.particle_templates[0].size_on, "circumscribed_radius");
  EXPECT_EQ(p.particle_templates[0].size->r_min(), 1.0);
  EXPECT_EQ(p.particle_templates[0].size->r_max(), 2.0);
  EXPECT_EQ(p.container2->bounds().size(), Vec2(20, 20));
  ASSERT_EQ(p.outputs.size(), 3u);
  EXPECT_EQ(p.outputs[0].path, std::string(FRONTPACK_SOURCE_DIR) + "/out/perez-capsules-2d.vtu");  // ../out/ from scenes/
  EXPECT_EQ(load_scene(dir + "perez-capsules-3d.yaml").container3->bounds().size(), Vec3(40, 40, 40));
}

// ---- errors ----------------------------------------------------------------------------------

TEST(SceneYamlShapesErrors, MissingShape) {
  expect_error(kBox3 + "  - size: {distribution: uniform, min: 1, max: 2}\n    aspect_ratio: 0.5\n", 4, "particles[0].shape",
               {"missing required key", "shape family"});
  expect_error(kBox3 + kCapsules + "  - aspect_ratio: 0.5\n    size: {distribution: uniform, min: 1, max: 2}\n", 6,
               "particles[1].shape", {"missing required key"});
  // A single mapping with template keys but no `shape` is a template missing its shape, not a sphere scene.
  expect_error(kBox3 + "  size: {distribution: uniform, min: 1, max: 2}\n  orientation: random\n", 4, "particles.shape",
               {"missing required key"});
  expect_error(kBox3 + "  - shape: \"\"\n    size: {distribution: uniform, min: 1, max: 2}\n", 4, "particles[0].shape",
               {"must name a shape family"});
  expect_error(kBox3 + "  - shape: [capsule]\n    size: {distribution: uniform, min: 1, max: 2}\n", 4, "particles[0].shape",
               {"expected a string", "a list"});
}

TEST(SceneYamlShapesErrors, MissingOrBadSize) {
  expect_error(kBox3 + "  - shape: spherocylinder\n    aspect_ratio: 0.5\n", 4, "particles[0].size",
               {"missing required key", "size distribution"});
  expect_error(kBox3 + "  - shape: spherocylinder\n    size:\n      distribution: uniform\n      min: -1\n      max: 2\n", 7,
               "particles[0].size.min", {"must be positive (got -1)"});
  expect_error(kBox3 + "  - shape: spherocylinder\n    size: {distribution: uniform, min: 1, max: 2, value: 3}\n", 5,
               "particles[0].size.value", {"not used by the 'uniform' distribution"});
  expect_error(kBox3 + "  - shape: spherocylinder\n    size: 1.5\n", 5, "particles[0].size", {"expected a mapping"});
  expect_error(kBox3 + kCapsules + "    size_on: [radius]\n", 6, "particles[0].size_on", {"expected a string"});
  expect_error(kBox3 + kCapsules + "    size_on: \"\"\n", 6, "particles[0].size_on", {"must name a dimension"});
}

TEST(SceneYamlShapesErrors, BadOrientation) {
  expect_error(kBox3 + kCapsules + "    orientation: randm\n", 6, "particles[0].orientation",
               {"unknown orientation 'randm'", "did you mean 'random'", "{fixed: [w, x, y, z]}"});
  expect_error(kRect2 + kCapsules + "    orientation: fixed\n", 6, "particles[0].orientation", {"{fixed: <angle in degrees>}"});
  expect_error(kBox3 + kCapsules + "    orientation: [1, 0, 0, 0]\n", 6, "particles[0].orientation", {"expected 'random' (isotropic), {fixed:", "{law: watson | fisher", "a list"});
  expect_error(kBox3 + kCapsules + "    orientation: {fixd: [1, 0, 0, 0]}\n", 6, "particles[0].orientation.fixd",
               {"unknown key", "did you mean 'fixed'"});
  expect_error(kBox3 + kCapsules + "    orientation: {}\n", 6, "particles[0].orientation.fixed", {"missing required key"});
  // 2D wants one angle, 3D a quaternion.
  expect_error(kRect2 + kCapsules + "    orientation: {fixed: [30]}\n", 6, "particles[0].orientation.fixed",
               {"in 2D", "one angle in degrees", "got a list"});
  expect_error(kRect2 + kCapsules + "    orientation: {fixed: thirty}\n", 6, "particles[0].orientation.fixed", {"expected a number"});
  expect_error(kBox3 + kCapsules + "    orientation: {fixed: 30}\n", 6, "particles[0].orientation.fixed",
               {"in 3D", "unit quaternion [w, x, y, z]", "'30'"});
  expect_error(kBox3 + kCapsules + "    orientation:\n      fixed: [1, 0, 0]\n", 7, "particles[0].orientation.fixed",
               {"4 components, got 3"});
  expect_error(kBox3 + kCapsules + "    orientation:\n      fixed: [1, 0, x, 0]\n", 7, "particles[0].orientation.fixed[2]",
               {"expected a number", "'x'"});
}

TEST(SceneYamlShapesErrors, BadOrientationLaw) {
  const std::string c = kBox3 + kCapsules;
  expect_error(c + "    orientation: {law: watsn, axis: [0, 0, 1], kappa: 2}\n", 6, "particles[0].orientation.law",
               {"unknown value 'watsn'", "did you mean 'watson'"});
  expect_error(c + "    orientation: {law: watson, kappa: 2}\n", 6, "particles[0].orientation.axis", {"missing required key", "[x, y, z]"});
  expect_error(c + "    orientation: {law: watson, axis: [0, 0]}\n", 6, "particles[0].orientation.axis", {"must have 3 components"});
  expect_error(c + "    orientation: {law: watson, axis: [0, 0, 0], kappa: 1}\n", 6, "particles[0].orientation.axis", {"non-zero"});
  expect_error(c + "    orientation: {law: watson, axis: [0, 0, 1]}\n", 6, "particles[0].orientation", {"needs its concentration", "order: S"});
  expect_error(c + "    orientation: {law: watson, axis: [0, 0, 1], kappa: 1, order: 0.5}\n", 6, "particles[0].orientation.order",
               {"either kappa or order"});
  expect_error(c + "    orientation: {law: watson, axis: [0, 0, 1], kappa: 2000}\n", 6, "particles[0].orientation.kappa",
               {"within [-1000, 1000]", "fixed orientation"});
  expect_error(c + "    orientation: {law: fisher, axis: [0, 0, 1], kappa: -1}\n", 6, "particles[0].orientation.kappa", {">= 0"});
  expect_error(c + "    orientation: {law: watson, axis: [0, 0, 1], order: 1}\n", 6, "particles[0].orientation.order",
               {"nematic order 1 is beyond"});
  expect_error(c + "    orientation: {law: fisher, axis: [0, 0, 1], order: -0.2}\n", 6, "particles[0].orientation.order", {"beyond"});
  expect_error(c + "    orientation: {law: watson, fixed: [1, 0, 0, 0], axis: [0, 0, 1], kappa: 1}\n", 6, "particles[0].orientation.law",
               {"not both"});
  expect_error(c + "    orientation: {law: isotropic, kappa: 1}\n", 6, "particles[0].orientation.kappa", {"no parameters"});
  expect_error(c + "    orientation: {fixed: [1, 0, 0, 0], kappa: 1}\n", 6, "particles[0].orientation.kappa", {"needs 'law: watson'"});
  expect_error(kRect2 + kCapsules + "    orientation: {law: fisher, axis: [0, 0, 1], kappa: 1}\n", 6, "particles[0].orientation.axis",
               {"must have 2 components"});
}

TEST(SceneYamlShapes, OrientationLaws) {
  auto orientation = [](const std::string& base, const std::string& line) {
    return parse_scene(base + kCapsules + line, kFile).particle_templates.at(0).orientation;
  };
  const OrientationSpec w = orientation(kBox3, "    orientation: {law: watson, axis: [0, 0, 2], kappa: -3}\n");
  EXPECT_EQ(w.kind, OrientationKind::Watson);
  EXPECT_EQ(w.axis, (std::vector<double>{0, 0, 1}));
  EXPECT_EQ(w.kappa, -3.0);
  // An order S instead of kappa: the kappa that gives it.
  const OrientationSpec s = orientation(kBox3, "    orientation: {law: watson, axis: [1, 0, 0], order: 0.5}\n");
  EXPECT_NEAR(s.law<3>().angle_law()->order(), 0.5, 1e-7);
  const OrientationSpec f = orientation(kRect2, "    orientation: {law: fisher, axis: [0, 3], order: 0.3}\n");
  EXPECT_EQ(f.kind, OrientationKind::Fisher);
  EXPECT_EQ(f.axis, (std::vector<double>{0, 1}));
  EXPECT_NEAR(f.law<2>().angle_law()->order(), 0.3, 1e-7);
  EXPECT_EQ(orientation(kBox3, "    orientation: isotropic\n").kind, OrientationKind::Isotropic);
  EXPECT_EQ(orientation(kBox3, "    orientation: {law: isotropic}\n").kind, OrientationKind::Isotropic);
}

TEST(SceneYamlShapes, OrientationSearchKeys) {
  const Scene d = parse_scene(kBox3 + kCapsules, kFile);
  EXPECT_EQ(d.packer.orientation_trials, 1);
  EXPECT_EQ(d.packer.roll_steps, 60);
  EXPECT_EQ(d.packer.pocket_trials, 32);
  EXPECT_EQ(d.packer.orientation_frame, fp::OrientationFrame::Radial);
  EXPECT_FALSE(d.packer.face_to_face);
  const Scene s = parse_scene(kBox3 + kCapsules + "packer: {orientation_trials: 4, roll_steps: 0, pocket_trials: 0}\n", kFile);
  EXPECT_EQ(s.packer.orientation_trials, 4);
  EXPECT_EQ(s.packer.roll_steps, 0);
  EXPECT_EQ(s.packer.pocket_trials, 0);
  const Scene lab = parse_scene(kBox3 + kCapsules + "packer: {orientation_frame: lab, face_to_face: true}\n", kFile);
  EXPECT_EQ(lab.packer.orientation_frame, fp::OrientationFrame::Lab);
  EXPECT_TRUE(lab.packer.face_to_face);
  expect_error(kBox3 + kCapsules + "packer: {orientation_frame: polar}\n", 6, "packer.orientation_frame", {"radial", "lab"});
  // Face-to-face turns are not turns about the radius: the radial frame refuses them.
  expect_error(kBox3 + kCapsules + "packer: {face_to_face: true}\n", 6, "packer.face_to_face", {"radial", "orientation_frame: lab"});
  expect_error(kBox3 + kCapsules + "packer:\n  orientation_frame: radial\n  face_to_face: true\n", 8, "packer.face_to_face",
               {"orientation_frame: lab"});
  expect_error(kBox3 + kCapsules + "packer: {pocket_trials: 10001}\n", 6, "packer.pocket_trials", {"from 0 to 10000"});
  expect_error(kBox3 + kCapsules + "packer: {pocket_trials: 2.5}\n", 6, "packer.pocket_trials", {"integer"});
  expect_error(kBox3 + kCapsules + "packer: {orientation_trials: 0}\n", 6, "packer.orientation_trials", {"from 1 to 10000"});
  expect_error(kBox3 + kCapsules + "packer: {roll_steps: -1}\n", 6, "packer.roll_steps", {"non-negative integer"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [10, 10, 10]}\n"
               "particles: {radius: {distribution: uniform, min: 1, max: 2}}\npacker: {roll_steps: 5}\n",
               4, "packer.roll_steps", {"spheres", "have none"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [10, 10, 10]}\n"
               "particles: {radius: {distribution: uniform, min: 1, max: 2}}\npacker: {orientation_frame: lab}\n",
               4, "packer.orientation_frame", {"spheres", "have none"});
}

TEST(SceneYamlShapesErrors, NonUnitQuaternion) {
  expect_error(kBox3 + kCapsules + "    orientation:\n      fixed: [1, 1, 0, 0]\n", 7, "particles[0].orientation.fixed",
               {"unit quaternion", "within 1e-6", "norm 1.41421356"});
  expect_error(kBox3 + kCapsules + "    orientation: {fixed: [0.5, 0.5, 0.5, 0.50001]}\n", 6, "particles[0].orientation.fixed",
               {"unit quaternion"});
  expect_error(kBox3 + kCapsules + "    orientation: {fixed: [0, 0, 0, 0]}\n", 6, "particles[0].orientation.fixed", {"norm 0"});
}

TEST(SceneYamlShapesErrors, BadFraction) {
  expect_error(kBox3 + kCapsules + "    fraction: -1\n", 6, "particles[0].fraction", {"must be positive (got -1)"});
  expect_error(kBox3 + kCapsules + "    fraction: 0\n", 6, "particles[0].fraction", {"must be positive (got 0)"});
  expect_error(kBox3 + kCapsules + "    fraction: half\n", 6, "particles[0].fraction", {"expected a number", "'half'"});
}

TEST(SceneYamlShapesErrors, ListWhereANumberIsNeeded) {
  expect_error(kBox3 + kCapsules + "    fraction: [1]\n", 6, "particles[0].fraction", {"expected a number, got a list"});
  expect_error(kBox3 + "  - shape: spherocylinder\n    size:\n      distribution: constant\n      value: [1, 2]\n", 7,
               "particles[0].size.value", {"expected a number, got a list"});
  expect_error(kBox3 + kCapsules + "packer:\n  minimisation:\n    gap_tolerance: [1e-6]\n", 8,
               "packer.minimisation.gap_tolerance", {"expected a number, got a list"});
  // A parameter list nested too deep.
  expect_error(kBox3 + kCapsules + "    vertices: [[[0, 0, 0]]]\n", 6, "particles[0].vertices[0][0]", {"expected a number, got a list"});
}

TEST(SceneYamlShapesErrors, BadShapeParameters) {
  // A list of points must hold only points.
  expect_error(kRect2 + kCapsules + "    vertices:\n      - [0, 0]\n      - [1, 0]\n      - 1\n", 9, "particles[0].vertices[2]",
               {"expected a point", "'1'"});
  // A list of numbers must hold only numbers.
  expect_error(kBox3 + kCapsules + "    radii: [1, [2], 3]\n", 6, "particles[0].radii[1]", {"expected a number, got a list"});
  // (A word such as `.5.` is kept as a word; the shape family refuses it where it wants a number.)
  expect_error(kBox3 + kCapsules + "    aspect_ratio: 1e999\n", 6, "particles[0].aspect_ratio", {"out of range"});
  expect_error(kBox3 + kCapsules + "    aspect_ratio:\n", 6, "particles[0].aspect_ratio", {"got nothing"});
  // A mapping is never a parameter: a misspelt common key, or a distribution outside `size`.
  expect_error(kRect2 + kCapsules + "    orientaton: {fixed: 30}\n", 6, "particles[0].orientaton",
               {"got a mapping", "did you mean 'orientation'"});
  expect_error(kBox3 + "  - shape: sphere\n    radius: {distribution: constant, value: 1}\n", 5, "particles[0].radius",
               {"got a mapping", "a size distribution goes in 'size'"});
}

// Named parameters (`preset: cube`) are kept as words, with their spot.
TEST(SceneYamlShapes, StringParameters) {
  const std::string yaml = kBox3 + "  - shape: polyhedron\n    preset: cube\n    size: {distribution: constant, value: 1}\n";
  const Scene s = parse_scene(yaml, kFile);
  EXPECT_EQ(s.particle_templates.at(0).parameters.strings.at("preset"), "cube");
  expect_spot(s.particle_templates.at(0).parameters.spots.at("preset"), kFile, 5, 13, "particles[0].preset");
}

TEST(SceneYamlShapesErrors, BadParticlesSection) {
  expect_error(kBox3 + "  []\n", 4, "particles", {"at least one particle template"});
  expect_error(kBox3.substr(0, kBox3.size() - 1) + " 3\n", 3, "particles", {"for spheres", "list of particle templates", "'3'"});
  expect_error(kBox3 + "  - sphere\n", 4, "particles[0]", {"expected a particle template", "'sphere'"});
  expect_error(kBox3 + "  radius: {distribution: constant, value: 1}\n  count: 5\n", 5, "particles.count", {"unknown key"});
  expect_error(kBox3 + "  {}\n", 4, "particles.radius", {"missing required key", "'shape'"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n", 1, "particles",
               {"missing required key", "list of particle templates"});
}

TEST(SceneYamlShapesErrors, BadMinimisationOptions) {
  expect_error(kBox3 + kCapsules + "packer:\n  minimisation:\n    algorithm: nelder_mead\n", 8, "packer.minimisation.algorithm",
               {"unknown value 'nelder_mead'", "did you mean 'nelder-mead'", "slsqp, lbfgs, nelder-mead, cobyla, sbplx"});
  expect_error(kBox3 + kCapsules + "packer: {minimisation: {algorithm: bfgs}}\n", 6, "packer.minimisation.algorithm",
               {"did you mean 'lbfgs'"});
  expect_error(kBox3 + kCapsules + "packer:\n  minimisation:\n    gap_tolerance: 0.5\n", 8, "packer.minimisation.gap_tolerance",
               {"(0, 0.1)"});
  expect_error(kBox3 + kCapsules + "packer:\n  minimisation:\n    gap_tolerance: 0\n", 8, "packer.minimisation.gap_tolerance",
               {"(0, 0.1)"});
  expect_error(kBox3 + kCapsules + "packer:\n  minimisation:\n    max_evaluations: 5\n", 8, "packer.minimisation.max_evaluations",
               {"from 10"});
  expect_error(kBox3 + kCapsules + "packer:\n  minimisation:\n    max_evaluations: 100.5\n", 8,
               "packer.minimisation.max_evaluations", {"integer"});
  expect_error(kBox3 + kCapsules + "packer:\n  minimisation:\n    polish: sometimes\n", 8, "packer.minimisation.polish",
               {"true or false"});
  expect_error(kBox3 + kCapsules + "packer:\n  minimisation:\n    max_evaluation: 50\n", 8, "packer.minimisation.max_evaluation",
               {"unknown key", "did you mean 'max_evaluations'"});
  expect_error(kBox3 + kCapsules + "packer:\n  minimisation: slsqp\n", 7, "packer.minimisation", {"expected a mapping"});
  expect_error(kBox3 + kCapsules + "packer:\n  minimization: {algorithm: slsqp}\n", 7, "packer.minimization",
               {"did you mean 'minimisation'"});
  // Sphere scenes solve contacts in closed form: the option would be silently ignored.
  expect_error(kBox3 + "  radius: {distribution: constant, value: 1}\npacker:\n  minimisation: {algorithm: slsqp}\n", 6,
               "packer.minimisation", {"particle templates only"});
}

}  // namespace
}  // namespace fp
