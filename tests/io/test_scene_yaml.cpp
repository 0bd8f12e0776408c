// The scene parser: every kind of container and distribution parses into the right object,
// and every bad input is reported with the file, the line and the dotted key.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/ball_container.hpp"
#include "core/geometry/box_container.hpp"
#include "core/geometry/cylinder_container.hpp"
#include "core/geometry/mesh_container.hpp"
#include "core/geometry/polygon_container.hpp"
#include "core/io/scene_yaml.hpp"
#include "core/sampling/constant_radius.hpp"
#include "core/sampling/discrete_radius.hpp"
#include "core/sampling/gradation_radius.hpp"
#include "core/sampling/histogram_radius.hpp"
#include "core/sampling/lognormal_radius.hpp"
#include "core/sampling/truncated_normal_radius.hpp"
#include "core/sampling/uniform_radius.hpp"
#include "tests/io/io_test_util.hpp"

namespace fp {
namespace {

const std::string kFile = "bad_scene.yaml";

const std::string kBox3 =
    "dimension: 3\n"
    "container: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
    "particles:\n"
    "  radius: {distribution: uniform, min: 0.01, max: 0.02}\n";

const std::string kRect2 =
    "dimension: 2\n"
    "container: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
    "particles:\n"
    "  radius: {distribution: constant, value: 0.05}\n";

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

// ---- valid scenes --------------------------------------------------------------------------

TEST(SceneYaml, MinimalSceneUsesDefaults) {
  const Scene s = parse_scene(kBox3, "min.yaml");
  EXPECT_EQ(s.source_path, "min.yaml");
  EXPECT_EQ(s.source_text, kBox3);
  EXPECT_EQ(s.dimension, 3);
  EXPECT_EQ(s.seed, 1u);
  ASSERT_TRUE(s.container3);
  EXPECT_FALSE(s.container2);
  const PackerOptions defaults;
  EXPECT_EQ(s.packer.front_pick, defaults.front_pick);
  EXPECT_EQ(s.packer.candidate, defaults.candidate);
  EXPECT_EQ(s.packer.radius_pool, 4);  // measured default (experiments/front-levers)
  EXPECT_FALSE(s.packer.seed_point);
  EXPECT_FALSE(s.stop.max_particles);
  EXPECT_FALSE(s.stop.target_volume_fraction);
  EXPECT_FALSE(s.stop.time_limit_seconds);
  EXPECT_TRUE(s.outputs.empty());
}

TEST(SceneYaml, FullSceneFileFromTheRepository) {
  const std::string path = std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/scenes/io_full.yaml";
  const Scene s = load_scene(path);
  EXPECT_EQ(s.source_path, path);
  EXPECT_EQ(s.source_text, test::slurp(path));
  EXPECT_EQ(s.dimension, 3);
  EXPECT_EQ(s.seed, 18446744073709551615ULL);
  const auto* box = dynamic_cast<const BoxContainer<3>*>(s.container3.get());
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(box->lo(), Vec3(0, 0, 0));
  EXPECT_EQ(box->hi(), Vec3(0.9, 0.9, 0.9));
  const auto* uni = dynamic_cast<const UniformRadius*>(s.radii.get());
  ASSERT_NE(uni, nullptr);
  EXPECT_EQ(uni->r_min(), 0.01);
  EXPECT_EQ(uni->r_max(), 0.02);
  EXPECT_EQ(s.packer.method, "front");
  EXPECT_EQ(s.packer.front_pick, FrontPick::Random);
  EXPECT_EQ(s.packer.candidate, CandidateChoice::First);
  EXPECT_EQ(s.packer.pair_order, PairOrder::Index);
  EXPECT_FALSE(s.packer.walls_as_bodies);
  EXPECT_EQ(s.packer.radius_pool, 8);
  EXPECT_EQ(s.packer.contact_tolerance, 1e-10);
  EXPECT_EQ(s.packer.grid_cell_factor, 2.5);
  EXPECT_EQ(s.packer.hierarchical_grid_ratio, 6.0);
  ASSERT_TRUE(s.packer.seed_point);
  EXPECT_EQ(*s.packer.seed_point, (std::vector<double>{0.45, 0.45, 0.45}));
  EXPECT_EQ(s.stop.max_particles, 1000000u);
  EXPECT_EQ(s.stop.target_volume_fraction, 0.6);
  EXPECT_EQ(s.stop.time_limit_seconds, 60.0);
  ASSERT_EQ(s.outputs.size(), 6u);
  const std::pair<const char*, const char*> expected[] = {{"vtu", "out/demo.vtu"},   {"yade", "out/demo.txt"},
                                                          {"lammps", "out/demo.data"}, {"csv", "out/demo.csv"},
                                                          {"json", "out/demo.json"}, {"csv", "out/other.dat"}};
  // A path in the scene is relative to the scene file's folder, wherever the run starts.
  const std::string folder = std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/scenes/";
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(s.outputs[i].format, expected[i].first);
    EXPECT_EQ(s.outputs[i].path, folder + expected[i].second);
  }
}

TEST(SceneYaml, EveryContainerKind) {
  {
    const Scene s = parse_scene("dimension: 3\nseed: 7\ncontainer: {type: sphere, center: [1, 2, 3], radius: 2}\n"
                                "particles: {radius: {distribution: constant, value: 0.1}}\n", "a.yaml");
    const auto* c = dynamic_cast<const BallContainer<3>*>(s.container3.get());
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->center(), Vec3(1, 2, 3));
    EXPECT_EQ(c->radius(), 2.0);
    EXPECT_EQ(s.seed, 7u);
  }
  {
    const Scene s = parse_scene("dimension: 3\ncontainer: {type: cylinder, base: [0, 0, -1], axis: [0, 2, 0], radius: 0.5, height: 3}\n"
                                "particles: {radius: {distribution: constant, value: 0.1}}\n", "a.yaml");
    const auto* c = dynamic_cast<const CylinderContainer*>(s.container3.get());
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->base_center(), Vec3(0, 0, -1));
    EXPECT_EQ(c->axis(), Vec3(0, 1, 0));
    EXPECT_EQ(c->radius(), 0.5);
    EXPECT_EQ(c->height(), 3.0);
  }
  {
    const Scene s = parse_scene("dimension: 3\ncontainer: {type: cylinder, base: [0, 0, 0], radius: 1, height: 2}\n"
                                "particles: {radius: {distribution: constant, value: 0.1}}\n", "a.yaml");
    const auto* c = dynamic_cast<const CylinderContainer*>(s.container3.get());
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->axis(), Vec3(0, 0, 1));  // default axis
  }
  {
    const Scene s = parse_scene(kRect2, "a.yaml");
    const auto* c = dynamic_cast<const BoxContainer<2>*>(s.container2.get());
    ASSERT_NE(c, nullptr);
    EXPECT_FALSE(s.container3);
    EXPECT_EQ(c->hi(), Vec2(1, 1));
  }
  {
    const Scene s = parse_scene("dimension: 2\ncontainer: {type: disk, center: [0.5, -0.5], radius: 4}\n"
                                "particles: {radius: {distribution: constant, value: 0.1}}\n", "a.yaml");
    const auto* c = dynamic_cast<const BallContainer<2>*>(s.container2.get());
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->center(), Vec2(0.5, -0.5));
    EXPECT_EQ(c->radius(), 4.0);
  }
  {
    const Scene s = parse_scene("dimension: 2\ncontainer:\n  type: polygon\n  vertices: [[0, 0], [2, 0], [2, 1], [1, 0.5], [0, 1]]\n"
                                "particles: {radius: {distribution: constant, value: 0.1}}\n", "a.yaml");
    const auto* c = dynamic_cast<const PolygonContainer*>(s.container2.get());
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->vertices().size(), 5u);
    EXPECT_DOUBLE_EQ(c->measure(), 1.5);
  }
}

