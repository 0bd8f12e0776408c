// Beside every vtu output, the container's boundary ("<stem>.container.vtu"), read back by VTK
// (Debian's python3-vtk9, the library ParaView is built on): a closed surface wound outwards
// whose volume is the container's (3D), or one closed polyline whose area is its area (2D), every
// point on the container's boundary, in absolute coordinates.
#include <gtest/gtest.h>

#include <cstdio>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "cli_test_util.hpp"

using namespace fptest;

namespace {

// argv: the container file, its kind, the parameters (JSON), the expected measure and the
// relative tolerance of the measure (a round boundary is drawn with chords).
const std::string kCheckBoundary = R"(
import sys, json, math
import vtk
r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update()
g = r.GetOutput()
kind, prm, measure, tol = sys.argv[2], json.loads(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
P = [g.GetPoint(i) for i in range(g.GetNumberOfPoints())]
cells = []
for c in range(g.GetNumberOfCells()):
    cell = g.GetCell(c)
    cells.append((cell.GetCellType(), [cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())]))
assert P and cells, 'empty'
def near(a, b, scale=1.0): return abs(a - b) <= 1e-9 * max(1.0, abs(scale))
def on_boundary(p):
    if kind in ('box', 'rectangle'):
        lo, hi = prm['min'], prm['max']
        inside = all(lo[k] - 1e-9 * max(1, abs(lo[k])) <= p[k] <= hi[k] + 1e-9 * max(1, abs(hi[k])) for k in range(len(lo)))
        return inside and any(near(p[k], lo[k], lo[k]) or near(p[k], hi[k], hi[k]) for k in range(len(lo)))
    if kind in ('sphere', 'disk'):
        c = prm['center']
        return near(math.dist(p[:len(c)], c), prm['radius'], prm['radius'])
    if kind == 'cylinder':
        b, a = prm['base'], prm['axis']
        n = math.sqrt(sum(x * x for x in a)); a = [x / n for x in a]
        d = [p[k] - b[k] for k in range(3)]
        t = sum(d[k] * a[k] for k in range(3))
        rho = math.sqrt(max(0.0, sum(x * x for x in d) - t * t))
        R, H = prm['radius'], prm['height']
        return (near(rho, R, R) and -1e-9 <= t <= H + 1e-9) or ((near(t, 0, H) or near(t, H, H)) and rho <= R * (1 + 1e-9))
    if kind == 'polygon':
        return any(near(p[0], v[0], v[0]) and near(p[1], v[1], v[1]) for v in prm['vertices'])
    raise SystemExit('unknown kind ' + kind)
bad = [p for p in P if not on_boundary(p)]
assert not bad, ('points off the boundary', len(bad), bad[:3])
if kind in ('box', 'sphere', 'cylinder'):
    assert all(t == 5 for t, _ in cells), 'triangles only'
    directed = {}
    for _, ids in cells:
        for k in range(3):
            e = (ids[k], ids[(k + 1) % 3])
            directed[e] = directed.get(e, 0) + 1
    assert all(n == 1 for n in directed.values()), 'an edge twice in one direction: not wound consistently'
    assert all((b, a) in directed for a, b in directed), 'an edge without its twin: not closed'
    o = P[0]
    vol = 0.0
    for _, (i, j, k) in cells:
        a = [P[i][m] - o[m] for m in range(3)]; b = [P[j][m] - o[m] for m in range(3)]; c = [P[k][m] - o[m] for m in range(3)]
        vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    assert vol > 0, ('wound inwards', vol)
    assert abs(vol - measure) <= tol * measure, ('volume', vol, measure)
else:
    assert len(cells) == 1 and cells[0][0] == 4, 'one polyline'
    ids = cells[0][1]
    assert ids[0] == ids[-1] and len(ids) == len(P) + 1, 'closed, through every point'
    assert all(p[2] == 0.0 for p in P)
    area = 0.5 * abs(sum(P[ids[k]][0] * P[ids[k + 1]][1] - P[ids[k + 1]][0] * P[ids[k]][1] for k in range(len(ids) - 1)))
    assert abs(area - measure) <= tol * measure, ('area', area, measure)
)";

struct Case {
  const char* name;
  int dimension;
  const char* container;  // the scene's container mapping
  const char* kind;       // for the check
  const char* params;     // JSON, for the check
  double measure;
  double tolerance;       // relative, of the measure
  double radius;          // of the particles
};

