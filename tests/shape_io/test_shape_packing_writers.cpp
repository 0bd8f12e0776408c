// Writers of shape packings (shapes/io/shape_packing_writers.hpp): every format in 2D and 3D,
// checked by re-reading the files (CSV/YADE/LAMMPS here, JSON with python's json module, VTU
// with VTK itself) against the particles' own geometry: exact end points and centres, unit
// quaternions, surfaces on the particles, atomic writes, refused formats.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/io/packing_readers.hpp"
#include "core/sampling/rng.hpp"
#include "shapes/io/shape_packing_writers.hpp"
#include "shapes/sphere_shape.hpp"
#include "shapes/spherocylinder_shape.hpp"
#include "tests/io/io_test_util.hpp"

namespace fp {
namespace {

using test::slurp;
using test::spit;
using test::TempDir;

// ---- a test-only cluster: a union of balls (the real ClusterShape lives in shapes/) --------

template <int D>
class TestCluster final : public Shape<D> {
 public:
  explicit TestCluster(std::vector<Ball<D>> balls) : balls_(std::move(balls)) {}
  const char* kind() const override { return "cluster"; }
  double measure() const override {
    double m = 0;
    for (const auto& b : balls_) m += ball_measure<D>(b.radius);  // overlaps ignored: test only
    return m;
  }
  double bounding_radius() const override {
    double r = 0;
    for (const auto& b : balls_) r = std::max(r, b.center.norm() + b.radius);
    return r;
  }
  double inscribed_radius() const override { return 0.0; }
  Vec<D> support(const Vec<D>& u) const override {
    Vec<D> best = balls_.front().center;
    double best_h = -1e300;
    const double n = u.norm();
    for (const auto& b : balls_) {
      const double h = b.center.dot(u) + b.radius * n;
      if (h > best_h) {
        best_h = h;
        best = n > 0 ? Vec<D>(b.center + u * (b.radius / n)) : b.center;
      }
    }
    return best;
  }
  bool contains(const Vec<D>& x) const override {
    return std::any_of(balls_.begin(), balls_.end(),
                       [&](const Ball<D>& b) { return (x - b.center).squaredNorm() <= b.radius * b.radius; });
  }
  std::vector<Ball<D>> hull_balls() const override { return balls_; }
  /// 2D: each member's circle as an open arc from t0 to t0 + 2 pi whose two end points are
  /// distinct vertices that coincide up to rounding (like ClusterShape's exposed arcs); 3D: every
  /// member's sphere.
  SurfaceMesh<D> surface(int resolution) const override {
    SurfaceMesh<D> m;
    if constexpr (D == 2) {
      for (const auto& b : balls_) {
        const int first = static_cast<int>(m.vertices.size());
        for (int k = 0; k <= resolution; ++k) {
          const double t = 0.3 + 2 * kPi * k / resolution;
          m.vertices.push_back(b.center + b.radius * Vec2(std::cos(t), std::sin(t)));
          if (k > 0) m.facets.push_back({first + k - 1, first + k});
        }
      }
      return m;
    }
    for (const auto& b : balls_) {
      const SurfaceMesh<D> s = SphereShape<D>(b.radius).surface(resolution);
      const int base = static_cast<int>(m.vertices.size());
      for (const auto& v : s.vertices) m.vertices.push_back(b.center + v);
      for (auto f : s.facets) {
        for (int& k : f) k += base;
        m.facets.push_back(f);
      }
    }
    return m;
  }
  std::vector<FclPart<D>> fcl_parts() const override { return {}; }
  ShapePtr<D> scaled(double s) const override {
    auto balls = balls_;
    for (auto& b : balls) {
      b.center *= s;
      b.radius *= s;
    }
    return std::make_shared<TestCluster<D>>(balls);
  }
  std::string definition_json() const override {
    std::ostringstream os;
    os.precision(17);
    os << R"({"kind": "cluster", "balls": [)";
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      os << (i ? ", [" : "[");
      for (int k = 0; k < D; ++k) os << balls_[i].center[k] << ", ";
      os << balls_[i].radius << "]";
    }
    os << "]}";
    return os.str();
  }