const char* kCubeOff =
    "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

TEST(SceneYaml, MeshFileIsRelativeToTheSceneFolder) {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "scenes" / "meshes");
  test::spit((dir.path() / "scenes" / "meshes" / "cube.off").string(), kCubeOff);
  const std::string scene = (dir.path() / "scenes" / "mesh.yaml").string();
  test::spit(scene, "dimension: 3\ncontainer: {type: mesh, file: meshes/cube.off, scale: 2}\n"
                    "particles: {radius: {distribution: constant, value: 0.1}}\n");
  const Scene s = load_scene(scene);
  const auto* m = dynamic_cast<const MeshContainer*>(s.container3.get());
  ASSERT_NE(m, nullptr);
  EXPECT_NEAR(m->measure(), 8.0, 1e-12);  // scale 2
  EXPECT_EQ(m->bounds().hi, Vec3(2, 2, 2));

  // The same scene, read from another working directory: the relative path still resolves.
  struct RestoreCwd {
    std::filesystem::path cwd = std::filesystem::current_path();
    ~RestoreCwd() { std::filesystem::current_path(cwd); }
  } restore;
  std::filesystem::current_path(dir.path());
  EXPECT_NO_THROW(load_scene("scenes/mesh.yaml"));
}

TEST(SceneYaml, EveryDistributionKind) {
  auto radii = [](const std::string& spec, int dim = 3) {
    const std::string box = dim == 3 ? "{type: box, min: [0, 0, 0], max: [100, 100, 100]}"
                                     : "{type: rectangle, min: [0, 0], max: [100, 100]}";
    return parse_scene("dimension: " + std::to_string(dim) + "\ncontainer: " + box + "\nparticles:\n  radius: " + spec + "\n",
                       "d.yaml")
        .radii;
  };
  {
    const auto d = radii("{distribution: constant, value: 0.25}");
    ASSERT_NE(dynamic_cast<const ConstantRadius*>(d.get()), nullptr);
    EXPECT_EQ(d->r_min(), 0.25);
    EXPECT_EQ(d->r_max(), 0.25);
  }
  {
    const auto d = radii("{distribution: normal, mean: 1.5, std: 0.3, min: 1, max: 2}");
    const auto* n = dynamic_cast<const TruncatedNormalRadius*>(d.get());
    ASSERT_NE(n, nullptr);
    EXPECT_EQ(n->parent_mean(), 1.5);
    EXPECT_EQ(n->parent_stddev(), 0.3);
    EXPECT_EQ(n->r_min(), 1.0);
    EXPECT_EQ(n->r_max(), 2.0);
  }
  {
    const auto d = radii("{distribution: lognormal, median: 1.5, sigma: 0.3, min: 1, max: 2}");
    const auto* l = dynamic_cast<const LognormalRadius*>(d.get());
    ASSERT_NE(l, nullptr);
    EXPECT_DOUBLE_EQ(l->mu_log(), std::log(1.5));
    EXPECT_EQ(l->sigma_log(), 0.3);
  }
  {
    const auto d = radii("{distribution: lognormal, mu: 0.25, sigma: 0.5, min: 1, max: 2}");
    const auto* l = dynamic_cast<const LognormalRadius*>(d.get());
    ASSERT_NE(l, nullptr);
    EXPECT_EQ(l->mu_log(), 0.25);
  }
  {
    const auto d = radii("{distribution: discrete, values: [[0.01, 1], [0.02, 2]]}");
    const auto* x = dynamic_cast<const DiscreteRadius*>(d.get());
    ASSERT_NE(x, nullptr);
    EXPECT_EQ(x->radii(), (std::vector<double>{0.01, 0.02}));
    EXPECT_DOUBLE_EQ(x->probabilities()[1], 2.0 / 3.0);
  }
  {
    const auto d = radii("{distribution: histogram, edges: [2, 3, 4, 6, 8], weights: [40, 30, 20, 10]}");
    const auto* h = dynamic_cast<const HistogramRadius*>(d.get());
    ASSERT_NE(h, nullptr);
    EXPECT_EQ(h->edges(), (std::vector<double>{2, 3, 4, 6, 8}));
    EXPECT_DOUBLE_EQ(h->probabilities()[0], 0.4);
  }
  for (const int dim : {2, 3}) {
    const auto d = radii("{distribution: gradation, curve: [[0.1, 0], [0.2, 30], [0.5, 100]]}", dim);
    const auto* g = dynamic_cast<const GradationRadius*>(d.get());
    ASSERT_NE(g, nullptr);
    EXPECT_EQ(g->basis(), GradationRadius::Basis::Mass);  // the default
    EXPECT_EQ(g->dimension(), dim);
    EXPECT_EQ(g->r_min(), 0.05);  // diameters in, radii out
    EXPECT_EQ(g->r_max(), 0.25);
  }
  {
    const auto d = radii("{distribution: gradation, basis: count, curve: [[0.1, 0], [0.5, 100]]}");
    const auto* g = dynamic_cast<const GradationRadius*>(d.get());
    ASSERT_NE(g, nullptr);
    EXPECT_EQ(g->basis(), GradationRadius::Basis::Count);
  }
}

