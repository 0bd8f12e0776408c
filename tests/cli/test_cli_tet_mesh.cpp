// `frontpack pack` of a tetrahedral mesh (container {type: mesh, file: X.msh}, packer
// {method: tet_mesh}: paper 000's steps 2-7b) end to end: the four encodings Gmsh wrote of one
// mesh (MSH 2.2 and 4.1, ASCII and binary) pack byte-identically per encoding and pass `frontpack
// validate`;
// phi0 and N0 stop it; the front packs the same container too; bad meshes and misplaced keys
// exit 2 naming the file and what is wrong, and write nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cli_test_util.hpp"

namespace fptest {
namespace {

std::string scene_for(const std::string& mesh, const std::string& extra = "packer: {method: tet_mesh}\n") {
  return "dimension: 3\nseed: 2\ncontainer: {type: mesh, file: " + mesh +
         "}\nparticles: {radius: {distribution: uniform, min: 0.01, max: 0.06}}\n" + extra;
}

TEST(CliTetMesh, EveryEncodingGmshWritesPacksTheSameSpheres) {
  // Versions 2.2 and 4.1 give the same nodes and tetrahedra: the same spheres, byte for byte. Gmsh
  // writes ASCII coordinates with 16 significant digits, binary ones exactly: the two differ in
  // the last digits, and so do their packings (by a few spheres in thousands).
  TempDir dir;
  std::string csv[2];
  for (const char* encoding : {"ascii", "binary"})
    for (const char* version : {"v2.2", "v4.1"}) {
      const std::string name = std::string("two_boxes_") + version + "_" + encoding;
      write_bytes(dir.work() / "s.yaml", scene_for(source_path("tests/data/meshes/msh/" + name + ".msh")));
      const RunResult r = run_frontpack(dir, "pack s.yaml -o out.csv");
      ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
      EXPECT_NE(r.out.find("tet mesh       250 tetrahedra"), std::string::npos) << r.out;
      EXPECT_NE(r.out.find("void filling   +"), std::string::npos) << r.out;
      std::string& mine = csv[std::string(encoding) == "binary"];
      const std::string out = read_bytes(dir.work() / "out.csv");
      if (mine.empty()) mine = out;
      EXPECT_EQ(out, mine) << name << " packs other spheres than the version 2.2 file of the same encoding";
      const RunResult v = run_frontpack(dir, "validate out.csv --scene s.yaml --ks-alpha 0");
      EXPECT_EQ(v.exit_code, 0) << name << ": " << v.out;
    }
  const double a = static_cast<double>(lines_of(csv[0]).size()), b = static_cast<double>(lines_of(csv[1]).size());
  EXPECT_GT(a, 5000);
  EXPECT_NEAR(a, b, 0.01 * a);
}

TEST(CliTetMesh, StopsAtTheTargetSolidFractionAndCount) {
  TempDir dir;
  const std::string mesh = source_path("tests/data/meshes/msh/cube_kuhn4.msh");
  write_bytes(dir.work() / "phi.yaml", scene_for(mesh, "packer: {method: tet_mesh}\nstop: {volume_fraction: 0.55}\n"));
  const RunResult phi = run_frontpack(dir, "pack phi.yaml -o phi.csv --record phi.json");
  ASSERT_EQ(phi.exit_code, 0) << phi.err;
  EXPECT_NE(phi.out.find("(stop: volume fraction"), std::string::npos) << phi.out;
  const std::string rec = read_bytes(dir.work() / "phi.json");
  const auto at = rec.find("\"volume_fraction_container\": ");
  ASSERT_NE(at, std::string::npos);
  const double vf = std::stod(rec.substr(at + 29));
  EXPECT_GE(vf, 0.55);
  EXPECT_LT(vf, 0.551) << "checked after every sphere";
  write_bytes(dir.work() / "n.yaml", scene_for(mesh, "packer: {method: tet_mesh}\nstop: {particles: 3000}\n"));
  ASSERT_EQ(run_frontpack(dir, "pack n.yaml -o n.csv -q").exit_code, 0);
  EXPECT_EQ(lines_of(read_bytes(dir.work() / "n.csv")).size(), 3001u) << "a header and 3,000 spheres";
}

TEST(CliTetMesh, AnAllowedOverlapPassesPackAndValidateAlike) {
  // Overlaps placed at exactly epsilon r_min (the last resort's reduction, the r_min fallback)
  // must pass the check: pack's and validate's, with their defaults (the radii: their range).
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", scene_for(source_path("tests/data/meshes/msh/cube_kuhn4.msh"),
                                               "packer: {method: tet_mesh, overlap: 0.05, fallback_r_min: true}\n"));
  const RunResult r = run_frontpack(dir, "pack s.yaml -o out.csv");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("tolerance 0.05"), std::string::npos) << r.out;
  const RunResult v = run_frontpack(dir, "validate out.csv --scene s.yaml");
  EXPECT_EQ(v.exit_code, 0) << v.out;
  EXPECT_NE(v.out.find("max overlap 0.05 of the smaller radius"), std::string::npos) << "the allowance is used: " << v.out;
}

