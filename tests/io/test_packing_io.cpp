// Writers and readers of packing files: exact round trips, format conventions (LAMMPS
// diameters, 1-based ids, 2D slab), determinism, and VTU validity checked by VTK itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/io/packing_readers.hpp"
#include "core/io/packing_writers.hpp"
#include "core/sampling/rng.hpp"
#include "tests/io/io_test_util.hpp"

namespace fp {
namespace {

using test::slurp;
using test::spit;
using test::TempDir;

// Coordinates with many significant digits, large offsets and tiny radii, plus values that
// a %.6g writer would corrupt: the round trip must be bit-exact anyway.
template <int D>
Packing<D> random_packing(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  Packing<D> p;
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> c;
    for (int k = 0; k < D; ++k) c[k] = rng.uniform(-1e3, 1e3) * (i % 3 == 0 ? 1e-7 : 1.0);
    p.add(c, rng.uniform(1e-6, 2.0));
  }
  Vec<D> special = Vec<D>::Constant(0.1);
  special[0] = -0.0;
  p.add(special, 1.0 / 3.0);
  p.add(Vec<D>::Constant(1e-300), 5e-324 * 1e10);
  return p;
}

RunRecord sample_record(int dimension) {
  RunRecord r;
  r.version = "0.1.0-test";
  r.scene_path = "scene.yaml";
  r.scene_text = "dimension: 3\n";
  r.seed = 18446744073709551615ULL;
  r.dimension = dimension;
  r.container_description = "box [0,1]^3";
  r.distribution_description = "uniform [0.01, 0.02]";
  r.timings = {{"pack", 1.25}, {"write", 0.5}};
  r.metrics = {{"volume_fraction", 0.6123456789012345}, {"undefined", std::nan("")}};
  r.counters = {{"pairs_tried", 123456789}};
  r.info = {{"host", "test"}};
  return r;
}

template <int D>
void expect_same(const Packing<D>& a, const Packing<D>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int k = 0; k < D; ++k) ASSERT_EQ(a.centers[i][k], b.centers[i][k]) << "particle " << i << " axis " << k;
    ASSERT_EQ(a.radii[i], b.radii[i]) << "particle " << i;
  }
}

const OutputFormat kAllFormats[] = {OutputFormat::Vtu, OutputFormat::Yade, OutputFormat::Lammps, OutputFormat::Csv,
                                    OutputFormat::Json};

TEST(PackingIo, RoundTripIsExact3D) {
  TempDir dir;
  const auto p = random_packing<3>(500, 7);
  for (const OutputFormat f : kAllFormats) {
    const std::string path = dir.file(std::string("p3.") + output_format_name(f));
    write_packing<3>(f, path, p, sample_record(3));
    SCOPED_TRACE(output_format_name(f));
    expect_same(p, read_packing<3>(f, path));
    EXPECT_EQ(packing_file_dimension(f, path), 3);
  }
}

TEST(PackingIo, RoundTripIsExact2D) {
  TempDir dir;
  const auto p = random_packing<2>(500, 8);
  for (const OutputFormat f : kAllFormats) {
    const std::string path = dir.file(std::string("p2.") + output_format_name(f));
    write_packing<2>(f, path, p, sample_record(2));
    SCOPED_TRACE(output_format_name(f));
    expect_same(p, read_packing<2>(f, path));
    EXPECT_EQ(packing_file_dimension(f, path), 2);
  }
}

TEST(PackingIo, EmptyPackingRoundTrips) {
  TempDir dir;
  for (const OutputFormat f : kAllFormats) {
    const std::string path = dir.file(std::string("empty.") + output_format_name(f));
    write_packing<3>(f, path, Packing<3>{}, sample_record(3));
    EXPECT_EQ(read_packing<3>(f, path).size(), 0u) << output_format_name(f);
  }
}

TEST(PackingIo, OutputIsByteIdenticalForIdenticalInput) {
  TempDir dir;
  const auto p = random_packing<3>(200, 9);
  for (const OutputFormat f : kAllFormats) {
    const std::string a = dir.file(std::string("a.") + output_format_name(f));
    const std::string b = dir.file(std::string("b.") + output_format_name(f));
    write_packing<3>(f, a, p, sample_record(3));
    write_packing<3>(f, b, random_packing<3>(200, 9), sample_record(3));
    const std::string bytes = slurp(a);
    EXPECT_FALSE(bytes.empty());
    EXPECT_EQ(bytes, slurp(b)) << output_format_name(f);
  }
}