// Chords of a circle of 64 segments: area 64/(2 pi) sin(2 pi/64) = 0.9984 of the disk's; the
// sphere's 64 x 32 facets enclose about 0.995 of the ball.
const Case kCases[] = {
    {"Box", 3, "{type: box, min: [0, 0, 0], max: [1, 2, 3]}", "box", R"({"min": [0, 0, 0], "max": [1, 2, 3]})", 6.0, 1e-9, 0.25},
    {"BoxFarAway", 3, "{type: box, min: [1e9, 0, 0], max: [1000000001, 1, 1]}", "box",
     R"({"min": [1e9, 0, 0], "max": [1000000001, 1, 1]})", 1.0, 1e-6, 0.2},
    {"Sphere", 3, "{type: sphere, center: [1, 1, 1], radius: 1.5}", "sphere", R"({"center": [1, 1, 1], "radius": 1.5})",
     4.0 / 3.0 * 3.141592653589793 * 3.375, 0.01, 0.3},
    {"Cylinder", 3, "{type: cylinder, base: [0, 0, 0], axis: [1, 1, 0], radius: 1, height: 3}", "cylinder",
     R"({"base": [0, 0, 0], "axis": [1, 1, 0], "radius": 1, "height": 3})", 3.141592653589793 * 3, 0.002, 0.25},
    {"Mesh", 3, "{type: mesh, file: MESH}", "box", R"({"min": [0, 0, 0], "max": [1, 1, 1]})", 1.0, 1e-9, 0.2},
    {"Rectangle", 2, "{type: rectangle, min: [0, 0], max: [2, 1]}", "rectangle", R"({"min": [0, 0], "max": [2, 1]})", 2.0,
     1e-9, 0.1},
    {"Disk", 2, "{type: disk, center: [0, 0], radius: 1}", "disk", R"({"center": [0, 0], "radius": 1})", 3.141592653589793,
     0.002, 0.1},
    {"Polygon", 2, "{type: polygon, vertices: [[0, 0], [2, 0], [2, 2], [1, 1], [0, 2]]}", "polygon",
     R"({"vertices": [[0, 0], [2, 0], [2, 2], [1, 1], [0, 2]]})", 3.0, 1e-9, 0.1},
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::string number(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

std::string scene_of(const Case& c) {
  std::string container = c.container;
  const std::string mesh = "MESH";
  if (const auto at = container.find(mesh); at != std::string::npos)
    container.replace(at, mesh.size(), source_path("tests/data/meshes/cube.stl"));
  return "dimension: " + std::to_string(c.dimension) + "\nseed: 3\ncontainer: " + container +
         "\nparticles: {radius: {distribution: constant, value: " + std::to_string(c.radius) + "}}\n";
}

class CliContainerVtu : public ::testing::TestWithParam<Case> {};

TEST_P(CliContainerVtu, TheContainerIsWrittenBesideTheVtuAndVtkReadsItsBoundary) {
  const Case& c = GetParam();
  TempDir dir;
  write_bytes(dir.work() / "scene.yaml", scene_of(c));
  const RunResult r = run_frontpack(dir, "pack scene.yaml -o out.vtu");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(fs::exists(dir.work() / "out.container.vtu"));
  EXPECT_NE(r.out.find("side file      out.container.vtu (of out.vtu"), std::string::npos) << r.out;
  EXPECT_EQ(python_check(kCheckBoundary, {dir.work() / "out.container.vtu", c.kind, c.params, number(c.measure), number(c.tolerance)}),
            0);
}

INSTANTIATE_TEST_SUITE_P(Containers, CliContainerVtu, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

const char* const kSmallBox =
    "dimension: 3\nseed: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
    "particles: {radius: {distribution: constant, value: 0.2}}\n";

/// Only vtu outputs have it: the other formats are read by programs that draw no walls.
TEST(CliContainerVtu, OtherFormatsWriteNoContainerFile) {
  TempDir dir;
  write_bytes(dir.work() / "scene.yaml", kSmallBox);
  const RunResult r = run_frontpack(dir, "pack scene.yaml -q -o out.csv -o out.data");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(listing(dir.work()), (std::set<std::string>{"out.csv", "out.data", "scene.yaml"}));
}

/// The container file is an output like the others: another output at its path is refused
/// before any work, naming both, and nothing is written.
TEST(CliContainerVtu, AnOutputAtTheContainerFilesPathIsRefused) {
  TempDir dir;
  write_bytes(dir.work() / "scene.yaml", kSmallBox);
  const RunResult r = run_frontpack(dir, "pack scene.yaml -o out.vtu -o out.container.vtu");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("out.container.vtu"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("side file of output 'out.vtu'"), std::string::npos) << r.err;
  EXPECT_EQ(listing(dir.work()), (std::set<std::string>{"scene.yaml"}));
}

}  // namespace