TEST(CliTetMesh, TheFrontPacksATetrahedralMeshsBoundaryToo) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml", scene_for(source_path("tests/data/meshes/msh/cube_kuhn4.msh"), ""));
  ASSERT_EQ(run_frontpack(dir, "pack s.yaml -o f.csv -q").exit_code, 0);
  EXPECT_EQ(run_frontpack(dir, "validate f.csv --scene s.yaml").exit_code, 0);
}

TEST(CliTetMesh, ASurfaceContainerIsMeshedFirst) {
  // An STL cube: meshed into tetrahedra of 8 mean radii (or packer.mesh_edge), then packed.
  TempDir dir;
  const std::string cube = source_path("tests/data/meshes/cube.stl");
  write_bytes(dir.work() / "s.yaml", "dimension: 3\nseed: 1\ncontainer: {type: mesh, file: " + cube +
                                         "}\nparticles: {radius: {distribution: uniform, min: 0.02, max: 0.06}}\n"
                                         "packer: {method: tet_mesh}\n");
  const RunResult r = run_frontpack(dir, "pack s.yaml -o out.csv");
  if (r.err.find("built without the tetrahedral mesher") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(run_frontpack(dir, "validate out.csv --scene s.yaml --ks-alpha 0").exit_code, 0);
  const auto tets = [](const std::string& out) {
    const auto at = out.find("tet mesh       ");
    return at == std::string::npos ? 0 : std::stoi(out.substr(at + 15));
  };
  EXPECT_GT(tets(r.out), 50);
  write_bytes(dir.work() / "fine.yaml", "dimension: 3\nseed: 1\ncontainer: {type: mesh, file: " + cube +
                                            "}\nparticles: {radius: {distribution: uniform, min: 0.02, max: 0.06}}\n"
                                            "packer: {method: tet_mesh, mesh_edge: 0.16}\n");
  const RunResult fine = run_frontpack(dir, "pack fine.yaml -o fine.csv");
  ASSERT_EQ(fine.exit_code, 0) << fine.err;
  EXPECT_GT(tets(fine.out), 4 * tets(r.out)) << "half the edge: about 8 times the tetrahedra";
  ASSERT_EQ(run_frontpack(dir, "pack s.yaml -o again.csv -q").exit_code, 0);
  EXPECT_EQ(read_bytes(dir.work() / "again.csv"), read_bytes(dir.work() / "out.csv")) << "the same mesh, the same spheres";
}

// A region whose law does not fit in it gets no sphere: the packing is valid but incomplete (exit 4).
TEST(CliTetMesh, ARegionLeftEmptyIsIncomplete) {
  TempDir dir;
  write_bytes(dir.work() / "s.yaml",
              scene_for(source_path("tests/data/meshes/msh/two_boxes_v4.1_binary.msh"),
                        "packer: {method: tet_mesh}\nregions:\n  upper: {radius: {distribution: uniform, min: 0.3, max: 0.4}}\n"));
  const RunResult r = run_frontpack(dir, "pack s.yaml -o out.csv");
  EXPECT_EQ(r.exit_code, 4) << r.out << r.err;
  EXPECT_NE(r.err.find("incomplete: the region upper holds no sphere"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir.work() / "out.csv")) << "a new path is written: the packing is valid";
}

TEST(CliTetMesh, RegionsKeepTheirOwnRadiiAndSolidFraction) {
  // The two physical volumes Gmsh wrote (lower z < 0.5, upper z > 0.5): the upper one with smaller
  // spheres and a lower solid fraction.
  TempDir dir;
  write_bytes(dir.work() / "s.yaml",
              scene_for(source_path("tests/data/meshes/msh/two_boxes_v4.1_binary.msh"),
                        "packer: {method: tet_mesh}\nregions:\n  upper: {radius: {distribution: uniform, min: 0.005, max: 0.03}, "
                        "volume_fraction: 0.45}\n  lower: {volume_fraction: 0.55}\n"));
  const RunResult r = run_frontpack(dir, "pack s.yaml -o out.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* line : {"region         upper: volume fraction 0.45", "region         lower: volume fraction 0.55"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << " in\n" << r.out;
  std::size_t upper = 0, lower = 0;
  for (const std::string& line : lines_of(read_bytes(dir.work() / "out.csv"))) {
    std::vector<double> v;
    if (!parse_numbers(line, ',', v) || v.size() != 5) continue;
    const double z = v[3], radius = v[4];
    if (std::abs(z - 0.5) <= 1e-9) continue;  // on the interface: either region's
    if (z > 0.5) {
      ++upper;
      EXPECT_GE(radius, 0.005);
      EXPECT_LE(radius, 0.03) << "a sphere centred in the upper region has its law";
    } else {
      ++lower;
      EXPECT_GE(radius, 0.01) << "a sphere centred in the lower region has the scene's law";
      EXPECT_LE(radius, 0.06);
    }
  }
  EXPECT_GT(upper, 3 * lower) << "smaller spheres above";
  EXPECT_EQ(run_frontpack(dir, "validate out.csv --scene s.yaml --ks-alpha 0").exit_code, 0);
}

TEST(CliTetMesh, BadMeshesAndMisplacedKeysExitTwoAndWriteNothing) {
  TempDir dir;
  const auto refused = [&](const std::string& scene, const std::string& message) {
    write_bytes(dir.work() / "s.yaml", scene);
    const RunResult r = run_frontpack(dir, "pack s.yaml -o out.csv");
    EXPECT_EQ(r.exit_code, 2) << message << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.work() / "out.csv")) << message;
  };
  // One tetrahedron, its last two nodes swapped: inverted.
  const std::string head = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n";
  write_bytes(dir.work() / "inverted.msh", head + "$Elements\n1\n1 4 2 1 1 1 2 4 3\n$EndElements\n");
  refused(scene_for("inverted.msh"), "inverted.msh");
  refused(scene_for("inverted.msh"), "inverted");
  // A file that ends inside its nodes.
  write_bytes(dir.work() / "short.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n");
  refused(scene_for("short.msh"), "short.msh");
  // A named volume without tetrahedra.
  write_bytes(dir.work() / "empty.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n3 1 \"full\"\n3 2 \"empty\"\n"
                                        "$EndPhysicalNames\n" + head.substr(head.find("$Nodes")) +
                                        "$Elements\n1\n1 4 2 1 1 1 2 3 4\n$EndElements\n");
  refused(scene_for("empty.msh"), "empty");
  // The packer needs a tetrahedral mesh; its parameters need the packer.
  refused("dimension: 3\ncontainer: {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
          "particles: {radius: {distribution: uniform, min: 0.01, max: 0.06}}\npacker: {method: tet_mesh}\n",
          "needs a tetrahedral mesh");
  refused(scene_for(source_path("tests/data/meshes/msh/cube_kuhn4.msh"), "packer: {z_min: 3}\n"), "needs 'method: tet_mesh'");
  refused(scene_for(source_path("tests/data/meshes/msh/cube_kuhn4.msh"), "packer: {method: tet_mesh, z_min: 5}\n"),
          "from 1 to 4");
  const std::string boxes = source_path("tests/data/meshes/msh/two_boxes_v2.2_ascii.msh");
  refused(scene_for(boxes, "packer: {method: tet_mesh}\nregions: {middle: {volume_fraction: 0.5}}\n"), "lower (11), upper (12)");
  refused(scene_for(boxes, "regions: {upper: {volume_fraction: 0.5}}\n"), "needs 'packer: {method: tet_mesh}'");
  refused(scene_for(boxes, "packer: {method: tet_mesh}\nregions: {upper: {volume_fraction: 1.5}}\n"), "regions.upper.volume_fraction");
  refused(scene_for(boxes, "packer: {method: tet_mesh}\nregions: {upper: {}, \"12\": {}}\n"), "the same physical volume");
  refused("dimension: 2\ncontainer: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
          "particles: {radius: {distribution: uniform, min: 0.01, max: 0.06}}\npacker: {method: tet_mesh}\n",
          "in 3D");
}

}  // namespace
}  // namespace fptest