TEST(SceneYaml, PackerEnumsAndOutputsMapToOptions) {
  const Scene s = parse_scene(kRect2 +
                                  "packer: {front: fifo, candidate: closest, pair_order: nearest, contact_bodies: all, walls: yes, seed_point: [0.25, 0.75]}\n"
                                  "stop: {particles: 2.5e3, time: 0.5}\n"
                                  "output:\n  - path: x.VTU\n  - {path: y.txt, format: LAMMPS}\n",
                              "p.yaml");
  EXPECT_EQ(s.packer.front_pick, FrontPick::Fifo);
  EXPECT_EQ(s.packer.candidate, CandidateChoice::ClosestToSeed);
  EXPECT_EQ(s.packer.pair_order, PairOrder::NearestFirst);
  EXPECT_EQ(s.packer.contact_bodies, ContactBodies::All);
  EXPECT_FALSE(s.packer.probe_smallest);  // not given: auto
  EXPECT_EQ(parse_scene(kRect2 + "packer: {probe_smallest: true}\n", "p.yaml").packer.probe_smallest, true);
  EXPECT_EQ(parse_scene(kRect2 + "packer: {probe_smallest: false}\n", "p.yaml").packer.probe_smallest, false);
  EXPECT_FALSE(parse_scene(kRect2 + "packer: {probe_smallest: auto}\n", "p.yaml").packer.probe_smallest);
  EXPECT_TRUE(s.packer.walls_as_bodies);
  EXPECT_EQ(*s.packer.seed_point, (std::vector<double>{0.25, 0.75}));
  EXPECT_EQ(s.stop.max_particles, 2500u);
  EXPECT_EQ(s.stop.time_limit_seconds, 0.5);
  ASSERT_EQ(s.outputs.size(), 2u);
  EXPECT_EQ(s.outputs[0].format, "vtu");  // from the extension
  EXPECT_EQ(s.outputs[1].format, "lammps");  // explicit wins over the extension
}

