// The MSH reader: the four files Gmsh 4.8.4 wrote from tests/data/meshes/msh/
// two_boxes.geo (versions 2.2 and 4.1, ASCII and binary) read as the same mesh, whose
// tetrahedra fill the unit cube exactly, each box its physical volume, the bottom face its
// physical surface; every deviation is refused with its line (ASCII) or byte (binary).
#include "core/geometry/msh_reader.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <Eigen/Geometry>  // cross

namespace fp {
namespace {

const std::string kDir = std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/meshes/msh/";

TetMesh read_ok(const std::string& path) {
  TetMesh m;
  std::string error;
  EXPECT_TRUE(read_msh(path, m, error)) << path << ": " << error;
  return m;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A file of this process' own: ctest runs each test as its own process, two at a time, and a
// shared name let one test read the bytes another was writing.
std::string own_path(const std::string& stem) {
  return std::string(FRONTPACK_BINARY_DIR) + "/" + stem + "_" + std::to_string(::getpid()) + ".msh";
}

std::string error_reading(const std::string& bytes) {
  const std::string path = own_path("msh_reader_test_bad");
  std::ofstream(path, std::ios::binary) << bytes;
  TetMesh m;
  std::string error;
  const bool ok = read_msh(path, m, error);
  std::remove(path.c_str());
  return ok ? "" : error;
}

double signed_volume(const TetMesh& m, std::size_t t) {
  const Vec3& a = m.nodes[m.tets[t][0]];
  return (m.nodes[m.tets[t][1]] - a).cross(m.nodes[m.tets[t][2]] - a).dot(m.nodes[m.tets[t][3]] - a) / 6.0;
}

TEST(MshReader, EveryVersionAndEncodingGmshWritesGivesTheSameMesh) {
  const TetMesh ref = read_ok(kDir + "two_boxes_v4.1_binary.msh");
  ASSERT_GT(ref.tets.size(), 100u);
  for (const char* name : {"two_boxes_v2.2_ascii.msh", "two_boxes_v2.2_binary.msh", "two_boxes_v4.1_ascii.msh"}) {
    const TetMesh m = read_ok(kDir + name);
    ASSERT_EQ(m.nodes.size(), ref.nodes.size()) << name;
    for (std::size_t k = 0; k < m.nodes.size(); ++k)  // ASCII holds 16 significant digits
      EXPECT_LE((m.nodes[k] - ref.nodes[k]).norm(), 1e-15) << name << " node " << k;
    EXPECT_EQ(m.tets, ref.tets) << name;
    EXPECT_EQ(m.tet_group, ref.tet_group) << name;
    EXPECT_EQ(m.triangles, ref.triangles) << name;
    EXPECT_EQ(m.triangle_group, ref.triangle_group) << name;
    EXPECT_EQ(m.group_names, ref.group_names) << name;
  }
  // The binary files hold the same doubles.
  EXPECT_EQ(read_ok(kDir + "two_boxes_v2.2_binary.msh").nodes, ref.nodes);
}

TEST(MshReader, TetrahedraFillTheCubeAndGroupsAreTheBoxes) {
  const TetMesh m = read_ok(kDir + "two_boxes_v4.1_ascii.msh");
  ASSERT_EQ(m.tet_group.size(), m.tets.size());
  double volume[2] = {0, 0};
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    ASSERT_TRUE(m.tet_group[t] == 11 || m.tet_group[t] == 12) << m.tet_group[t];
    const double v = std::abs(signed_volume(m, t));
    EXPECT_GT(v, 0.0);
    volume[m.tet_group[t] == 12] += v;
    // Group 11 is the lower box, 12 the upper one: every node of a tetrahedron on its side.
    for (const std::uint32_t n : m.tets[t]) {
      if (m.tet_group[t] == 11) EXPECT_LE(m.nodes[n].z(), 0.5 + 1e-12);
      else EXPECT_GE(m.nodes[n].z(), 0.5 - 1e-12);
    }
  }
  EXPECT_NEAR(volume[0], 0.5, 1e-12);
  EXPECT_NEAR(volume[1], 0.5, 1e-12);
  ASSERT_FALSE(m.triangles.empty());
  double area = 0;
  for (std::size_t f = 0; f < m.triangles.size(); ++f) {
    EXPECT_EQ(m.triangle_group[f], 21);
    for (const std::uint32_t n : m.triangles[f]) EXPECT_NEAR(m.nodes[n].z(), 0.0, 1e-12);
    const Vec3& a = m.nodes[m.triangles[f][0]];
    area += 0.5 * (m.nodes[m.triangles[f][1]] - a).cross(m.nodes[m.triangles[f][2]] - a).norm();
  }
  EXPECT_NEAR(area, 1.0, 1e-12);  // the bottom face, whole
  EXPECT_EQ(m.group_names.at({3, 11}), "lower");
  EXPECT_EQ(m.group_names.at({3, 12}), "upper");
  EXPECT_EQ(m.group_names.at({2, 21}), "bottom");
}

const std::string kTiny =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
    "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
    "$Elements\n2\n1 15 2 0 1 1\n2 4 2 7 1 1 2 3 4\n$EndElements\n";

TEST(MshReader, AHandWrittenVersion22FileWithAPointElement) {
  const std::string path = own_path("msh_reader_test_tiny");
  std::ofstream(path, std::ios::binary) << kTiny;
  const TetMesh m = read_ok(path);
  std::remove(path.c_str());
  ASSERT_EQ(m.tets.size(), 1u);  // the point element is read past
  EXPECT_EQ(m.tets[0], (std::array<std::uint32_t, 4>{0, 1, 2, 3}));
  EXPECT_EQ(m.tet_group[0], 7);
  EXPECT_NEAR(signed_volume(m, 0), 1.0 / 6.0, 1e-15);
}

void expect_error(const std::string& bytes, const std::string& part) {
  const std::string e = error_reading(bytes);
  EXPECT_NE(e.find(part), std::string::npos) << "error '" << e << "' lacks '" << part << "'";
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(MshReader, DeviationsAreRefusedWithTheirLine) {
  expect_error(replaced(kTiny, "3 0 1 0", "3 0 abc 0"), "line 8: a node coordinate must be a finite number, got 'abc'");
  expect_error(replaced(kTiny, "1 1 2 3 4", "1 1 2 3 9"), "tetrahedron 1 names node 9, which the file does not have");
  expect_error(replaced(kTiny, "4 0 0 1", "3 0 0 1"), "node tag 3 is given twice");
  expect_error(replaced(kTiny, "2.2 0 8", "3.0 0 8"), "line 2: MSH version 3.0 is not supported");
  expect_error(replaced(kTiny, "2.2 0 8", "2.2 0 4"), "the data size must be 8");
  expect_error(replaced(kTiny, "1 15 2", "1 99 2"), "line 13: element type 99 is not one Gmsh documents");
  expect_error(replaced(kTiny, "$Nodes\n4\n", "$Nodes\n4000000000\n"), "line 5: 4000000000 nodes cannot fit");
  expect_error(replaced(kTiny, "$EndNodes", "$EndNode"), "expected $EndNodes, got '$EndNode'");
  expect_error(kTiny.substr(0, kTiny.find("$Elements")), "no $Elements section");
  expect_error(replaced(kTiny, "1 0 0 0", "-1 0 0 0"), "node tag -1 is not positive");
  expect_error("", "the file ends where $MeshFormat was expected");
  expect_error(replaced(kTiny, "$EndElements\n", "$EndElements\n$Comments\nnot closed\n"), "section $Comments has no end line");
  // An unknown section is read past.
  const std::string with_data = replaced(kTiny, "$EndElements\n", "$EndElements\n$NodeData\n1\n\"t\"\n$EndNodeData\n");
  EXPECT_EQ(error_reading(with_data), "");
}

TEST(MshReader, BinaryFilesCutShortOrCorruptedNameTheirByte) {
  const std::string bin = file_text(kDir + "two_boxes_v4.1_binary.msh");
  const std::string cut = bin.substr(0, bin.find("$EndNodes") - 7);
  const std::string e = error_reading(cut);
  EXPECT_EQ(e.rfind("byte ", 0), 0u) << e;
  EXPECT_NE(e.find("the file ends inside"), std::string::npos) << e;
  // A byte-order check that is not 1 (a big-endian or damaged file).
  std::string swapped = bin;
  const std::size_t check = swapped.find("4.1 1 8\n") + 8;
  swapped[check] = 0;
  swapped[check + 3] = 1;
  EXPECT_NE(error_reading(swapped).find("not a little-endian binary MSH file"), std::string::npos);
  // A node block claiming more nodes than the file holds is refused before any allocation.
  std::string big = file_text(kDir + "two_boxes_v2.2_binary.msh");
  const std::size_t nodes = big.find("$Nodes\n") + 7;
  big.replace(nodes, big.find('\n', nodes) - nodes, "900000000000");
  EXPECT_NE(error_reading(big).find("nodes cannot fit"), std::string::npos) << error_reading(big);
  // Node tags an element names must exist, in binary files too: the first element's first node
  // (after the block header: type, count, tag count; then the element's tag and tags).
  std::string v2 = file_text(kDir + "two_boxes_v2.2_binary.msh");
  std::size_t at = v2.find("$Elements\n") + 10;
  at = v2.find('\n', at) + 1;
  int tags = 0;
  std::memcpy(&tags, v2.data() + at + 8, 4);
  const int missing = 999999;
  std::memcpy(v2.data() + at + 12 + 4 + 4 * tags, &missing, 4);
  EXPECT_NE(error_reading(v2).find("names node 999999, which the file does not have"), std::string::npos)
      << error_reading(v2);
}

}  // namespace
}  // namespace fp