 private:
  std::vector<Ball<D>> balls_;
};

// ---- packings ----------------------------------------------------------------------------

template <int D>
Mat<D> random_rotation(Rng& rng) {
  if constexpr (D == 2) {
    return rotation_2d(rng.uniform(-kPi, kPi));
  } else {
    Eigen::Quaterniond q(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    return q.normalized().toRotationMatrix();
  }
}

template <int D>
Vec<D> random_point(Rng& rng, double scale) {
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = rng.uniform(-scale, scale);
  return x;
}

template <int D>
Particle<D> make_particle(ShapePtr<D> shape, Rng& rng, int template_id, double size) {
  Particle<D> p;
  p.shape = std::move(shape);
  p.pose.position = random_point<D>(rng, 10.0);
  p.pose.position[0] += 1e3 / 3.0;  // a large offset: many significant digits
  p.pose.rotation = random_rotation<D>(rng);
  p.template_id = template_id;
  p.size = size;
  return p;
}

template <int D>
ShapePtr<D> random_capsule(Rng& rng) {
  return std::make_shared<SpherocylinderShape<D>>(rng.uniform(0.05, 1.0), rng.uniform(0.01, 0.3));
}

template <int D>
ShapePtr<D> random_cluster(Rng& rng) {
  std::vector<Ball<D>> balls;
  const int n = 2 + static_cast<int>(rng.below(3));
  for (int i = 0; i < n; ++i) balls.push_back({random_point<D>(rng, 0.5), rng.uniform(0.1, 0.4)});
  return std::make_shared<TestCluster<D>>(balls);
}

template <int D>
ShapePacking<D> capsules(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  ShapePacking<D> p;
  p.template_names = {"spherocylinder", "spherocylinder"};
  for (std::size_t i = 0; i < n; ++i) {
    auto s = random_capsule<D>(rng);
    const double size = s->bounding_radius();
    p.particles.push_back(make_particle<D>(s, rng, static_cast<int>(i % 2), size));
  }
  return p;
}

/// Spheres (template 0) and clusters (template 1): every format can write them.
template <int D>
ShapePacking<D> balls_and_clusters(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  ShapePacking<D> p;
  p.template_names = {"sphere", "cluster"};
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 2 == 0) {
      const double r = rng.uniform(0.01, 1.0) / 3.0;
      p.particles.push_back(make_particle<D>(std::make_shared<SphereShape<D>>(r), rng, 0, r));
    } else {
      auto s = random_cluster<D>(rng);
      const double size = s->bounding_radius();
      p.particles.push_back(make_particle<D>(s, rng, 1, size));
    }
  }
  return p;
}

/// Spheres, clusters and capsules (templates 0, 1, 2), plus an unused template 3.
template <int D>
ShapePacking<D> mixed(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  ShapePacking<D> p;
  p.template_names = {"sphere", "cluster", "spherocylinder", "unused \"quoted\" template"};
  for (std::size_t i = 0; i < n; ++i) {
    const int t = static_cast<int>(i % 3);
    ShapePtr<D> s = t == 0 ? ShapePtr<D>(std::make_shared<SphereShape<D>>(rng.uniform(0.05, 0.5)))
                    : t == 1 ? random_cluster<D>(rng)
                             : random_capsule<D>(rng);
    const double size = s->bounding_radius();
    p.particles.push_back(make_particle<D>(s, rng, t, size));
  }
  return p;
}

RunRecord sample_record(int dimension) {
  RunRecord r;
  r.version = "0.1.0-test";
  r.scene_path = "scene.yaml";
  r.scene_text = "dimension: 3\nparticles:\n  - {shape: spherocylinder}\n";
  r.seed = 42;
  r.dimension = dimension;
  r.container_description = "box [0,1]^3";
  r.distribution_description = "uniform";
  r.density = 2500.0;
  r.metrics = {{"volume_fraction", 0.5}, {"undefined", std::nan("")}};
  return r;
}

// ---- parsing helpers -------------------------------------------------------------------

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  if (sep == ' ') {
    std::istringstream in(line);
    std::string w;
    while (in >> w) out.push_back(w);
    return out;
  }
  std::string cur;
  for (const char c : line) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

double num(const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  EXPECT_TRUE(end != s.c_str() && *end == '\0') << "not a number: '" << s << "'";
  return v;
}

long long integer(const std::string& s) {
  long long v = 0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  EXPECT_TRUE(res.ec == std::errc() && res.ptr == s.data() + s.size()) << "not an integer: '" << s << "'";
  return v;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

template <int D>
Vec3 embed(const Vec<D>& v) {
  if constexpr (D == 3) return v;
  else return Vec3(v[0], v[1], 0.0);
}

bool python_has(const char* module) {
  return std::system(("/usr/bin/python3 -c 'import " + std::string(module) + "' >/dev/null 2>&1").c_str()) == 0;
}

/// Runs a python script with arguments; returns its exit status (0 = fine).
int run_python(const TempDir& dir, const std::string& script, const std::vector<std::string>& args) {
  const std::string file = dir.file("script.py");
  spit(file, script);
  std::string cmd = "/usr/bin/python3 " + file;
  for (const auto& a : args) cmd += " '" + a + "'";
  return std::system(cmd.c_str());
}

const OutputFormat kAllFormats[] = {OutputFormat::Vtu, OutputFormat::Yade, OutputFormat::Lammps, OutputFormat::Csv,
                                    OutputFormat::Json};

std::string name_for(OutputFormat f, const std::string& stem) {
  switch (f) {
    case OutputFormat::Vtu: return stem + ".vtu";
    case OutputFormat::Yade: return stem + ".txt";
    case OutputFormat::Lammps: return stem + ".data";
    case OutputFormat::Csv: return stem + ".csv";
    case OutputFormat::Json: return stem + ".json";
  }
  return stem;
}

// ---- format support --------------------------------------------------------------------

TEST(ShapeIo, CheckShapeFormatAcceptsAndRefusesWithAClearMessage) {
  for (const OutputFormat f : {OutputFormat::Vtu, OutputFormat::Csv, OutputFormat::Json}) {
    EXPECT_NO_THROW(check_shape_format<3>(f, {"spherocylinder", "polyhedron", "sphere"}));
    EXPECT_NO_THROW(check_shape_format<2>(f, {"spherocylinder", "polygon"}));
  }
  for (const OutputFormat f : {OutputFormat::Yade, OutputFormat::Lammps}) {
    EXPECT_NO_THROW(check_shape_format<3>(f, {"sphere", "cluster"}));
    EXPECT_NO_THROW(check_shape_format<2>(f, {"cluster"}));
    EXPECT_NO_THROW(check_shape_format<3>(f, {}));
  }
  try {
    check_shape_format<3>(OutputFormat::Yade, {"sphere", "spherocylinder"});
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "format 'yade' writes spheres and clusters only; this scene has 'spherocylinder' particles; use vtu, "
              "csv or json");
  }
  try {
    check_shape_format<2>(OutputFormat::Lammps, {"spherocylinder", "polygon", "spherocylinder", "sphere"});
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("format 'lammps'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'spherocylinder' and 'polygon' particles"), std::string::npos) << e.what();
  }
}

