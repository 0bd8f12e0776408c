// The OFF reader: what Geomview's format allows is read, every deviation is refused with its
// line, and a header's counts are checked against the file size before anything is allocated.
#include "core/geometry/off_reader.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace fp::detail {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = std::string(FRONTPACK_BINARY_DIR) + "/off_reader_test_" + name + ".off";
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string error_reading(const std::string& text) {
  PolygonSoup soup;
  std::string error;
  if (read_off(write_temp("bad", text), soup, error)) return "";
  return error;
}

const std::string kTetraFaces = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";

TEST(OffReader, ReadsCommentsColoursAndCountsOnTheHeaderLine) {
  PolygonSoup soup;
  std::string error;
  const std::string text = "COFF 4 4 6  # counts on the keyword's line\n"
                           "\n# a comment line\n"
                           "0 0 0 1 0 0\n1 0 0 1 0 0 1\n0 1 0 0 1 0\n0 0 1 0 0 1 0.5\n"
                           "3 0 2 1 255 0 0\n3 0 1 3\n3 1 2 3 7\n3 2 0 3 0.1 0.2 0.3 1  # face colours\n";
  ASSERT_TRUE(read_off(write_temp("good", text), soup, error)) << error;
  ASSERT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.points[3], Vec3(0, 0, 1));
  ASSERT_EQ(soup.polygons.size(), 4u);
  EXPECT_EQ(soup.polygons[0], (std::vector<std::size_t>{0, 2, 1}));
}

TEST(OffReader, VertexLineWithANumberTooManyNamesTheLine) {
  const std::string e = error_reading("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0 7\n0 0 1\n" + kTetraFaces);
  EXPECT_NE(e.find("line 5:"), std::string::npos) << e;
  EXPECT_NE(e.find("vertex 2 has 4 numbers"), std::string::npos) << e;
}

TEST(OffReader, HeaderClaimingMoreThanTheFileHoldsIsRefusedBeforeAllocating) {
  const std::string e = error_reading("OFF\n2000000000 4 0\n0 0 0\n");
  EXPECT_NE(e.find("line 2:"), std::string::npos) << e;
  EXPECT_NE(e.find("2000000000 vertices"), std::string::npos) << e;
  EXPECT_NE(error_reading("OFF\n4 18446744073709551615 0\n").find("more than the file"), std::string::npos);
}

TEST(OffReader, OtherDeviationsNameTheLine) {
  const std::string v = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::pair<std::string, std::string> cases[] = {
      {"OFF\n4 4 0\n" + v + "3 0 2 9\n3 0 1 3\n3 1 2 3\n3 2 0 3\n", "line 7: face 0: '9' is not a vertex index"},
      {"OFF\n4 4 0\n" + v + "3 0 2\n3 0 1 3\n3 1 2 3\n3 2 0 3\n", "line 7: face 0 has 2 numbers"},
      {"OFF\n4 4 0\n" + v + "2 0 2\n3 0 1 3\n3 1 2 3\n3 2 0 3\n", "line 7: face 0 must start"},
      {"OFF\n4 4 0\n" + v + kTetraFaces + "3 0 1 2\n", "line 11: text after the last of the 4 faces"},
      {"OFF\n4 4 0\n0 0 0\n1 0 x\n0 1 0\n0 0 1\n" + kTetraFaces, "line 4: 'x' is not a number"},
      {"OFF\n4 4\n" + v + "3 0 2 1\n" + std::string(40, '#'), "the file ends after 1 of 4 faces"},
      {"OFF\nfour 4 0\n", "line 2: expected the counts"},
      {"PLY\n", "line 1: the header is 'PLY'"},
      {"", "empty file"},
  };
  for (const auto& [text, expected] : cases) EXPECT_NE(error_reading(text).find(expected), std::string::npos) << error_reading(text);
}

}  // namespace
}  // namespace fp::detail
