// container.bed: a container filled from its floor up to a height. Judged from the written file,
// apart from frontpack's own figures: no particle above the level, the independent validation
// against the scene file, a bulk (the slabs 2 r_max from floor and level, by each sphere's exact
// sections) as dense as the container packed to the same height without a bed, a surface where
// the profile falls to half the bulk within a particle diameter of the level, a flat top (every
// column's highest particle within a diameter of the level), the same bytes for the same seed,
// and the same results for the scene scaled by 2^40 and shifted by 1e9.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "cli_test_util.hpp"

namespace fptest {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string number(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

struct Ball {
  std::vector<double> c;
  double r;
};

std::vector<Ball> read_csv(const fs::path& p, int dimension) {
  std::vector<Ball> balls;
  const auto lines = lines_of(read_bytes(p));
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty() || lines[i][0] == '#') continue;
    std::vector<double> v;
    EXPECT_TRUE(parse_numbers(lines[i], ',', v)) << lines[i];
    if (v.size() != static_cast<std::size_t>(dimension + 2)) continue;  // id, centre, r
    balls.push_back({std::vector<double>(v.begin() + 1, v.begin() + 1 + dimension), v.back()});
  }
  return balls;
}

/// The measure of a ball's part below height t over its centre (2D: a disk's).
double below(int dimension, double r, double t) {
  t = std::clamp(t, -r, r);
  if (dimension == 3) return kPi * (r * r * (t + r) - (t * t * t + r * r * r) / 3);
  return r * r * (std::asin(t / r) + kPi / 2) + t * std::sqrt(r * r - t * t);
}

/// A bed whose cross-section is the same at every height (a vertical cylinder or a rectangle),
/// of area `section`, filled to `height` over the floor at 0 along the last axis.
struct Profile {
  std::vector<double> vf;  // slabs of `width` from the floor
  double width = 0, bulk = 0, half_bulk_height = 0;
};

Profile profile_of(const std::vector<Ball>& balls, int dimension, double section, double height, double r_max, double unit,
                   double offset) {
  Profile p;
  const int slabs = static_cast<int>(std::ceil(height / (0.5 * r_max)));
  p.width = height / slabs;
  std::vector<double> solid(static_cast<std::size_t>(slabs), 0.0);
  for (const Ball& b : balls) {
    const double h = (b.c[static_cast<std::size_t>(dimension - 1)] - offset) / unit, r = b.r / unit;
    for (int k = 0; k < slabs; ++k)
      solid[static_cast<std::size_t>(k)] += below(dimension, r, (k + 1) * p.width - h) - below(dimension, r, k * p.width - h);
  }
  double bulk_solid = 0, bulk_measure = 0;
  for (int k = 0; k < slabs; ++k) {
    p.vf.push_back(solid[static_cast<std::size_t>(k)] / (section * p.width));
    if (k * p.width >= 2 * r_max - 1e-12 && (k + 1) * p.width <= height - 2 * r_max + 1e-12)
      bulk_solid += solid[static_cast<std::size_t>(k)], bulk_measure += section * p.width;
  }
  p.bulk = bulk_solid / bulk_measure;
  for (int k = slabs - 1; k >= 0; --k)
    if (p.vf[static_cast<std::size_t>(k)] >= 0.5 * p.bulk) {
      p.half_bulk_height = (k + 1) * p.width;  // the top of the first slab past half, read down
      break;
    }
  return p;
}