TEST(ShapeIo, WritingAnUnsupportedFormatThrowsAndWritesNothing) {
  TempDir dir;
  const auto p3 = mixed<3>(6, 1);
  const auto p2 = capsules<2>(4, 2);
  for (const OutputFormat f : {OutputFormat::Yade, OutputFormat::Lammps}) {
    const std::string path = dir.file(name_for(f, "x"));
    try {
      write_packing<3>(f, path, p3, sample_record(3));
      ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("'spherocylinder'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(write_packing<2>(f, path, p2, sample_record(2)), std::invalid_argument);
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ShapeIo, CompanionFileNames) {
  EXPECT_EQ(surfaces_path("out/capsules.vtu"), "out/capsules.surfaces.vtu");
  EXPECT_EQ(surfaces_path("a.b.vtu"), "a.b.surfaces.vtu");
  EXPECT_EQ(surfaces_path("noext"), "noext.surfaces.vtu");
  EXPECT_EQ(multisphere_path("out/clumps.data"), "out/clumps.multisphere.txt");
  EXPECT_EQ(multisphere_path("x.lammps"), "x.multisphere.txt");
}

// ---- CSV -------------------------------------------------------------------------------

template <int D>
void check_capsule_csv() {
  TempDir dir;
  const auto p = capsules<D>(300, 10 + D);
  const std::string path = dir.file("c.csv");
  write_packing<D>(OutputFormat::Csv, path, p, sample_record(D));
  const auto lines = lines_of(slurp(path));
  ASSERT_EQ(lines.size(), p.size() + 1);
  EXPECT_EQ(lines[0], D == 3 ? "id,shape_id,ax,ay,az,bx,by,bz,r" : "id,shape_id,ax,ay,bx,by,r");
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto f = split(lines[i + 1], ',');
    ASSERT_EQ(f.size(), static_cast<std::size_t>(2 * D + 3)) << lines[i + 1];
    const auto& q = p.particles[i];
    const auto& s = static_cast<const SpherocylinderShape<D>&>(*q.shape);
    EXPECT_EQ(integer(f[0]), static_cast<long long>(i));
    EXPECT_EQ(integer(f[1]), q.template_id);
    Vec<D> a, b;
    for (int k = 0; k < D; ++k) {
      a[k] = num(f[2 + k]);
      b[k] = num(f[2 + D + k]);
    }
    // Exactly the world end points (shortest round-trip printing), ...
    const Vec<D> wa = q.pose.to_world(s.end_a()), wb = q.pose.to_world(s.end_b());
    for (int k = 0; k < D; ++k) {
      ASSERT_EQ(a[k], wa[k]) << "particle " << i;
      ASSERT_EQ(b[k], wb[k]) << "particle " << i;
    }
    EXPECT_EQ(num(f[2 * D + 2]), s.radius());
    // ... 2a apart, centred on the particle's position.
    EXPECT_NEAR((b - a).norm(), 2 * s.half_length(), 1e-12 * (q.pose.position.norm() + 1));
    EXPECT_LT((0.5 * (a + b) - q.pose.position).norm(), 1e-12 * (q.pose.position.norm() + 1));
  }
}

TEST(ShapeIo, CsvOfCapsulesGivesExactWorldSegments3D) { check_capsule_csv<3>(); }
TEST(ShapeIo, CsvOfStadiumsGivesExactWorldSegments2D) { check_capsule_csv<2>(); }

template <int D>
void check_generic_csv() {
  TempDir dir;
  const auto p = mixed<D>(60, 20 + D);
  const std::string path = dir.file("m.csv");
  write_packing<D>(OutputFormat::Csv, path, p, sample_record(D));
  const auto lines = lines_of(slurp(path));
  ASSERT_EQ(lines.size(), p.size() + 1);
  EXPECT_EQ(lines[0], D == 3 ? "id,shape_id,kind,x,y,z,qw,qx,qy,qz,size,bounding_radius"
                             : "id,shape_id,kind,x,y,qw,qx,qy,qz,size,bounding_radius");
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto f = split(lines[i + 1], ',');
    ASSERT_EQ(f.size(), static_cast<std::size_t>(D + 9)) << lines[i + 1];
    const auto& q = p.particles[i];
    EXPECT_EQ(integer(f[0]), static_cast<long long>(i));
    EXPECT_EQ(integer(f[1]), q.template_id);
    EXPECT_EQ(f[2], q.shape->kind());
    for (int k = 0; k < D; ++k) EXPECT_EQ(num(f[3 + k]), q.pose.position[k]);
    const Eigen::Vector4d w = quaternion_of<D>(q.pose.rotation);
    Eigen::Vector4d read;
    for (int k = 0; k < 4; ++k) read[k] = num(f[3 + D + k]);
    EXPECT_EQ(read, w);
    EXPECT_NEAR(read.norm(), 1.0, 1e-15);
    // The quaternion gives back the rotation.
    EXPECT_LT((rotation_of<D>(read) - q.pose.rotation).norm(), 1e-14);
    EXPECT_EQ(num(f[7 + D]), q.size);
    EXPECT_EQ(num(f[8 + D]), q.shape->bounding_radius());
  }
}

TEST(ShapeIo, CsvOfMixedShapesGivesPoseAndQuaternion3D) { check_generic_csv<3>(); }
TEST(ShapeIo, CsvOfMixedShapesGivesPoseAndQuaternion2D) { check_generic_csv<2>(); }

// ---- JSON ------------------------------------------------------------------------------

template <int D>
void check_json() {
  if (!python_has("json")) GTEST_SKIP() << "/usr/bin/python3 cannot import json";
  TempDir dir;
  const auto p = mixed<D>(30, 30 + D);
  const std::string path = dir.file("m.json");
  write_packing<D>(OutputFormat::Json, path, p, sample_record(D));
  const std::string result = dir.file("result.txt");
  ASSERT_EQ(run_python(dir,
                       "import json, sys\n"
                       "d = json.load(open(sys.argv[1]))\n"
                       "assert list(d.keys()) == ['frontpack', 'dimension', 'shapes', 'particles'], list(d.keys())\n"
                       "f = d['frontpack']\n"
                       "with open(sys.argv[2], 'w') as out:\n"
                       "    out.write('record %d %d %d %s %r\\n' % (f['n'], f['dimension'], f['seed'], "
                       "f['frontpack_version'], f['metrics']['undefined']))\n"
                       "    out.write('dimension %d\\n' % d['dimension'])\n"
                       "    for s in d['shapes']:\n"
                       "        dk = s['definition']['kind'] if s['definition'] else None\n"
                       "        out.write('shape %d %s %s %d %r %r %s\\n' % (s['shape_id'], json.dumps(s['name']).replace(' ', '_'), "
                       "s['kind'], s['count'], s['representative_id'], s['representative_size'], dk))\n"
                       "    for q in d['particles']:\n"
                       "        out.write('particle %d %d %s %s %r\\n' % (q['id'], q['shape_id'], "
                       "' '.join(repr(float(x)) for x in q['position']), "
                       "' '.join(repr(float(x)) for x in q['quaternion']), float(q['size'])))\n",
                       {path, result}),
            0)
      << slurp(path).substr(0, 2000);
  const auto lines = lines_of(slurp(result));
  const std::string json_text = slurp(path);
  ASSERT_EQ(lines.size(), 2 + p.template_names.size() + p.size());
  EXPECT_EQ(lines[0], "record " + std::to_string(p.size()) + " " + std::to_string(D) + " 42 0.1.0-test None");
  EXPECT_EQ(lines[1], "dimension " + std::to_string(D));
  for (std::size_t t = 0; t < p.template_names.size(); ++t) {
    const auto f = split(lines[2 + t], ' ');
    ASSERT_EQ(f.size(), 8u) << lines[2 + t];
    EXPECT_EQ(integer(f[1]), static_cast<long long>(t));
    std::size_t count = 0, first = p.size();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.particles[i].template_id == static_cast<int>(t)) {
        if (count++ == 0) first = i;
      }
    EXPECT_EQ(integer(f[4]), static_cast<long long>(count));
    if (count == 0) {
      EXPECT_EQ(f[2], "\"unused_\\\"quoted\\\"_template\"");  // the escaped name survives
      EXPECT_EQ(f[3], "None");
      EXPECT_EQ(f[7], "None");
    } else {
      EXPECT_EQ(f[3], p.particles[first].shape->kind());
      EXPECT_EQ(f[7], p.particles[first].shape->kind());  // the definition's own "kind"
      EXPECT_EQ(integer(f[5]), static_cast<long long>(first));
      EXPECT_EQ(num(f[6]), p.particles[first].size);
      // The definition's numbers are exact and printed in the shortest form like the rest.
      const auto* capsule = dynamic_cast<const SpherocylinderShape<D>*>(p.particles[first].shape.get());
      const auto* sphere = dynamic_cast<const SphereShape<D>*>(p.particles[first].shape.get());
      const double r = capsule ? capsule->radius() : sphere ? sphere->radius() : 0.0;
      if (r > 0) {
        char tmp[32];
        const std::string shortest(tmp, std::to_chars(tmp, tmp + sizeof tmp, r).ptr);
        const std::string key = "\"radius\": " + shortest;
        const std::size_t at = json_text.find(key);
        ASSERT_NE(at, std::string::npos) << key;
        EXPECT_TRUE(json_text[at + key.size()] == ',' || json_text[at + key.size()] == '}') << key;
      }
    }
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto f = split(lines[2 + p.template_names.size() + i], ' ');
    ASSERT_EQ(f.size(), 11u);
    const auto& q = p.particles[i];
    EXPECT_EQ(integer(f[1]), static_cast<long long>(i));
    EXPECT_EQ(integer(f[2]), q.template_id);
    const Vec3 x = embed<D>(q.pose.position);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(num(f[3 + k]), x[k]);  // 2D: z = 0
    Eigen::Vector4d w;
    for (int k = 0; k < 4; ++k) w[k] = num(f[6 + k]);
    EXPECT_EQ(w, quaternion_of<D>(q.pose.rotation));
    EXPECT_NEAR(w.norm(), 1.0, 1e-15);
    EXPECT_EQ(num(f[10]), q.size);
  }
}