TEST(PackingIo, YadeAndCsvLayout) {
  TempDir dir;
  Packing<3> p3;
  p3.add(Vec3(0.5, 0.25, 0.125), 0.1);
  write_packing<3>(OutputFormat::Yade, dir.file("a.txt"), p3, RunRecord{});
  EXPECT_EQ(slurp(dir.file("a.txt")), "#format x_y_z_r\n0.5 0.25 0.125 0.1\n");
  write_packing<3>(OutputFormat::Csv, dir.file("a.csv"), p3, RunRecord{});
  EXPECT_EQ(slurp(dir.file("a.csv")), "id,x,y,z,r\n0,0.5,0.25,0.125,0.1\n");

  Packing<2> p2;
  p2.add(Vec2(1.5, -2.0), 0.75);
  p2.add(Vec2(3.0, 4.0), 1e-5);
  write_packing<2>(OutputFormat::Yade, dir.file("b.txt"), p2, RunRecord{});
  EXPECT_EQ(slurp(dir.file("b.txt")), "#format x_y_z_r\n1.5 -2 0 0.75\n3 4 0 1e-05\n");
  write_packing<2>(OutputFormat::Csv, dir.file("b.csv"), p2, RunRecord{});
  EXPECT_EQ(slurp(dir.file("b.csv")), "id,x,y,r\n0,1.5,-2,0.75\n1,3,4,1e-05\n");
}

// Parses the Atoms section of a LAMMPS data file: rows of 7 numbers.
std::vector<std::vector<double>> lammps_atoms(const std::string& text, std::string& header) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::vector<double>> rows;
  bool atoms = false;
  while (std::getline(in, line)) {
    if (line.rfind("Atoms", 0) == 0) {
      atoms = true;
      continue;
    }
    if (!atoms) {
      header += line + "\n";
      continue;
    }
    if (line.empty()) continue;
    std::istringstream fields(line);
    std::vector<double> row;
    double v;
    while (fields >> v) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

TEST(PackingIo, LammpsUsesDiametersOneBasedIdsAndTheContainerBox) {
  TempDir dir;
  Packing<3> p;
  p.add(Vec3(0.5, 0.5, 0.5), 0.1);
  p.add(Vec3(0.2, 0.3, 0.4), 0.05);
  RunRecord rec;
  rec.density = 2500.0;
  Aabb<3> box;
  box.lo = Vec3(0, 0, 0);
  box.hi = Vec3(1, 2, 3);
  rec.bounds = box;
  write_packing<3>(OutputFormat::Lammps, dir.file("a.data"), p, rec);
  std::string header;
  const auto rows = lammps_atoms(slurp(dir.file("a.data")), header);
  EXPECT_NE(header.find("\n2 atoms\n"), std::string::npos) << header;
  EXPECT_NE(header.find("\n1 atom types\n"), std::string::npos) << header;
  EXPECT_NE(header.find("\n0 1 xlo xhi\n0 2 ylo yhi\n0 3 zlo zhi\n"), std::string::npos) << header;
  ASSERT_EQ(rows.size(), 2u);
  const std::vector<double> first = {1, 1, 0.2, 2500, 0.5, 0.5, 0.5};
  const std::vector<double> second = {2, 1, 0.1, 2500, 0.2, 0.3, 0.4};
  EXPECT_EQ(rows[0], first);
  EXPECT_EQ(rows[1], second);
  // And the reader halves the diameter back.
  const auto back = read_packing<3>(OutputFormat::Lammps, dir.file("a.data"));
  EXPECT_EQ(back.radii[0], 0.1);
  EXPECT_EQ(back.radii[1], 0.05);
}

TEST(PackingIo, LammpsWithoutBoundsUsesGrownBoundingBox2DHasThinSlab) {
  TempDir dir;
  Packing<2> p;
  p.add(Vec2(1.0, 1.0), 0.5);
  p.add(Vec2(3.0, 2.0), 0.25);
  write_packing<2>(OutputFormat::Lammps, dir.file("a.data"), p, RunRecord{});
  std::string header;
  const auto rows = lammps_atoms(slurp(dir.file("a.data")), header);
  EXPECT_NE(header.find("\n0.5 3.25 xlo xhi\n0.5 2.25 ylo yhi\n-0.5 0.5 zlo zhi\n"), std::string::npos) << header;
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1][2], 0.5);  // diameter
  EXPECT_EQ(rows[1][6], 0.0);  // z
  EXPECT_EQ(rows[0][3], 1.0);  // default density
}

