// `frontpack pack SCENE --seed N --format F -o FILE` for every format: the file parses, holds
// the same particles as the CSV of the same seed (exactly: numbers round-trip), and the same
// seed gives the same bytes while another seed gives other bytes.
#include <gtest/gtest.h>

#include "cli_test_util.hpp"

namespace fptest {
namespace {

const char* kScene3D = R"(dimension: 3
seed: 1
container: {type: cylinder, base: [0, 0, 0], axis: [0, 0, 1], radius: 0.1, height: 0.15}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";
const char* kScene2D = R"(dimension: 2
seed: 1
container: {type: polygon, vertices: [[0, 0], [0.4, 0], [0.4, 0.2], [0.2, 0.2], [0.2, 0.4], [0, 0.4]]}
particles: {radius: {distribution: uniform, min: 0.01, max: 0.02}}
)";

struct Particle {
  double x, y, z, r;
};

/// Runs pack with --format and -o in dir; returns the file's bytes (asserting exit 0).
std::string pack_to(const TempDir& dir, const std::string& format, const std::string& file, unsigned seed) {
  const RunResult r = run_frontpack(dir, "pack scene.yaml -q --seed " + std::to_string(seed) + " --format " + format + " -o " + file);
  EXPECT_EQ(r.exit_code, 0) << format << ": " << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(fs::exists(dir.work() / file)) << file;
  return read_bytes(dir.work() / file);
}

std::vector<Particle> parse_csv(const std::string& text, int dimension) {
  std::vector<Particle> ps;
  const auto lines = lines_of(text);
  EXPECT_FALSE(lines.empty());
  if (lines.empty()) return ps;
  EXPECT_EQ(lines[0], dimension == 3 ? "id,x,y,z,r" : "id,x,y,r");
  std::vector<double> v;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    EXPECT_TRUE(parse_numbers(lines[i], ',', v)) << lines[i];
    EXPECT_EQ(v.size(), static_cast<std::size_t>(dimension + 2)) << lines[i];
    if (v.size() != static_cast<std::size_t>(dimension + 2)) continue;
    EXPECT_EQ(v[0], static_cast<double>(i - 1)) << "0-based ids in order";
    ps.push_back(dimension == 3 ? Particle{v[1], v[2], v[3], v[4]} : Particle{v[1], v[2], 0.0, v[3]});
  }
  return ps;
}

void expect_same(const std::vector<Particle>& a, const std::vector<Particle>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x, b[i].x) << what << " particle " << i;
    EXPECT_EQ(a[i].y, b[i].y) << what << " particle " << i;
    EXPECT_EQ(a[i].z, b[i].z) << what << " particle " << i;
    EXPECT_EQ(a[i].r, b[i].r) << what << " particle " << i;
  }
}

std::vector<Particle> parse_yade(const std::string& text) {
  std::vector<Particle> ps;
  const auto lines = lines_of(text);
  EXPECT_FALSE(lines.empty());
  if (lines.empty()) return ps;
  EXPECT_EQ(lines[0], "#format x_y_z_r");
  std::vector<double> v;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    EXPECT_TRUE(parse_numbers(lines[i], ' ', v)) << lines[i];
    EXPECT_EQ(v.size(), 4u) << "line " << i + 1 << ": " << lines[i];
    if (v.size() == 4) ps.push_back({v[0], v[1], v[2], v[3]});
  }
  return ps;
}