TEST(ShapeIo, JsonParsesWithPythonAndIsExact3D) { check_json<3>(); }
TEST(ShapeIo, JsonParsesWithPythonAndIsExact2D) { check_json<2>(); }

TEST(ShapeIo, EmptyPackingWritesValidFiles) {
  TempDir dir;
  ShapePacking<3> empty;
  for (const OutputFormat f : kAllFormats) write_packing<3>(f, dir.file(name_for(f, "e")), empty, RunRecord{});
  EXPECT_EQ(slurp(dir.file("e.csv")), "id,shape_id,kind,x,y,z,qw,qx,qy,qz,size,bounding_radius\n");
  if (python_has("json")) {
    EXPECT_EQ(run_python(dir,
                         "import json, sys\nd = json.load(open(sys.argv[1]))\n"
                         "assert d['particles'] == [] and d['shapes'] == [] and d['frontpack']['n'] == 0\n",
                         {dir.file("e.json")}),
              0);
  }
  EXPECT_EQ(read_packing<3>(OutputFormat::Lammps, dir.file("e.data")).size(), 0u);
}

// ---- VTU, read back by VTK ---------------------------------------------------------------

/// Distance from a world point to the surface of particle q (0 on the surface), computed from the
/// shape's definition: spheres, capsules and clusters.
template <int D>
double distance_to_surface(const Particle<D>& q, const Vec3& world) {
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = world[k];
  const Vec<D> b = q.pose.to_body(x);
  if (const auto* s = dynamic_cast<const SpherocylinderShape<D>*>(q.shape.get())) {
    Vec<D> d = b;
    d[0] -= std::clamp(b[0], -s->half_length(), s->half_length());
    return std::abs(d.norm() - s->radius());
  }
  double best = 1e300;  // sphere or cluster: on the outline of one of its balls
  for (const auto& ball : q.shape->hull_balls()) best = std::min(best, std::abs((b - ball.center).norm() - ball.radius));
  return best;
}