TEST(PackingIo, LammpsReaderAcceptsImageFlagsAndAnyIdOrder) {
  TempDir dir;
  spit(dir.file("x.data"),
       "title\n\n3 atoms\n1 atom types\n0 1 xlo xhi\n0 1 ylo yhi\n0 1 zlo zhi\n\nAtoms # sphere\n\n"
       "3 1 0.3 1 0.3 0.3 0.3 0 0 0\n1 1 0.1 1 0.1 0.1 0.1 0 0 0\n2 1 0.2 1 0.2 0.2 0.2 0 0 0\n\nVelocities\n\n1 0 0 0\n");
  const auto p = read_packing<3>(OutputFormat::Lammps, dir.file("x.data"));
  ASSERT_EQ(p.size(), 3u);
  const double diameter[] = {0.1, 0.2, 0.3};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(p.radii[i], 0.5 * diameter[i]);
    EXPECT_EQ(p.centers[i].x(), diameter[i]);
  }
}

void expect_read_error(OutputFormat f, int dim, const std::string& path, const std::vector<std::string>& parts) {
  try {
    if (dim == 2) read_packing<2>(f, path);
    else read_packing<3>(f, path);
    ADD_FAILURE() << "no error reading " << path;
  } catch (const std::runtime_error& e) {
    for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(PackingIo, ReaderErrorsNameFileAndLine) {
  TempDir dir;
  const std::string csv = dir.file("bad.csv");
  spit(csv, "id,x,y,z,r\n0,1,2,3,0.5\n1,1,2,abc,0.5\n");
  expect_read_error(OutputFormat::Csv, 3, csv, {csv + ":3:", "'abc'"});
  expect_read_error(OutputFormat::Csv, 2, csv, {csv + ":1:", "id,x,y,r"});
  spit(csv, "id,x,y,z,r\n0,1,2,3,0.5\n0,1,2,3,0.5\n");
  expect_read_error(OutputFormat::Csv, 3, csv, {csv + ":3:", "duplicate id 0"});
  spit(csv, "id,x,y,z,r\n0,1,2,3\n");
  expect_read_error(OutputFormat::Csv, 3, csv, {csv + ":2:", "5 fields"});

  const std::string yade = dir.file("bad.txt");
  spit(yade, "#format x_y_z_r\n1 2 3 4\n1 2 3\n");
  expect_read_error(OutputFormat::Yade, 3, yade, {yade + ":3:", "4 columns"});
  spit(yade, "#format x_y_z_r\n1 2 0 4\n1 2 0.5 1\n");
  expect_read_error(OutputFormat::Yade, 2, yade, {yade + ":3:", "z must be 0"});

  const std::string data = dir.file("bad.data");
  spit(data, "title\n\n3 atoms\n\nAtoms # sphere\n\n1 1 0.1 1 0 0 0\n2 1 0.1 1 1 1 1\n");
  expect_read_error(OutputFormat::Lammps, 3, data, {data + ":", "announces 3 atoms", "has 2"});
  spit(data, "title\n\n1 atoms\n\nAtoms # atomic\n\n1 1 0 0 0\n");
  expect_read_error(OutputFormat::Lammps, 3, data, {data + ":5:", "'atomic'"});

  const std::string vtu = dir.file("bad.vtu");
  spit(vtu, "<VTKFile type=\"UnstructuredGrid\"><AppendedData encoding=\"base64\"></AppendedData></VTKFile>");
  expect_read_error(OutputFormat::Vtu, 3, vtu, {vtu, "appended raw"});

  expect_read_error(OutputFormat::Csv, 3, dir.file("missing.csv"), {dir.file("missing.csv"), "cannot open"});

  const std::string json = dir.file("bad.json");
  spit(json, "{\"dimension\": 3,\n \"n\": }");
  expect_read_error(OutputFormat::Json, 3, json, {json, "line 2"});
  write_packing<2>(OutputFormat::Json, json, random_packing<2>(3, 1), sample_record(2));
  expect_read_error(OutputFormat::Json, 3, json, {json, "2D, expected 3D"});
}

TEST(PackingIo, FormatNamesAndExtensions) {
  EXPECT_EQ(parse_output_format("vtu"), OutputFormat::Vtu);
  EXPECT_EQ(parse_output_format("LAMMPS"), OutputFormat::Lammps);
  for (const OutputFormat f : kAllFormats) EXPECT_EQ(parse_output_format(output_format_name(f)), f);
  try {
    parse_output_format("xyz");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'xyz'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("vtu, yade, lammps, csv, json"), std::string::npos);
  }
  EXPECT_EQ(format_from_extension("out/a.vtu"), OutputFormat::Vtu);
  EXPECT_EQ(format_from_extension("a.txt"), OutputFormat::Yade);
  EXPECT_EQ(format_from_extension("a.yade"), OutputFormat::Yade);
  EXPECT_EQ(format_from_extension("a.data"), OutputFormat::Lammps);
  EXPECT_EQ(format_from_extension("a.lammps"), OutputFormat::Lammps);
  EXPECT_EQ(format_from_extension("A.CSV"), OutputFormat::Csv);
  EXPECT_EQ(format_from_extension("a.json"), OutputFormat::Json);
  EXPECT_THROW(format_from_extension("a.xyz"), std::invalid_argument);
  EXPECT_THROW(format_from_extension("noext"), std::invalid_argument);
}

// --- VTU read back by VTK itself ---------------------------------------------------------

bool python_has_vtk() { return std::system("/usr/bin/python3 -c 'import vtk' >/dev/null 2>&1") == 0; }

TEST(PackingIo, VtuOpensInVtk) {
  if (!python_has_vtk()) GTEST_SKIP() << "/usr/bin/python3 cannot import vtk (install python3-vtk9)";
  TempDir dir;
  for (const int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    const std::string vtu = dir.file("p.vtu");
    Packing<3> p3 = random_packing<3>(1000, 11);
    Packing<2> p2 = random_packing<2>(1000, 12);
    if (dim == 3) write_packing<3>(OutputFormat::Vtu, vtu, p3, RunRecord{});
    else write_packing<2>(OutputFormat::Vtu, vtu, p2, RunRecord{});
    const std::string script = dir.file("read.py");
    const std::string result = dir.file("result.txt");
    spit(script,
         "import sys, vtk\n"
         "r = vtk.vtkXMLUnstructuredGridReader()\n"
         "r.SetFileName(sys.argv[1])\n"
         "r.Update()\n"
         "g = r.GetOutput()\n"
         "rad = g.GetPointData().GetArray('radius')\n"
         "ids = g.GetPointData().GetArray('id')\n"
         "with open(sys.argv[2], 'w') as f:\n"
         "    f.write('%d %d %d %d\\n' % (g.GetNumberOfPoints(), g.GetNumberOfCells(), g.GetCellType(0), rad.GetNumberOfTuples()))\n"
         "    for i in (0, 1, 500, g.GetNumberOfPoints() - 1):\n"
         "        x, y, z = g.GetPoint(i)\n"
         "        f.write('%r %r %r %r %d\\n' % (x, y, z, rad.GetValue(i), ids.GetValue(i)))\n");
    ASSERT_EQ(std::system(("/usr/bin/python3 " + script + " " + vtu + " " + result).c_str()), 0);
    std::istringstream in(slurp(result));
    std::size_t points = 0, cells = 0, rad_count = 0;
    int cell_type = 0;
    in >> points >> cells >> cell_type >> rad_count;
    const std::size_t n = dim == 3 ? p3.size() : p2.size();
    EXPECT_EQ(points, n);
    EXPECT_EQ(cells, n);
    EXPECT_EQ(cell_type, 1);  // VTK_VERTEX
    EXPECT_EQ(rad_count, n);
    for (const std::size_t i : {std::size_t{0}, std::size_t{1}, std::size_t{500}, n - 1}) {
      std::string sx, sy, sz, sr;  // repr() of Python floats round-trips exactly
      long long id = -1;
      in >> sx >> sy >> sz >> sr >> id;
      EXPECT_EQ(id, static_cast<long long>(i));
      const double x = std::strtod(sx.c_str(), nullptr), y = std::strtod(sy.c_str(), nullptr);
      const double z = std::strtod(sz.c_str(), nullptr), r = std::strtod(sr.c_str(), nullptr);
      if (dim == 3) {
        EXPECT_EQ(x, p3.centers[i].x());
        EXPECT_EQ(y, p3.centers[i].y());
        EXPECT_EQ(z, p3.centers[i].z());
        EXPECT_EQ(r, p3.radii[i]);
      } else {
        EXPECT_EQ(x, p2.centers[i].x());
        EXPECT_EQ(y, p2.centers[i].y());
        EXPECT_EQ(z, 0.0);
        EXPECT_EQ(r, p2.radii[i]);
      }
    }
  }
}

}  // namespace
}  // namespace fp