// ---- errors ----------------------------------------------------------------------------------

TEST(SceneYamlErrors, UnknownKeysAreNamedWithTheAllowedOnes) {
  expect_error(kBox3 + "seeed: 3\n", 5, "seeed", {"unknown key", "did you mean 'seed'", "dimension, seed, container"});
  expect_error("dimension: 3\ncontainer:\n  type: box\n  min: [0, 0, 0]\n  max: [1, 1, 1]\n  radiuss: 2\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               6, "container.radiuss", {"unknown key", "'radius'", "allowed keys in 'container'"});
  // A known key that the chosen type does not use is an error too, not silently ignored.
  expect_error("dimension: 3\ncontainer:\n  type: box\n  min: [0, 0, 0]\n  max: [1, 1, 1]\n  radius: 2\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               6, "container.radius", {"not used by a 'box' container", "type, min, max"});
  expect_error(kBox3 + "packer:\n  front: random\n  walls_as_bodies: true\n", 7, "packer.walls_as_bodies",
               {"unknown key", "walls"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius: {distribution: uniform, min: 0.01, max: 0.02, mean: 0.015}\n",
               4, "particles.radius.mean", {"not used by the 'uniform' distribution"});
  expect_error(kBox3 + "output:\n  - {format: csv, path: a.csv, precision: 3}\n", 6, "output[0].precision", {"format, path"});
}

TEST(SceneYamlErrors, DuplicateKey) {
  expect_error(kBox3 + "seed: 1\nseed: 2\n", 6, "seed", {"duplicate key", "line 5"});
}

TEST(SceneYamlErrors, WrongTypes) {
  expect_error("dimension: 3\ncontainer: {type: sphere, center: [0, 0, 0], radius: big}\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               2, "container.radius", {"expected a number", "'big'"});
  expect_error("dimension: 3\ncontainer: {type: sphere, center: [0, 0, 0], radius: \"1.0\"}\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               2, "container.radius", {"expected a number", "the string \"1.0\""});
  expect_error("dimension: 3\ncontainer: {type: sphere, center: 0, radius: 1}\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               2, "container.center", {"expected a list"});
  expect_error(kBox3 + "seed: 1.5\n", 5, "seed", {"non-negative integer", "'1.5'"});
  expect_error(kBox3 + "seed: -3\n", 5, "seed", {"non-negative integer"});
  expect_error(kBox3 + "seed: 18446744073709551616\n", 5, "seed", {"out of range"});
  expect_error(kBox3 + "packer: {walls: maybe}\n", 5, "packer.walls", {"true or false", "'maybe'"});
  expect_error(kBox3 + "packer: {radius_pool: 2.5}\n", 5, "packer.radius_pool", {"integer"});
  expect_error(kBox3 + "stop: {particles: 10.5}\n", 5, "stop.particles", {"integer"});
  expect_error(kBox3 + "output: {format: csv, path: a.csv}\n", 5, "output", {"list"});
  expect_error("dimension: 3\ncontainer: box\nparticles: {radius: {distribution: constant, value: 0.1}}\n", 2,
               "container", {"expected a mapping"});
  expect_error("dimension: three\n" + kBox3.substr(13), 1, "dimension", {"'three'"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius: {distribution: discrete, values: [[0.01, 1], [0.02]]}\n",
               4, "particles.radius.values[1]", {"pair [radius, count weight]"});
}

TEST(SceneYamlErrors, WrongListLength) {
  expect_error("dimension: 3\ncontainer:\n  type: box\n  min: [0, 0]\n  max: [1, 1, 1]\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               4, "container.min", {"must have 3 components", "got 2"});
  expect_error(kRect2 + "packer:\n  seed_point: [0.5, 0.5, 0.5]\n", 6, "packer.seed_point", {"2 components"});
  expect_error("dimension: 2\ncontainer:\n  type: polygon\n  vertices: [[0, 0], [1, 0, 0], [1, 1]]\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               4, "container.vertices[1]", {"2 components"});
}

TEST(SceneYamlErrors, MinGreaterThanMax) {
  expect_error("dimension: 3\ncontainer:\n  type: box\n  min: [0, 0, 0]\n  max: [1, -1, 1]\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               5, "container.max", {"greater than container.min", "on y"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius:\n    distribution: uniform\n    min: 0.02\n    max: 0.01\n",
               7, "particles.radius.max", {"greater than min"});
}

TEST(SceneYamlErrors, NonPositiveSizes) {
  expect_error("dimension: 3\ncontainer:\n  type: sphere\n  center: [0, 0, 0]\n  radius: -1\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               5, "container.radius", {"must be positive (got -1)"});
  expect_error("dimension: 3\ncontainer: {type: cylinder, base: [0, 0, 0], radius: 1, height: 0}\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               2, "container.height", {"must be positive (got 0)"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius:\n    distribution: constant\n    value: 0\n",
               6, "particles.radius.value", {"must be positive"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius: {distribution: normal, mean: 0.1, std: -0.01, min: 0.05, max: 0.2}\n",
               4, "particles.radius.std", {"must be positive"});
  // A spread every draw rounds away is one radius: its law's CDF jumps and the radii test fails.
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius: {distribution: normal, mean: 0.1, std: 1e-300, min: 0.05, max: 0.2}\n",
               4, "particles.radius.std", {"below 1e-9 of the radii (got 1e-300)", "distribution: constant"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius: {distribution: lognormal, median: 0.1, sigma: 1e-12, min: 0.05, max: 0.2}\n",
               4, "particles.radius.sigma", {"below 1e-9", "distribution: constant"});
  expect_error(kBox3 + "stop:\n  time: -5\n", 6, "stop.time", {"must be positive"});
  expect_error(kBox3 + "stop:\n  particles: 0\n", 6, "stop.particles", {"positive integer"});
}

// stop.scale_sizes solves for the scale at which the front's N particles fill the container:
// without N, or with what cuts its trial packings short or changes the count, it is refused at its key.
TEST(SceneYamlErrors, ScaleSizesNeedsACountAndNothingThatChangesIt) {
  const Scene ok = parse_scene(kBox3 + "stop: {particles: 300, scale_sizes: true}\n", kFile);
  EXPECT_TRUE(ok.stop.scale_sizes);
  EXPECT_FALSE(parse_scene(kBox3 + "stop: {particles: 300, scale_sizes: false}\n", kFile).stop.scale_sizes);
  const std::pair<std::string, const char*> cases[] = {
      {"stop: {scale_sizes: true}\n", "give the count"},
      {"stop: {particles: 300, scale_sizes: true, time: 5}\n", "drop 'stop.time'"},
      {"stop: {particles: 300, scale_sizes: true, volume_fraction: 0.3}\n", "drop 'stop.volume_fraction'"},
      {"stop: {particles: 300, scale_sizes: true}\ntarget: {solid_fraction: 0.4}\n", "'target' would change the count"},
      {"stop: {particles: 300, scale_sizes: true}\ndensify: {}\n", "the void filling"},
      {"stop: {particles: 300, scale_sizes: true}\npacker: {method: stacking}\n", "'packer.method' must be front"},
      {"stop: {particles: 300, scale_sizes: yes please}\n", ""},
  };
  for (const auto& [stop, why] : cases)
    expect_error(kBox3 + stop, 5, "stop.scale_sizes", {*why ? "fill the container; " : "", why});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\nparticles:\n"
               "  - {shape: ellipsoid, axes: [1, 0.8, 0.6], size: {distribution: constant, value: 0.05}}\n"
               "stop: {particles: 30, scale_sizes: true}\n",
               5, "stop.scale_sizes", {"spheres (disks) only"});
}

TEST(SceneYamlErrors, OutOfRangeOptions) {
  expect_error(kBox3 + "stop: {volume_fraction: 1.2}\n", 5, "stop.volume_fraction", {"(0, 1)"});
  expect_error(kBox3 + "packer:\n  contact_tolerance: 0.01\n", 6, "packer.contact_tolerance", {"(0, 1e-3)"});
  expect_error(kBox3 + "packer:\n  grid_cell_factor: 0.5\n", 6, "packer.grid_cell_factor", {">= 1"});
  expect_error(kBox3 + "packer:\n  hierarchical_grid_ratio: 1\n", 6, "packer.hierarchical_grid_ratio", {"> 1"});
  expect_error(kBox3 + "packer:\n  radius_pool: 0\n", 6, "packer.radius_pool", {"from 1"});
  expect_error(kBox3 + "packer:\n  seed_point: [2, 0.5, 0.5]\n", 6, "packer.seed_point", {"outside the container"});
  expect_error("dimension: 4\n" + kBox3.substr(13), 1, "dimension", {"2 or 3"});
}

TEST(SceneYamlErrors, ImpossibleContainersCarryTheConstructorMessage) {
  // A zero axis is caught here; a self-intersecting polygon by PolygonContainer.
  expect_error("dimension: 3\ncontainer: {type: cylinder, base: [0, 0, 0], axis: [0, 0, 0], radius: 1, height: 1}\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               2, "container.axis", {"non-zero"});
  expect_error("dimension: 2\ncontainer:\n  type: polygon\n  vertices: [[0, 0], [2, 2], [2, 0], [0, 1]]\n"
               "particles: {radius: {distribution: constant, value: 0.01}}\n",
               3, "container", {"self-intersect"});
  expect_error("dimension: 2\ncontainer:\n  type: polygon\n  vertices: [[0, 0], [1, 1]]\n"
               "particles: {radius: {distribution: constant, value: 0.01}}\n",
               4, "container.vertices", {"at least 3"});
  // A distribution whose constructor refuses the parameters.
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius:\n    distribution: gradation\n    curve: [[0.1, 10], [0.2, 100]]\n",
               5, "particles.radius", {"0"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius:\n    distribution: discrete\n    values: [[0.01, 0], [0.02, 0]]\n",
               5, "particles.radius", {"weight"});
  // Particles that cannot fit at all.
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 0.1]}\n"
               "particles:\n  radius: {distribution: uniform, min: 0.2, max: 0.3}\n",
               4, "particles.radius", {"does not fit"});
}

TEST(SceneYamlErrors, BadEnumValuesListTheAllowedOnes) {
  expect_error("dimension: 3\ncontainer: {type: cube, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               2, "container.type", {"'cube'", "box, sphere, cylinder, mesh"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles: {radius: {distribution: gaussian, mean: 1}}\n",
               3, "particles.radius.distribution", {"'gaussian'", "constant, uniform, normal, lognormal"});
  expect_error(kBox3 + "packer: {front: closets}\n", 5, "packer.front", {"did you mean 'closest'", "closest, random, fifo"});
  expect_error(kBox3 + "packer: {candidate: any}\n", 5, "packer.candidate", {"closest, first"});
  expect_error(kBox3 + "packer: {pair_order: random}\n", 5, "packer.pair_order", {"nearest, index"});
  expect_error(kBox3 + "packer: {contact_bodies: some}\n", 5, "packer.contact_bodies", {"front, all"});
  expect_error(kBox3 + "packer: {probe_smallest: sometimes}\n", 5, "packer.probe_smallest", {});
  // r_min fits, r_max fits nowhere (the strip is 0.05 thick): the distribution cannot be packed.
  expect_error("dimension: 2\ncontainer: {type: rectangle, min: [0, 0], max: [1, 0.05]}\n"
               "particles: {radius: {distribution: uniform, min: 0.005, max: 0.03}}\n",
               3, "particles.radius", {"the largest particles (radius up to 0.03) fit nowhere", "0.025 from the boundary"});
  expect_error(kBox3 + "packer: {method: mesh}\n", 5, "packer.method", {"front"});
  expect_error(kBox3 + "output:\n  - {format: vtk, path: a.vtk}\n", 6, "output[0].format", {"vtu, yade, lammps, csv, json"});
  expect_error(kBox3 + "output:\n  - {path: a.xyz}\n", 6, "output[0].path", {"extension", "format"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius: {distribution: gradation, basis: volume, curve: [[1, 0], [2, 100]]}\n",
               4, "particles.radius.basis", {"mass, count"});
}

TEST(SceneYamlErrors, DimensionContainerMismatch) {
  expect_error("dimension: 2\ncontainer:\n  type: box\n  min: [0, 0]\n  max: [1, 1]\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               3, "container.type", {"'box' is a 3D container", "rectangle, disk, polygon"});
  expect_error("dimension: 3\ncontainer:\n  type: disk\n  center: [0, 0, 0]\n  radius: 1\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               3, "container.type", {"'disk' is a 2D container", "box, sphere, cylinder, mesh"});
}

TEST(SceneYamlErrors, MissingRequiredKeys) {
  expect_error("seed: 3\n" + kBox3.substr(13), 1, "dimension", {"missing required key"});
  expect_error("dimension: 3\nparticles: {radius: {distribution: constant, value: 0.1}}\n", 1, "container", {"missing"});
  expect_error("dimension: 3\ncontainer:\n  min: [0, 0, 0]\n  max: [1, 1, 1]\nparticles: {radius: {distribution: constant, value: 0.1}}\n",
               3, "container.type", {"missing", "box, sphere, cylinder, mesh"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n", 1, "particles", {"missing"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\nparticles:\n  radius:\n    min: 1\n", 5,
               "particles.radius.distribution", {"missing"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0]}\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               2, "container.max", {"missing"});
  expect_error("dimension: 3\ncontainer: {type: cylinder, base: [0, 0, 0], radius: 1}\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               2, "container.height", {"missing"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius: {distribution: normal, mean: 0.1, std: 0.01}\n",
               4, "particles.radius.min", {"missing", "truncated"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius: {distribution: lognormal, sigma: 0.1, min: 0.01, max: 0.02}\n",
               4, "particles.radius.median", {"missing", "mu"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius: {distribution: lognormal, median: 0.015, mu: -4, sigma: 0.1, min: 0.01, max: 0.02}\n",
               4, "particles.radius.mu", {"not both"});
  expect_error(kBox3 + "output:\n  - {format: csv}\n", 6, "output[0].path", {"missing"});
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
               "particles:\n  radius:\n    distribution: histogram\n    edges: [1, 2, 3]\n    weights: [1]\n",
               7, "particles.radius.weights", {"one weight per bin", "2 for 3 edges"});
}

TEST(SceneYamlErrors, EmptyValueIsReportedAtItsKey) {
  expect_error("dimension: 3\ncontainer:\n  type: sphere\n  center: [0, 0, 0]\n  radius:\n"
               "particles: {radius: {distribution: constant, value: 0.1}}\n",
               5, "container.radius", {"got nothing"});
}

TEST(SceneYamlErrors, MissingMeshFileNamesTheResolvedPath) {
  test::TempDir dir;
  const std::string scene = dir.file("mesh.yaml");
  test::spit(scene, "dimension: 3\ncontainer:\n  type: mesh\n  file: parts/femur.stl\n"
                    "particles: {radius: {distribution: constant, value: 0.1}}\n");
  try {
    load_scene(scene);
    ADD_FAILURE();
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(scene + ":4:", 0), 0u) << what;
    EXPECT_EQ(e.key(), "container.file");
    EXPECT_NE(what.find((dir.path() / "parts" / "femur.stl").string()), std::string::npos) << what;
  }
}

TEST(SceneYamlErrors, BrokenMeshCarriesTheLoaderMessage) {
  test::TempDir dir;
  test::spit(dir.file("open.off"), "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  const std::string scene = dir.file("mesh.yaml");
  test::spit(scene, "dimension: 3\ncontainer:\n  type: mesh\n  file: open.off\n"
                    "particles: {radius: {distribution: constant, value: 0.1}}\n");
  try {
    load_scene(scene);
    ADD_FAILURE();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 3) << e.what();
    EXPECT_EQ(e.key(), "container");
    EXPECT_NE(std::string(e.what()).find("open.off"), std::string::npos) << e.what();
  }
}

TEST(SceneYamlErrors, MissingSceneFile) {
  try {
    load_scene("/nonexistent/scene.yaml");
    ADD_FAILURE();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.yaml"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cannot read"), std::string::npos);
  }
}

TEST(SceneYamlErrors, YamlSyntaxErrorHasFileAndLine) {
  expect_error("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]\nparticles: 3\n", 3, "", {"YAML syntax error"});
  expect_error("dimension: 3\n  seed: 2\n", 2, "", {"YAML syntax error"});
  expect_error("", 1, "", {"empty"});
  expect_error("- 1\n- 2\n", 1, "", {"expected a mapping"});
}

}  // namespace
}  // namespace fp
