// `frontpack pack` with non-spherical particles (scene `particles: [{shape: ...}]`): small
// capsule scenes in 2D and 3D written to a temp folder, every output format that applies
// (vtu + its surfaces companion, csv, json), the run record, refusals (a format that cannot hold
// capsules, an unknown family, a bad parameter) and reproducibility.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <utility>
#include <vector>

#include "cli_test_util.hpp"

namespace fptest {
namespace {

/// A capsule scene (aspect ratio 0.5: radius = half the circumscribed radius, half-length = the
/// other half) with a tiny stop and the three formats that can hold capsules.
std::string capsule_scene(int dimension, int particles) {
  const std::string container = dimension == 2 ? "container: {type: rectangle, min: [0, 0], max: [6, 6]}\n"
                                               : "container: {type: box, min: [0, 0, 0], max: [4, 4, 4]}\n";
  return "dimension: " + std::to_string(dimension) + "\nseed: 5\n" + container +
         "particles:\n"
         "  - shape: spherocylinder\n"
         "    aspect_ratio: 0.5\n"
         "    size: {distribution: uniform, min: 0.4, max: 0.6}\n"
         "stop: {particles: " + std::to_string(particles) + "}\n"
         "output:\n"
         "  - {format: vtu, path: out/caps.vtu}\n"
         "  - {format: csv, path: out/caps.csv}\n"
         "  - {format: json, path: out/caps.json}\n";
}

int python(const std::string& code, const fs::path& arg) {
  return std::system(("/usr/bin/python3 -c " + quoted(code) + " " + quoted(arg.string())).c_str());
}

class CliShapes : public ::testing::TestWithParam<int> {};

TEST_P(CliShapes, CapsulesEveryFormat) {
  const int D = GetParam();
  const int n = D == 2 ? 25 : 15;
  TempDir dir;
  write_bytes(dir.work() / "caps.yaml", capsule_scene(D, n));
  fs::create_directories(dir.work() / "out");
  const RunResult r = run_frontpack(dir, "pack caps.yaml --record out/rec.json");
  // The count stop leaves the box unfilled: incomplete (exit 4), said once, every file written.
  ASSERT_EQ(r.exit_code, kIncomplete) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("frontpack: error: the packing is valid but incomplete: stop.particles (" + std::to_string(n) +
                        ") ended the packing before it filled the container", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  // The summary names the side file with its size, and the dimension each size law is drawn on.
  EXPECT_NE(r.out.find("side file      out/caps.surfaces.vtu (of out/caps.vtu, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" on the circumscribed radius"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("validation     ok"), std::string::npos) << r.out;
  EXPECT_EQ(listing(dir.work() / "out"), (std::set<std::string>{"caps.vtu", "caps.surfaces.vtu", "caps.container.vtu", "caps.csv", "caps.json", "rec.json"}));

  // CSV: the capsule layout, end points 2a apart (a = half-length = r for aspect ratio 0.5).
  const std::vector<std::string> lines = lines_of(read_bytes(dir.work() / "out/caps.csv"));
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(n) + 1);
  EXPECT_EQ(lines[0], D == 3 ? "id,shape_id,ax,ay,az,bx,by,bz,r" : "id,shape_id,ax,ay,bx,by,r");
  for (int i = 1; i <= n; ++i) {
    std::vector<double> v;
    ASSERT_TRUE(parse_numbers(lines[static_cast<std::size_t>(i)], ',', v)) << lines[static_cast<std::size_t>(i)];
    ASSERT_EQ(v.size(), static_cast<std::size_t>(2 * D + 3));
    EXPECT_EQ(v[0], i - 1);
    EXPECT_EQ(v[1], 0);
    double len2 = 0;
    for (int k = 0; k < D; ++k) len2 += (v[2 + D + k] - v[2 + k]) * (v[2 + D + k] - v[2 + k]);
    const double radius = v[2 + 2 * D];
    EXPECT_GE(radius, 0.5 * 0.4 * (1 - 1e-12));  // circumscribed radius U[0.4, 0.6], radius = half of it
    EXPECT_LE(radius, 0.5 * 0.6 * (1 + 1e-12));
    EXPECT_NEAR(std::sqrt(len2), 2 * radius, 1e-9 * radius) << lines[static_cast<std::size_t>(i)];
  }

  // JSON: parses, names the shapes, one entry per particle.
  EXPECT_EQ(python("import json,sys; d=json.load(open(sys.argv[1])); "
                   "assert 'shapes' in d and d['shapes'][0]['kind'] == 'spherocylinder', d.get('shapes'); "
                   "assert len(d['particles']) == " + std::to_string(n) + "; assert d['dimension'] == " + std::to_string(D),
                   dir.work() / "out/caps.json"),
            0);
  // VTU and its surfaces companion.
  for (const char* f : {"out/caps.vtu", "out/caps.surfaces.vtu"}) {
    const std::string text = read_bytes(dir.work() / f);
    EXPECT_NE(text.find("<VTKFile"), std::string::npos) << f;
    EXPECT_NE(text.find("UnstructuredGrid"), std::string::npos) << f;
  }
  // The run record: the shape counters. Capsules are placed without minimisation: by the polygon
  // wrapper in 2D (closed form), by the gap Newton solver in 3D.
  const std::string solvers = "assert c['minimisations'] == 0 and c['analytic_solves'] == c['solves'], c; ";
  EXPECT_EQ(python("import json,sys; d=json.load(open(sys.argv[1])); c=d['counters']; "
                   "assert 'fcl_queries' in c and 'minimisations' in c, c; " + solvers +
                   "assert c['solves'] > 0, c; assert d['n'] == " + std::to_string(n),
                   dir.work() / "out/rec.json"),
            0);
}

TEST_P(CliShapes, SameSeedSameCsv) {
  const int D = GetParam();
  TempDir dir;
  write_bytes(dir.work() / "caps.yaml", capsule_scene(D, D == 2 ? 20 : 10));
  ASSERT_EQ(run_frontpack(dir, "pack caps.yaml -q -o a.csv").exit_code, kIncomplete);  // the count stop
  ASSERT_EQ(run_frontpack(dir, "pack caps.yaml -q -o b.csv").exit_code, kIncomplete);
  ASSERT_EQ(run_frontpack(dir, "pack caps.yaml -q -o c.csv --seed 6").exit_code, kIncomplete);
  const std::string a = read_bytes(dir.work() / "a.csv");
  EXPECT_GT(lines_of(a).size(), 5u);
  EXPECT_EQ(a, read_bytes(dir.work() / "b.csv"));
  EXPECT_NE(a, read_bytes(dir.work() / "c.csv"));
  // elongation 2 is aspect_ratio 0.5, its older inverse: the same packing.
  std::string elongated = capsule_scene(D, D == 2 ? 20 : 10);
  elongated.replace(elongated.find("aspect_ratio: 0.5"), 17, "elongation: 2");
  write_bytes(dir.work() / "long.yaml", elongated);
  ASSERT_EQ(run_frontpack(dir, "pack long.yaml -q -o d.csv").exit_code, kIncomplete);
  EXPECT_EQ(a, read_bytes(dir.work() / "d.csv"));
}

// The surfaces side file: fine (the default), coarse (half the segments per turn), none; the
// particles' own vtu the same bytes whatever its side file; the coarse one read by VTK.
TEST_P(CliShapes, SurfacesFineCoarseOrNone) {
  const int D = GetParam();
  TempDir dir;
  write_bytes(dir.work() / "caps.yaml", capsule_scene(D, 40));
  for (const char* detail : {"fine", "coarse", "none"}) {
    fs::create_directories(dir.work() / detail);
    const std::string out = std::string(detail) + "/c.vtu";
    const RunResult r = run_frontpack(dir, "pack caps.yaml -o " + out + " --surfaces " + detail);
    ASSERT_EQ(r.exit_code, kIncomplete) << r.out << r.err;
    EXPECT_EQ(r.out.find(std::string(detail) + "/c.surfaces.vtu") != std::string::npos, std::string(detail) != "none") << r.out;
  }
  const std::string fine = read_bytes(dir.work() / "fine/c.surfaces.vtu"), coarse = read_bytes(dir.work() / "coarse/c.surfaces.vtu");
  EXPECT_LT(coarse.size(), fine.size() * (D == 3 ? 0.4 : 0.6));
  EXPECT_FALSE(fs::exists(dir.work() / "none/c.surfaces.vtu"));
  EXPECT_EQ(read_bytes(dir.work() / "none/c.vtu"), read_bytes(dir.work() / "fine/c.vtu"));
  EXPECT_EQ(read_bytes(dir.work() / "coarse/c.vtu"), read_bytes(dir.work() / "fine/c.vtu"));
  EXPECT_EQ(python("import sys, vtk\n"
                   "r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update()\n"
                   "g = r.GetOutput(); ids = {int(g.GetCellData().GetArray('id').GetValue(c)) for c in range(g.GetNumberOfCells())}\n"
                   "assert ids == set(range(40)), sorted(ids)[:5]",
                   dir.work() / "coarse/c.surfaces.vtu"),
            0);
  // In the scene's output list too; refused where there is no surfaces file.
  std::string listed = capsule_scene(D, 40);
  listed.replace(listed.find("{format: vtu, path: out/caps.vtu}"), 33, "{format: vtu, path: out/caps.vtu, surfaces: none}");
  write_bytes(dir.work() / "listed.yaml", listed);
  fs::create_directories(dir.work() / "out");
  ASSERT_EQ(run_frontpack(dir, "pack listed.yaml -q").exit_code, kIncomplete);
  EXPECT_TRUE(fs::exists(dir.work() / "out/caps.vtu"));
  EXPECT_FALSE(fs::exists(dir.work() / "out/caps.surfaces.vtu"));
  std::string on_csv = capsule_scene(D, 40);
  on_csv.replace(on_csv.find("{format: csv, path: out/caps.csv}"), 33, "{format: csv, path: out/caps.csv, surfaces: coarse}");
  expect_refused(dir, on_csv, "beside a vtu output only");
  const RunResult spheres = run_frontpack(dir, "pack " + quoted(source_path("scenes/demo.yaml")) + " -o s.vtu --surfaces coarse");
  EXPECT_EQ(spheres.exit_code, 2);
  EXPECT_NE(spheres.err.find("spheres have no surfaces side file"), std::string::npos) << spheres.err;
  EXPECT_NE(run_frontpack(dir, "pack caps.yaml -o x.vtu --surfaces rough").exit_code, 0);
}

TEST_P(CliShapes, YadeCannotHoldCapsules) {
  const int D = GetParam();
  TempDir dir;
  write_bytes(dir.work() / "caps.yaml", capsule_scene(D, 5));
  const auto before = listing(dir.work());
  for (const std::string args : {"pack caps.yaml -o caps.txt --format yade", "pack caps.yaml -o caps.yade"}) {
    const RunResult r = run_frontpack(dir, args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find("yade"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("spherocylinder"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(listing(dir.work()), before) << "nothing may be written";
  }
  // In the scene's own output list too: the other outputs are not written either.
  write_bytes(dir.work() / "caps2.yaml", capsule_scene(D, 5) + "  - {format: yade, path: caps.txt}\n");
  fs::create_directories(dir.work() / "out");
  const auto before2 = listing(dir.work());
  const RunResult r = run_frontpack(dir, "pack caps2.yaml");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("yade"), std::string::npos) << r.err;
  EXPECT_EQ(listing(dir.work()), before2);
}

// The general front keeps F by distance to the seed point only: another `front` is refused
// before any work rather than silently ignored.
// One front for every shape: the levers of the sphere front mean the same for shapes. Each one
// here gives a valid packing of the requested count (validated by `pack`), different from the
// default one (the lever reached the packer).
TEST_P(CliShapes, EveryFrontLeverAppliesToShapes) {
  const int D = GetParam();
  const int n = D == 2 ? 25 : 15;
  TempDir dir;
  fs::create_directories(dir.work() / "out");
  auto pack = [&](const std::string& name, const std::string& packer) {
    write_bytes(dir.work() / (name + ".yaml"), capsule_scene(D, n) + packer);
    const RunResult r = run_frontpack(dir, "pack " + name + ".yaml -o out/" + name + ".csv");
    EXPECT_EQ(r.exit_code, kIncomplete) << name << ": " << r.out << r.err;  // the count stop
    EXPECT_NE(r.out.find("validation     ok"), std::string::npos) << name << ": " << r.out;
    const std::string csv = read_bytes(dir.work() / ("out/" + name + ".csv"));
    EXPECT_EQ(lines_of(csv).size(), static_cast<std::size_t>(n) + 1) << name;
    return csv;
  };
  const std::string base = pack("default", "");
  for (const auto& [name, packer] : std::vector<std::pair<std::string, std::string>>{
           {"random", "packer: {front: random}\n"},
           {"fifo", "packer: {front: fifo}\n"},
           {"first", "packer: {candidate: first, pair_order: index}\n"},
           {"probe", "packer: {probe_smallest: true, radius_pool: 6}\n"},
           {"pool1", "packer: {radius_pool: 1}\n"}})
    EXPECT_NE(pack(name, packer), base) << name;
}

// packer.contact_solver: minimisation places every particle by minimisation (no closed-form
// solve), auto uses the wrappers (2D capsules: every solve); both packings validate, and the
// wrappers' contacts are exact to rounding where the minimisation's stop at its tolerance.
TEST(CliShapesSolver, ContactSolverChoice) {
  const std::string cases[][2] = {{"auto", "assert c['minimisations'] == 0 and c['analytic_solves'] == c['solves'] > 0, c; "
                                           "assert d['metrics']['max_contact_gap_over_smaller_radius'] < 1e-12, d['metrics']"},
                                  {"minimisation", "assert c['analytic_solves'] == 0 and c['minimisations'] > 0, c; "
                                                   "assert d['metrics']['max_contact_gap_over_smaller_radius'] < 1e-6, d['metrics']"}};
  for (const auto& [solver, check] : cases) {
    TempDir dir;
    fs::create_directories(dir.work() / "out");
    write_bytes(dir.work() / "caps.yaml", capsule_scene(2, 15) + "packer: {contact_solver: " + solver + "}\n");
    const RunResult r = run_frontpack(dir, "pack caps.yaml -o out/caps.csv --record out/rec.json");
    ASSERT_EQ(r.exit_code, kIncomplete) << solver << ": " << r.err;  // the count stop
    EXPECT_NE(r.out.find("validation     ok"), std::string::npos) << r.out;
    EXPECT_EQ(python("import json,sys; d=json.load(open(sys.argv[1])); c=d['counters']; " + check +
                         "; assert d['info']['contact_solver'] == '" + solver + "'",
                     dir.work() / "out/rec.json"),
              0)
        << solver;
  }
}

TEST(CliShapesSolver, ContactSolverIsForParticleTemplatesOnly) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml",
              "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
              "particles: {radius: {distribution: uniform, min: 0.1, max: 0.2}}\npacker: {contact_solver: minimisation}\n");
  const RunResult r = run_frontpack(dir, "pack s.yaml -o out.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("key 'packer.contact_solver'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("particle templates only"), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(Dimensions, CliShapes, ::testing::Values(2, 3),
                         [](const auto& info) { return std::to_string(info.param) + "D"; });

/// The scene is refused with exit 2, the message naming bad.yaml:line: and the key, nothing written.
void expect_shape_refused(const std::string& text, int line, const std::string& key, const std::string& also = "") {
  TempDir dir;
  write_bytes(dir.work() / "bad.yaml", text);
  const auto before = listing(dir.work());
  const RunResult r = run_frontpack(dir, "pack bad.yaml -o out.csv");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("bad.yaml:" + std::to_string(line) + ":"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("key '" + key + "'"), std::string::npos) << r.err;
  if (!also.empty()) {
    EXPECT_NE(r.err.find(also), std::string::npos) << r.err;
  }
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(listing(dir.work()), before);
}

const std::string kShapeHead = "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [4, 4, 4]}\nparticles:\n";  // lines 1-3

TEST(CliShapesRefused, UnknownFamily) {
  expect_shape_refused(kShapeHead + "  - shape: capsul\n    size: {distribution: uniform, min: 0.4, max: 0.6}\n", 4,
                       "particles[0].shape", "capsul");
}

TEST(CliShapesRefused, BadAspectRatio) {
  for (const std::string bad : {"1.5", "0", "-0.2", "wide"}) {
    SCOPED_TRACE(bad);
    expect_shape_refused(kShapeHead + "  - shape: spherocylinder\n    size: {distribution: uniform, min: 0.4, max: 0.6}\n"
                                      "    aspect_ratio: " + bad + "\n",
                         6, "particles[0].aspect_ratio", "aspect_ratio");
  }
}

TEST(CliShapesRefused, FamilyMissingInTwoD) {
  expect_shape_refused("dimension: 2\ncontainer: {type: rectangle, min: [0, 0], max: [4, 4]}\nparticles:\n"
                       "  - shape: cylinder\n    aspect_ratio: 1\n    size: {distribution: uniform, min: 0.4, max: 0.6}\n",
                       4, "particles[0].shape", "cylinder");
}

// `fraction: {volume: ...}`: spheres of radii 0.1 and 0.2 half the solid each, so 8 small ones
// for a large one by number; the packing validates (its mix test against those number shares)
// and its solid is shared half and half within sampling.
TEST(CliShapesFractions, ByVolumeTheSolidIsSharedAsAsked) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", "dimension: 3\nseed: 2\ncontainer: {type: box, min: [0, 0, 0], max: [3, 3, 3]}\nparticles:\n"
                                     "  - {shape: sphere, size: {distribution: constant, value: 0.1}, fraction: {volume: 1}}\n"
                                     "  - {shape: sphere, size: {distribution: constant, value: 0.2}, fraction: {mass: 1}}\n");
  const RunResult r = run_frontpack(dir, "pack s.yaml -o p.csv");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::vector<std::string> rows = lines_of(read_bytes(dir.work() / "p.csv"));
  double small = 0, large = 0, n_small = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double size = std::stod(rows[i].substr(rows[i].rfind(',', rows[i].rfind(',') - 1) + 1));
    (size < 0.15 ? small : large) += size * size * size;
    n_small += size < 0.15;
  }
  const double n = static_cast<double>(rows.size() - 1), p = 8.0 / 9.0;
  EXPECT_GT(n, 1500);
  EXPECT_NEAR(n_small / n, p, 4 * std::sqrt(p * (1 - p) / n)) << n_small << " of " << n;
  // The solid's share v = (n - m) / (n + 7 m), m ~ Binomial(n, 1/9) large ones: sd 0.7955 / sqrt(n).
  EXPECT_NEAR(small / (small + large), 0.5, 4 * 0.7955 / std::sqrt(n));
}

}  // namespace
}  // namespace fptest