template <int D>
void check_vtu() {
  if (!python_has("vtk")) GTEST_SKIP() << "/usr/bin/python3 cannot import vtk (install python3-vtk9)";
  TempDir dir;
  const auto p = mixed<D>(12, 40 + D);
  const std::string path = dir.file("m.vtu");
  write_packing<D>(OutputFormat::Vtu, path, p, sample_record(D));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"m.surfaces.vtu", "m.vtu"}));
  const std::string result = dir.file("result.txt");
  ASSERT_EQ(run_python(dir,
                       "import sys, vtk\n"
                       "def read(name):\n"
                       "    r = vtk.vtkXMLUnstructuredGridReader()\n"
                       "    r.SetFileName(name)\n"
                       "    r.Update()\n"
                       "    return r.GetOutput()\n"
                       "g = read(sys.argv[1])\n"
                       "s = read(sys.argv[2])\n"
                       "out = open(sys.argv[3], 'w')\n"
                       "pd = g.GetPointData()\n"
                       "out.write('main %d %d %d\\n' % (g.GetNumberOfPoints(), g.GetNumberOfCells(), "
                       "len(set(g.GetCellType(i) for i in range(g.GetNumberOfCells())) - {1})))\n"
                       "for k in range(pd.GetNumberOfArrays()):\n"
                       "    a = pd.GetArray(k)\n"
                       "    out.write('array %s %d %d\\n' % (a.GetName(), a.GetNumberOfComponents(), a.GetNumberOfTuples()))\n"
                       "names = ['id', 'shape_id', 'size', 'bounding_radius', 'measure', 'quaternion', 'axis_x', 'axis_y', "
                       "'axis_z']\n"
                       "for i in range(g.GetNumberOfPoints()):\n"
                       "    vals = list(g.GetPoint(i))\n"
                       "    for n in names:\n"
                       "        vals += list(pd.GetArray(n).GetTuple(i))\n"
                       "    out.write('point ' + ' '.join(repr(v) for v in vals) + '\\n')\n"
                       "cd = s.GetCellData()\n"
                       "out.write('surf %d %d %d %d\\n' % (s.GetNumberOfPoints(), s.GetNumberOfCells(), "
                       "cd.GetArray('id').GetNumberOfTuples(), cd.GetArray('shape_id').GetNumberOfTuples()))\n"
                       "types = {}\n"
                       "for c in range(s.GetNumberOfCells()):\n"
                       "    t = s.GetCellType(c)\n"
                       "    types[t] = types.get(t, 0) + 1\n"
                       "    cell = s.GetCell(c)\n"
                       "    pid = int(cd.GetArray('id').GetValue(c))\n"
                       "    out.write('cell %d %d %d %d\\n' % (pid, int(cd.GetArray('shape_id').GetValue(c)), t, "
                       "cell.GetNumberOfPoints()))\n"
                       "    for j in range(cell.GetNumberOfPoints()):\n"
                       "        x = s.GetPoint(cell.GetPointId(j))\n"
                       "        out.write('p %r %r %r\\n' % x)\n"
                       "out.write('types ' + ' '.join('%d:%d' % kv for kv in sorted(types.items())) + '\\n')\n",
                       {path, surfaces_path(path), result}),
            0);
  const auto lines = lines_of(slurp(result));
  ASSERT_FALSE(lines.empty());
  std::size_t li = 0;
  auto next = [&]() -> std::vector<std::string> {
    EXPECT_LT(li, lines.size());
    return li < lines.size() ? split(lines[li++], ' ') : std::vector<std::string>{};
  };
  const std::size_t n = p.size();
  auto f = next();
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(integer(f[1]), static_cast<long long>(n));
  EXPECT_EQ(integer(f[2]), static_cast<long long>(n));
  EXPECT_EQ(integer(f[3]), 0);  // every cell a VTK_VERTEX
  const std::map<std::string, int> components = {{"id", 1},      {"shape_id", 1}, {"size", 1},
                                                 {"bounding_radius", 1}, {"measure", 1}, {"quaternion", 4},
                                                 {"axis_x", 3},  {"axis_y", 3},   {"axis_z", 3}};
  std::map<std::string, int> seen;
  while (li < lines.size() && lines[li].rfind("array ", 0) == 0) {
    f = next();
    seen[f[1]] = static_cast<int>(integer(f[2]));
    EXPECT_EQ(integer(f[3]), static_cast<long long>(n)) << f[1];
  }
  EXPECT_EQ(seen, components);
  for (std::size_t i = 0; i < n; ++i) {
    f = next();
    ASSERT_EQ(f.size(), 1u + 3 + 5 + 4 + 9);
    std::vector<double> v;
    for (std::size_t k = 1; k < f.size(); ++k) v.push_back(num(f[k]));
    const auto& q = p.particles[i];
    const Vec3 x = embed<D>(q.pose.position);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(v[k], x[k]);
    EXPECT_EQ(v[3], static_cast<double>(i));
    EXPECT_EQ(v[4], q.template_id);
    EXPECT_EQ(v[5], q.size);
    EXPECT_EQ(v[6], q.shape->bounding_radius());
    EXPECT_EQ(v[7], q.shape->measure());
    const Eigen::Vector4d w(v[8], v[9], v[10], v[11]);
    EXPECT_EQ(w, quaternion_of<D>(q.pose.rotation));
    EXPECT_NEAR(w.norm(), 1.0, 1e-15);
    for (int a = 0; a < 3; ++a) {
      const Vec3 axis(v[12 + 3 * a], v[13 + 3 * a], v[14 + 3 * a]);
      Vec3 expected = Vec3::UnitZ();
      if (a < D) expected = embed<D>(Vec<D>(q.pose.rotation.col(a)));
      EXPECT_EQ(axis, expected) << "axis " << a;
    }
  }
  // Surfaces: one point per surface vertex; triangles (3D) or one polygon per outline loop (2D).
  std::size_t points = 0, cells = 0;
  for (const auto& q : p.particles) {
    const auto m = q.shape->surface(kShapeSurfaceResolution<D>);
    points += m.vertices.size();
    if constexpr (D == 3) cells += m.facets.size();
    else cells += std::string(q.shape->kind()) == "cluster" ? q.shape->hull_balls().size() : 1;
  }
  f = next();
  ASSERT_EQ(f.size(), 5u);
  EXPECT_EQ(integer(f[1]), static_cast<long long>(points));
  EXPECT_EQ(integer(f[2]), static_cast<long long>(cells));
  EXPECT_EQ(integer(f[3]), static_cast<long long>(cells));
  EXPECT_EQ(integer(f[4]), static_cast<long long>(cells));
  std::vector<std::size_t> cells_of(n, 0);
  double worst_surface = 0, worst_bound = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    f = next();
    ASSERT_EQ(f.size(), 5u);
    ASSERT_EQ(f[0], "cell");
    const auto id = static_cast<std::size_t>(integer(f[1]));
    ASSERT_LT(id, n);
    const auto& q = p.particles[id];
    ++cells_of[id];
    EXPECT_EQ(integer(f[2]), q.template_id);
    EXPECT_EQ(integer(f[3]), D == 3 ? 5 : 7);  // VTK_TRIANGLE / VTK_POLYGON
    const long long k = integer(f[4]);
    if (D == 3) {
      EXPECT_EQ(k, 3);
    } else {
      EXPECT_GE(k, kShapeSurfaceResolution<D>);  // a whole outline (or a cluster member's)
    }
    for (long long j = 0; j < k; ++j) {
      f = next();
      ASSERT_EQ(f.size(), 4u);
      const Vec3 x(num(f[1]), num(f[2]), num(f[3]));
      if (D == 2) {
        EXPECT_EQ(x.z(), 0.0);
      }
      const double rb = q.shape->bounding_radius();
      worst_bound = std::max(worst_bound, (x - embed<D>(q.pose.position)).norm() / rb);
      worst_surface = std::max(worst_surface, distance_to_surface(q, x) / rb);
    }
  }
  EXPECT_LE(worst_bound, 1.0 + 1e-12);  // every surface point within the bounding radius
  EXPECT_GT(worst_bound, 0.99);         // and the far ends reach it
  EXPECT_LT(worst_surface, 1e-12);      // on the particle's own surface: the pose is applied
  for (std::size_t i = 0; i < n; ++i) EXPECT_GT(cells_of[i], 0u) << "particle " << i << " has no surface";
  f = next();
  ASSERT_FALSE(f.empty());
  EXPECT_EQ(lines[li - 1], "types " + std::to_string(D == 3 ? 5 : 7) + ":" + std::to_string(cells));
}