/// LAMMPS data file, atom_style sphere: "N atoms", box lines, "Atoms # sphere", then
/// "id type diameter density x y z" with 1-based ids.
std::vector<Particle> parse_lammps(const std::string& text) {
  std::vector<Particle> ps;
  const auto lines = lines_of(text);
  std::size_t declared = 0, atoms_at = 0;
  int box_lines = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {  // line 1 is a free comment
    const std::string& l = lines[i];
    if (l.find(" atoms") != std::string::npos && l.find("types") == std::string::npos) declared = std::stoul(l);
    if (l.find("xlo xhi") != std::string::npos || l.find("ylo yhi") != std::string::npos ||
        l.find("zlo zhi") != std::string::npos) {
      std::vector<double> v;
      EXPECT_TRUE(parse_numbers(l.substr(0, l.find_first_of("xyz")), ' ', v)) << l;
      EXPECT_EQ(v.size(), 2u) << l;
      if (v.size() == 2) EXPECT_LT(v[0], v[1]) << l;
      ++box_lines;
    }
    if (l.rfind("Atoms", 0) == 0) {
      EXPECT_NE(l.find("sphere"), std::string::npos) << l;
      atoms_at = i;
      break;
    }
  }
  EXPECT_EQ(box_lines, 3);
  EXPECT_GT(atoms_at, 0u) << "no Atoms section";
  std::vector<double> v;
  for (std::size_t i = atoms_at + 1; i < lines.size(); ++i) {
    if (lines[i].empty()) {
      if (ps.empty()) continue;  // the blank line after the header
      break;
    }
    EXPECT_TRUE(parse_numbers(lines[i], ' ', v)) << lines[i];
    EXPECT_EQ(v.size(), 7u) << lines[i];
    if (v.size() != 7) continue;
    EXPECT_EQ(v[0], static_cast<double>(ps.size() + 1)) << "1-based ids in order";
    EXPECT_EQ(v[1], 1.0) << "atom type";
    EXPECT_GT(v[3], 0.0) << "density";
    ps.push_back({v[4], v[5], v[6], v[2] / 2});  // diameter / 2 is exact
  }
  EXPECT_EQ(ps.size(), declared);
  return ps;
}

// The CSV of the same seed, read back in Python, is the reference for VTU and JSON.
const std::string kPyReadCsv = R"(
import sys, csv
rows = list(csv.reader(open(sys.argv[2])))
head, rows = rows[0], rows[1:]
ref = [[float(v) for v in row[1:]] for row in rows]
d = len(head) - 2
)";

class CliFormats : public ::testing::TestWithParam<int> {};