struct Case {
  const char* name;
  int dimension;
  std::string container;  // kL: k length units, O: the offset; the bed is appended
  std::string bed;        // the bed's keys
  double section;         // the cross-section's area, in L
  double height;          // the fill height, in L
  double half_width;      // the columns lie within this of the axis (cylinder) or the sides (rectangle)
  double r_min, r_max;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::string scene_of(const Case& c, double unit, double offset, bool with_bed) {
  std::string container = c.container;
  // kL: k lengths (k: digits, or none for one).
  for (std::size_t at; (at = container.find('L')) != std::string::npos;) {
    std::size_t from = at;
    while (from > 0 && std::isdigit(static_cast<unsigned char>(container[from - 1]))) --from;
    const double k = from < at ? std::stod(container.substr(from, at - from)) : 1.0;
    container.replace(from, at + 1 - from, number(k * unit));
  }
  for (std::size_t at; (at = container.find('O')) != std::string::npos;) container.replace(at, 1, number(offset));
  container += with_bed ? ", bed: {height: " + number(c.height * unit) + c.bed + "}}" : "}";
  return "dimension: " + std::to_string(c.dimension) + "\nseed: 5\ncontainer: " + container +
         "\nparticles: {radius: {distribution: uniform, min: " + number(c.r_min * unit) + ", max: " + number(c.r_max * unit) +
         "}}\n";
}

const Case kCases[] = {
    {"cylinder_free", 3, "{type: cylinder, base: [O, O, O], radius: L, height: 3L", "", kPi, 1.2, 1.0, 0.04, 0.06},
    {"cylinder_flat", 3, "{type: cylinder, base: [O, O, O], radius: L, height: 3L", ", surface: flat", kPi, 1.2, 1.0, 0.04, 0.06},
    {"rectangle_free", 2, "{type: rectangle, min: [O, O], max: [4L, 5L]", ", up: [0, 1]", 4.0, 2.0, 2.0, 0.02, 0.04},
};

/// The same container cut at the fill height by its own wall: what the bed's bulk is held to.
std::string plain_of(const Case& c) {
  Case plain = c;
  const std::string tall = c.dimension == 3 ? "height: 3L" : "5L]";
  plain.container.replace(plain.container.find(tall), tall.size(),
                          c.dimension == 3 ? "height: " + number(c.height) : number(c.height) + "]");
  return scene_of(plain, 1.0, 0.0, false);
}

class CliBed : public ::testing::TestWithParam<Case> {};

TEST_P(CliBed, FillsToItsLevelAsDenseAsTheBulkWithAFlatTop) {
  const Case& c = GetParam();
  const int d = c.dimension;
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", scene_of(c, 1.0, 0.0, true));
  const RunResult r = run_frontpack(dir, "pack s.yaml -o p.csv");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("filled to height " + number(c.height)), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bed profile"), std::string::npos) << r.out;
  EXPECT_EQ(run_frontpack(dir, "validate p.csv --scene s.yaml -q").exit_code, 0);

  const std::vector<Ball> balls = read_csv(dir.work() / "p.csv", d);
  ASSERT_GT(balls.size(), 1000u);
  // No particle reaches above the level.
  for (const Ball& b : balls) ASSERT_LE(b.c[static_cast<std::size_t>(d - 1)] + b.r, c.height * (1 + 1e-12));

  // The bulk against the container cut at the same height by a wall of its own.
  write_bytes(dir.work() / "plain.yaml", plain_of(c));
  ASSERT_EQ(run_frontpack(dir, "pack plain.yaml -q -o plain.csv").exit_code, 0);
  const Profile bed = profile_of(balls, d, c.section, c.height, c.r_max, 1.0, 0.0);
  const Profile plain = profile_of(read_csv(dir.work() / "plain.csv", d), d, c.section, c.height, c.r_max, 1.0, 0.0);
  EXPECT_NEAR(bed.bulk, plain.bulk, 0.015);
  // A flat surface across a cylinder's axis is the cylinder's own top: the same packing, byte for byte.
  if (c.bed.find("flat") != std::string::npos)
    EXPECT_EQ(read_bytes(dir.work() / "p.csv"), read_bytes(dir.work() / "plain.csv"));
  EXPECT_GT(bed.bulk, d == 3 ? 0.56 : 0.78);
  // The surface: half the bulk is reached within a diameter of the level.
  EXPECT_GE(bed.half_bulk_height, c.height - 2 * c.r_max);

  // A flat top: columns of 4 r_max wholly inside the cross-section each hold a particle whose
  // top lies within a diameter of the level.
  const double column = 4 * c.r_max;
  std::map<std::vector<long long>, double> tops;
  for (const Ball& b : balls) {
    std::vector<long long> key;
    for (int a = 0; a + 1 < d; ++a) key.push_back(static_cast<long long>(std::floor(b.c[static_cast<std::size_t>(a)] / column)));
    double& top = tops[key];
    top = std::max(top, b.c[static_cast<std::size_t>(d - 1)] + b.r);
  }
  int columns = 0;
  for (const auto& [key, top] : tops) {
    double far = 0;  // the column's farthest point from the axis (3D) or from the rectangle's middle
    for (std::size_t a = 0; a < key.size(); ++a) {
      const double lo = key[a] * column, hi = lo + column;
      const double mid = d == 3 ? 0.0 : c.half_width;
      far = d == 3 ? std::hypot(far, std::max(std::abs(lo - mid), std::abs(hi - mid))) : std::max(std::abs(lo - mid), std::abs(hi - mid));
    }
    if (far > c.half_width) continue;
    ++columns;
    EXPECT_GE(top, c.height - 2 * c.r_max) << "column at " << key[0] * column;
  }
  EXPECT_GE(columns, d == 3 ? 30 : 10);

  // The same seed, the same bytes.
  ASSERT_EQ(run_frontpack(dir, "pack s.yaml -q -o again.csv").exit_code, 0);
  EXPECT_EQ(read_bytes(dir.work() / "again.csv"), read_bytes(dir.work() / "p.csv"));

  // Scaled by 2^40 and shifted by 1e9: as many particles, valid, at the level, as dense.
  const double unit = 0x1p40, offset = 1e9;
  write_bytes(dir.work() / "far.yaml", scene_of(c, unit, offset, true));
  ASSERT_EQ(run_frontpack(dir, "pack far.yaml -q -o far.csv").exit_code, 0);
  EXPECT_EQ(run_frontpack(dir, "validate far.csv --scene far.yaml -q").exit_code, 0);
  const std::vector<Ball> far = read_csv(dir.work() / "far.csv", d);
  EXPECT_NEAR(static_cast<double>(far.size()), static_cast<double>(balls.size()), 0.01 * static_cast<double>(balls.size()));
  for (const Ball& b : far) ASSERT_LE((b.c[static_cast<std::size_t>(d - 1)] - offset + b.r) / unit, c.height * (1 + 1e-9));
  EXPECT_NEAR(profile_of(far, d, c.section, c.height, c.r_max, unit, offset).bulk, bed.bulk, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Beds, CliBed, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// Beds along other directions: a horizontal drum filled 0.8 up from its lowest line, a ball along
// a diagonal, a disk from its top down; and cubes in a box. Valid against the scene, and filled
// up to the level and no higher (the level worked out by hand).
TEST(CliBedDirections, DrumBowlAndShapesStayBelowTheirLevel) {
  struct Other {
    const char* scene;
    std::vector<double> up;
    double level;  // up . x at the level, by hand
  };
  const double s3 = 1 / std::sqrt(3.0);
  const Other others[] = {
      {"dimension: 3\ncontainer: {type: cylinder, base: [0, 0, 0], axis: [1, 0, 0], radius: 1, height: 1, bed: {height: 0.8}}\n"
       "particles: {radius: {distribution: uniform, min: 0.04, max: 0.06}}\n",
       {0, 0, 1}, -1 + 0.8},
      {"dimension: 3\ncontainer: {type: sphere, center: [1, 1, 1], radius: 1, bed: {height: 0.7, up: [1, 1, 1]}}\n"
       "particles: {radius: {distribution: uniform, min: 0.04, max: 0.06}}\n",
       {s3, s3, s3}, 3 * s3 - 1 + 0.7},
      {"dimension: 2\ncontainer: {type: disk, center: [0, 0], radius: 1, bed: {height: 0.5, up: [0, -1], surface: flat}}\n"
       "particles: {radius: {distribution: uniform, min: 0.02, max: 0.03}}\n",
       {0, -1}, -1 + 0.5},
  };
  for (const Other& o : others) {
    TempDir dir;
    write_bytes(dir.work() / "s.yaml", o.scene);
    const RunResult r = run_frontpack(dir, "pack s.yaml -o p.csv");
    ASSERT_EQ(r.exit_code, 0) << o.scene << r.out << r.err;
    EXPECT_EQ(run_frontpack(dir, "validate p.csv --scene s.yaml -q").exit_code, 0) << o.scene;
    const int d = static_cast<int>(o.up.size());
    const std::vector<Ball> balls = read_csv(dir.work() / "p.csv", d);
    ASSERT_GT(balls.size(), 200u) << o.scene;
    double highest = -1e300;
    for (const Ball& b : balls) {
      double h = b.r;
      for (int a = 0; a < d; ++a) h += o.up[static_cast<std::size_t>(a)] * b.c[static_cast<std::size_t>(a)];
      highest = std::max(highest, h);
    }
    EXPECT_LE(highest, o.level + 1e-9) << o.scene;
    EXPECT_GE(highest, o.level - 0.02) << o.scene;  // and it is filled up to it
  }
  // Cubes in a box bed: validated (their containment is tested against the cut box).
  TempDir dir;
  write_bytes(dir.work() / "s.yaml",
              "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [2, 2, 4], bed: {height: 1.2}}\n"
              "particles: [{shape: polyhedron, preset: cube, size: {distribution: uniform, min: 0.15, max: 0.2}}]\n");
  const RunResult r = run_frontpack(dir, "pack s.yaml -o p.json");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("bed bulk / top"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bed surface          highest tops over"), std::string::npos) << r.out;  // by the support function
  EXPECT_EQ(run_frontpack(dir, "validate p.json --scene s.yaml -q").exit_code, 0);
}

// The container beside a VTU output: the walls below the level, open above it (3D), or the
// outline closed along the level (2D), read back by VTK.
const std::string kCheckBedWalls = R"(
import sys, math
import vtk
r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update()
g = r.GetOutput()
level, expected = float(sys.argv[2]), float(sys.argv[3])
P = [g.GetPoint(i) for i in range(g.GetNumberOfPoints())]
cells = [[g.GetCell(c).GetPointId(k) for k in range(g.GetCell(c).GetNumberOfPoints())] for c in range(g.GetNumberOfCells())]
dim = 3 if len(cells) > 1 else 2
up = dim - 1
assert all(p[up] <= level + 1e-12 for p in P), 'a point above the level'
if dim == 3:
    area, edges = 0.0, {}
    for i, j, k in cells:
        a = [P[j][m] - P[i][m] for m in range(3)]; b = [P[k][m] - P[i][m] for m in range(3)]
        cx = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
        area += 0.5 * math.sqrt(sum(x * x for x in cx))
        for e in ((i, j), (j, k), (k, i)): edges[e] = edges.get(e, 0) + 1
    # The open rim: edges without a twin, every one on the level (points are not shared between
    # facets, so twins are matched by position).
    pos = lambda e: (tuple(P[e[0]]), tuple(P[e[1]]))
    directed = {pos(e) for e in edges}
    rim = [e for e in directed if (e[1], e[0]) not in directed]
    assert rim and all(abs(a[up] - level) < 1e-12 and abs(b[up] - level) < 1e-12 for a, b in rim), 'rim off the level'
    assert abs(area - expected) < 1e-9 * expected, ('wall area', area, expected)
else:
    ids = cells[0]
    assert ids[0] == ids[-1], 'closed'
    area = 0.5 * abs(sum(P[ids[k]][0] * P[ids[k + 1]][1] - P[ids[k + 1]][0] * P[ids[k]][1] for k in range(len(ids) - 1)))
    assert abs(area - expected) < 1e-12, ('area', area, expected)
)";

TEST(CliBedPicture, TheContainerIsDrawnUpToTheLevel) {
  TempDir dir;
  // 3D: a 1 x 2 floor and the four sides 1.5 high: 2 + 2 (1 + 2) 1.5 = 11.
  write_bytes(dir.work() / "b.yaml", "dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 2, 3], bed: {height: 1.5}}\n"
                                     "particles: {radius: {distribution: constant, value: 0.2}}\n");
  ASSERT_EQ(run_frontpack(dir, "pack b.yaml -q -o b.vtu").exit_code, 0);
  EXPECT_EQ(python_check(kCheckBedWalls, {dir.work() / "b.container.vtu", "1.5", "11"}), 0);
  write_bytes(dir.work() / "r.yaml", "dimension: 2\ncontainer: {type: rectangle, min: [0, 0], max: [2, 1], bed: {height: 0.5}}\n"
                                     "particles: {radius: {distribution: constant, value: 0.05}}\n");
  ASSERT_EQ(run_frontpack(dir, "pack r.yaml -q -o r.vtu").exit_code, 0);
  EXPECT_EQ(python_check(kCheckBedWalls, {dir.work() / "r.container.vtu", "0.5", "1"}), 0);
  // analyze --plots adds the profile's figure.
  if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0)
    GTEST_SKIP() << "python3-matplotlib is not installed (scripts/install-deps.sh --test installs it)";
  fs::create_directory(dir.work() / "figs");
  ASSERT_EQ(run_frontpack(dir, "analyze b.vtu --scene b.yaml -q --plots figs").exit_code, 0);
  EXPECT_GT(fs::file_size(dir.work() / "figs" / "bed_profile.png"), 5000u);
  EXPECT_TRUE(fs::exists(dir.work() / "figs" / "section_xz.png"));
}

TEST(CliBedRefusals, NamesTheKey) {
  TempDir dir;
  const std::string head = "dimension: 3\ncontainer: {type: cylinder, base: [0, 0, 0], radius: 1, height: 3, bed: ";
  const std::string tail = "}\nparticles: {radius: {distribution: uniform, min: 0.04, max: 0.06}}\n";
  expect_refused(dir, head + "{height: 0}" + tail, "container.bed.height");
  expect_refused(dir, head + "{height: -1}" + tail, "container.bed.height");
  expect_refused(dir, head + "{height: 1, up: [0, 0, 0]}" + tail, "must be a non-zero vector");
  expect_refused(dir, head + "{height: 1, up: [0, 1]}" + tail, "container.bed.up");
  expect_refused(dir, head + "{height: 1, surface: rough}" + tail, "container.bed.surface");
  expect_refused(dir, head + "{heigth: 1}" + tail, "heigth");
  expect_refused(dir, head + "1.2" + tail, "container.bed");
  expect_refused(dir, head + "{height: 1}" + tail + "packer: {method: stacking}\nstop: {particles: 10}\n",
                 "a bed (container.bed) is filled by the advancing front");
  // Lower than the smallest particle: nothing fits.
  expect_refused(dir, head + "{height: 0.05}" + tail, "does not fit in the container");
}

}  // namespace
}  // namespace fptest