TEST(ShapeIo, VtuAndSurfacesOpenInVtk3D) { check_vtu<3>(); }
TEST(ShapeIo, VtuAndSurfacesOpenInVtk2D) { check_vtu<2>(); }

// ---- YADE and LAMMPS clumps ------------------------------------------------------------

template <int D>
void check_yade() {
  TempDir dir;
  const auto p = balls_and_clusters<D>(40, 50 + D);
  const std::string path = dir.file("c.txt");
  write_packing<D>(OutputFormat::Yade, path, p, sample_record(D));
  const auto lines = lines_of(slurp(path));
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines[0], "#format x_y_z_r_clumpId");
  EXPECT_EQ(lines[1].rfind("# ", 0), 0u);
  std::size_t li = 2;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& q = p.particles[i];
    for (const auto& ball : q.shape->hull_balls()) {
      ASSERT_LT(li, lines.size());
      const auto f = split(lines[li++], ' ');
      ASSERT_EQ(f.size(), 5u);
      const Vec3 c = embed<D>(q.pose.to_world(ball.center));
      for (int k = 0; k < 3; ++k) EXPECT_EQ(num(f[k]), c[k]);
      EXPECT_EQ(num(f[3]), ball.radius);
      EXPECT_EQ(integer(f[4]), static_cast<long long>(i));
    }
  }
  EXPECT_EQ(li, lines.size());  // no blank line: ymport.textClumps would choke on one
}