TEST_P(CliFormats, EveryFormatParsesAndMatchesTheCsv) {
  const int dimension = GetParam();
  TempDir dir;
  write_bytes(dir.work() / "scene.yaml", dimension == 3 ? kScene3D : kScene2D);
  const auto csv = parse_csv(pack_to(dir, "csv", "ref.csv", 7), dimension);
  ASSERT_GE(csv.size(), 20u);

  expect_same(parse_yade(pack_to(dir, "yade", "out.yade", 7)), csv, "yade");
  expect_same(parse_lammps(pack_to(dir, "lammps", "out.lammps", 7)), csv, "lammps");

  pack_to(dir, "vtu", "out.vtu", 7);
  EXPECT_EQ(python_check(kPyReadCsv + R"(
import vtk
r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update()
g = r.GetOutput()
assert g.GetNumberOfPoints() == len(ref), (g.GetNumberOfPoints(), len(ref))
assert g.GetNumberOfCells() == len(ref)
rad = g.GetPointData().GetArray('radius')
for i, p in enumerate(ref):
    x = g.GetPoint(i)
    got = list(x[:d]) + [rad.GetValue(i)]
    assert got == p, (i, got, p)
    assert d == 3 or x[2] == 0.0
)", {dir.work() / "out.vtu", dir.work() / "ref.csv"}), 0);

  pack_to(dir, "json", "out.json", 7);
  EXPECT_EQ(python_check(kPyReadCsv + R"(
import json
j = json.load(open(sys.argv[1]))
assert j['seed'] == 7 and j['dimension'] == d and j['n'] == len(ref), (j['seed'], j['n'])
P = j['particles']
cols = ['x', 'y', 'z'][:d] + ['r']
for i, p in enumerate(ref):
    got = [P[c][i] for c in cols]
    assert got == p, (i, got, p)
)", {dir.work() / "out.json", dir.work() / "ref.csv"}), 0);
}

INSTANTIATE_TEST_SUITE_P(Dimensions, CliFormats, ::testing::Values(3, 2),
                         [](const auto& info) { return std::to_string(info.param) + "D"; });

TEST(CliFormats, FormatFromTheExtension) {
  TempDir dir;
  write_bytes(dir.work() / "scene.yaml", kScene3D);
  for (const char* f : {"out.txt", "out.data", "out.csv", "out.vtu", "out.json"}) {
    const RunResult r = run_frontpack(dir, std::string("pack scene.yaml -q -o ") + f);
    EXPECT_EQ(r.exit_code, 0) << f << ": " << r.err;
  }
  EXPECT_EQ(read_bytes(dir.work() / "out.txt").rfind("#format x_y_z_r\n", 0), 0u);
  EXPECT_NE(read_bytes(dir.work() / "out.data").find("Atoms # sphere"), std::string::npos);
  EXPECT_EQ(read_bytes(dir.work() / "out.vtu").rfind("<?xml", 0), 0u);
}

/// `material: {density}` is the density column of the LAMMPS data file and the record's
/// density (default 2650, quartz in SI units); a bad one is refused, naming the key.
TEST(CliFormats, TheLammpsDensityIsTheScenesMaterial) {
  TempDir dir;
  write_bytes(dir.work() / "plain.yaml", kScene3D);
  write_bytes(dir.work() / "steel.yaml", std::string(kScene3D) + "material: {density: 7850}\n");
  for (const auto& [name, density] : {std::pair<std::string, double>{"plain", 2650.0}, {"steel", 7850.0}}) {
    SCOPED_TRACE(name);
    const RunResult r = run_frontpack(dir, "pack " + name + ".yaml -q -o " + name + ".data --record " + name + ".json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto lines = lines_of(read_bytes(dir.work() / (name + ".data")));
    int atoms = 0;
    bool in_atoms = false;
    for (const std::string& l : lines) {
      if (l.rfind("Atoms", 0) == 0) in_atoms = true;
      std::vector<double> v;
      if (!in_atoms || l.empty() || !parse_numbers(l, ' ', v) || v.size() != 7) continue;
      EXPECT_EQ(v[3], density) << l;
      ++atoms;
    }
    EXPECT_GT(atoms, 100);
    EXPECT_EQ(record_number(read_bytes(dir.work() / (name + ".json")), "density"), density);
  }
  expect_refused(dir, std::string(kScene3D) + "material: {density: 0}\n", "material.density");
  expect_refused(dir, std::string(kScene3D) + "material: {density: -1}\n", "must be a positive number");
  expect_refused(dir, std::string(kScene3D) + "material: {density: .nan}\n", "material.density");
  expect_refused(dir, std::string(kScene3D) + "material: {rho: 2}\n", "material.rho");
  expect_refused(dir, std::string(kScene3D) + "material: {}\n", "material.density");
}

TEST(CliFormats, SameSeedSameBytesOtherSeedOtherBytes) {
  TempDir dir;
  write_bytes(dir.work() / "scene.yaml", kScene3D);
  for (const char* f : {"yade", "csv", "vtu", "lammps"}) {
    SCOPED_TRACE(f);
    const std::string a = pack_to(dir, f, std::string("a.") + f, 11);
    const std::string b = pack_to(dir, f, std::string("b.") + f, 11);
    const std::string c = pack_to(dir, f, std::string("c.") + f, 12);
    EXPECT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "two runs with seed 11 differ";
    EXPECT_FALSE(a == c) << "seeds 11 and 12 give the same file";
  }
  // Without --seed the scene's seed (1) is used: the same bytes as --seed 1.
  ASSERT_EQ(run_frontpack(dir, "pack scene.yaml -q -o scene_seed.csv").exit_code, 0);
  EXPECT_EQ(read_bytes(dir.work() / "scene_seed.csv"), pack_to(dir, "csv", "seed1.csv", 1));
}

TEST(CliFormats, ExistingOutputIsReplacedWhole) {
  // A longer old file must not leave a tail behind the new content.
  TempDir dir;
  write_bytes(dir.work() / "scene.yaml", kScene3D);
  const std::string fresh = pack_to(dir, "csv", "fresh.csv", 3);
  write_bytes(dir.work() / "old.csv", std::string(fresh.size() * 3, 'x'));
  EXPECT_EQ(pack_to(dir, "csv", "old.csv", 3), fresh);
  EXPECT_EQ(listing(dir.work()), (std::set<std::string>{"scene.yaml", "fresh.csv", "old.csv"})) << "temporary left behind";
}

}  // namespace
}  // namespace fptest