TEST(ShapeIo, YadeClumpsListEveryMemberBall3D) { check_yade<3>(); }
TEST(ShapeIo, YadeClumpsListEveryMemberBall2D) { check_yade<2>(); }

template <int D>
void check_lammps() {
  TempDir dir;
  const auto p = balls_and_clusters<D>(40, 60 + D);
  const std::string path = dir.file("c.data");
  write_packing<D>(OutputFormat::Lammps, path, p, sample_record(D));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"c.data", "c.multisphere.txt"}));

  // The data file: the member balls, exactly, readable by frontpack's own LAMMPS reader.
  const Packing<D> atoms = read_packing<D>(OutputFormat::Lammps, path);
  std::size_t members = 0;
  for (const auto& q : p.particles) members += q.shape->hull_balls().size();
  ASSERT_EQ(atoms.size(), members);
  const std::string text = slurp(path);
  EXPECT_NE(text.find("\n" + std::to_string(members) + " atoms\n"), std::string::npos);
  EXPECT_NE(text.find("\n2 atom types\n"), std::string::npos);
  EXPECT_NE(text.find("c.multisphere.txt"), std::string::npos);
  EXPECT_NE(text.find("\nAtoms # hybrid\n"), std::string::npos);
  std::vector<int> types;
  std::vector<long long> molecules;
  bool in_atoms = false;
  for (const auto& line : lines_of(text)) {
    if (line.rfind("Atoms", 0) == 0) in_atoms = true;
    else if (in_atoms && !line.empty()) {
      const auto f = split(line, ' ');  // id type x y z diameter density molecule
      ASSERT_EQ(f.size(), 8u);
      types.push_back(static_cast<int>(integer(f[1])));
      EXPECT_EQ(num(f[6]), 2500.0);
      molecules.push_back(integer(f[7]));
    }
  }
  ASSERT_EQ(types.size(), members);

  // The multisphere listing: clump pose and members in the body frame.
  const auto lines = lines_of(slurp(multisphere_path(path)));
  std::size_t li = 0;
  while (li < lines.size() && lines[li].rfind("#", 0) == 0) ++li;
  EXPECT_GE(li, 3u);  // the layout is explained
  std::size_t atom = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& q = p.particles[i];
    const auto balls = q.shape->hull_balls();
    ASSERT_LT(li, lines.size());
    auto f = split(lines[li++], ' ');
    ASSERT_EQ(f.size(), 10u) << lines[li - 1];
    EXPECT_EQ(integer(f[0]), static_cast<long long>(i));
    ASSERT_EQ(integer(f[1]), static_cast<long long>(balls.size()));
    EXPECT_EQ(integer(f[2]), q.template_id);
    const Vec3 x(num(f[3]), num(f[4]), num(f[5]));
    EXPECT_EQ(x, embed<D>(q.pose.position));
    const Eigen::Vector4d w(num(f[6]), num(f[7]), num(f[8]), num(f[9]));
    EXPECT_EQ(w, quaternion_of<D>(q.pose.rotation));
    const Eigen::Matrix3d R = Eigen::Quaterniond(w[0], w[1], w[2], w[3]).toRotationMatrix();
    for (const auto& ball : balls) {
      ASSERT_LT(li, lines.size());
      f = split(lines[li++], ' ');
      ASSERT_EQ(f.size(), 4u);
      const Vec3 body(num(f[0]), num(f[1]), num(f[2]));
      EXPECT_EQ(body, embed<D>(ball.center));
      EXPECT_EQ(num(f[3]), ball.radius);
      // The atom of this member: exact world centre, and the listing's pose reproduces it.
      const Vec<D> world = q.pose.to_world(ball.center);
      for (int k = 0; k < D; ++k) EXPECT_EQ(atoms.centers[atom][k], world[k]);
      EXPECT_EQ(atoms.radii[atom], ball.radius);
      EXPECT_EQ(types[atom], q.template_id + 1);
      EXPECT_EQ(molecules[atom], static_cast<long long>(i) + 1) << "molecule = clump id + 1";
      EXPECT_LT((x + R * body - embed<D>(world)).norm(), 1e-12 * (x.norm() + 1));
      ++atom;
    }
  }
  EXPECT_EQ(li, lines.size());
  EXPECT_EQ(atom, members);
}

TEST(ShapeIo, LammpsDataAndMultisphereListing3D) { check_lammps<3>(); }
TEST(ShapeIo, LammpsDataAndMultisphereListing2D) { check_lammps<2>(); }

// ---- every format, determinism, atomicity ---------------------------------------------------

template <int D>
void write_all(const TempDir& dir, const std::string& stem, std::uint64_t seed) {
  for (const OutputFormat f : kAllFormats)
    write_packing<D>(f, dir.file(name_for(f, stem)), balls_and_clusters<D>(25, seed), sample_record(D));
}

TEST(ShapeIo, EveryFormatIsWrittenInBothDimensionsAndIsDeterministic) {
  TempDir a, b;
  write_all<3>(a, "p3", 7);
  write_all<2>(a, "p2", 8);
  write_all<3>(b, "p3", 7);
  write_all<2>(b, "p2", 8);
  const std::vector<std::string> expected = {"p2.csv",  "p2.data", "p2.json", "p2.multisphere.txt", "p2.surfaces.vtu",
                                             "p2.txt",  "p2.vtu",  "p3.csv",  "p3.data",            "p3.json",
                                             "p3.multisphere.txt", "p3.surfaces.vtu", "p3.txt", "p3.vtu"};
  ASSERT_EQ(a.entries(), expected);  // no temporary left behind
  for (const auto& name : expected) {
    const std::string bytes = slurp(a.file(name));
    EXPECT_FALSE(bytes.empty()) << name;
    EXPECT_EQ(bytes, slurp(b.file(name))) << name;
  }
}

TEST(ShapeIo, MissingFolderThrowsNamingThePathAndLeavesNothing) {
  TempDir dir;
  const auto p = balls_and_clusters<3>(6, 3);
  for (const OutputFormat f : kAllFormats) {
    const std::string path = dir.file("missing/" + name_for(f, "x"));
    try {
      write_packing<3>(f, path, p, sample_record(3));
      ADD_FAILURE() << "no error for " << path;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("'" + path + "'"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ShapeIo, AFailingCompanionLeavesNoFileAndKeepsTheOldOne) {
  TempDir dir;
  const auto p = balls_and_clusters<3>(6, 4);
  for (const OutputFormat f : {OutputFormat::Vtu, OutputFormat::Lammps}) {
    SCOPED_TRACE(output_format_name(f));
    const std::string path = dir.file(name_for(f, "x"));
    const std::string companion = f == OutputFormat::Vtu ? surfaces_path(path) : multisphere_path(path);
    // A folder where the companion should go: the main file must not appear either.
    std::filesystem::create_directory(companion);
    try {
      write_packing<3>(f, path, p, sample_record(3));
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("'" + path + "'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(companion), std::string::npos) << e.what();
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{std::filesystem::path(companion).filename().string()});
    // An existing pair is kept as it was when the next write fails.
    std::filesystem::remove(companion);
    write_packing<3>(f, path, p, sample_record(3));
    const std::string before = slurp(path);
    std::filesystem::remove(companion);
    std::filesystem::create_directory(companion);
    EXPECT_THROW(write_packing<3>(f, path, balls_and_clusters<3>(9, 5), sample_record(3)), std::runtime_error);
    EXPECT_EQ(slurp(path), before);
    EXPECT_EQ(dir.entries().size(), 2u);  // the old main file and the folder: no temporaries
    std::filesystem::remove_all(dir.path());
    std::filesystem::create_directories(dir.path());
  }
}

TEST(ShapeIo, ReadOnlyFolderThrowsAndLeavesNothing) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
  TempDir dir;
  const std::string ro = dir.file("ro");
  std::filesystem::create_directory(ro);
  ::chmod(ro.c_str(), 0555);
  const auto p = capsules<2>(5, 6);
  for (const OutputFormat f : {OutputFormat::Vtu, OutputFormat::Csv, OutputFormat::Json}) {
    const std::string path = ro + "/" + name_for(f, "x");
    try {
      write_packing<2>(f, path, p, sample_record(2));
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(std::filesystem::is_empty(ro));
  ::chmod(ro.c_str(), 0755);
}

}  // namespace
}  // namespace fp
