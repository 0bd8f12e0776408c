// MeshContainer: file formats, refusals, and the real femur against brute force (own ray
// parity and point-triangle distances, no CGAL), plus per-query timings (printed).
#include "core/geometry/mesh_container.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <set>
#include <thread>

#include "core/sampling/rng.hpp"
#include "tests/geometry/reference_geometry.hpp"

namespace fp {
namespace {

std::string data(const std::string& name) { return std::string(FRONTPACK_SOURCE_DIR) + "/tests/data/meshes/" + name; }

using Tris = std::vector<std::array<int, 3>>;

/// Axis-aligned cube [lo, lo + size]^3 as 12 outward triangles appended to (v, t).
void add_cube(std::vector<Vec3>& v, Tris& t, double lo, double size) {
  const int b = static_cast<int>(v.size());
  for (int k = 0; k < 8; ++k) v.emplace_back(lo + size * (k & 1), lo + size * ((k >> 1) & 1), lo + size * ((k >> 2) & 1));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    t.push_back({b + q[0], b + q[1], b + q[2]});
    t.push_back({b + q[0], b + q[2], b + q[3]});
  }
}

Vec3 centroid(const MeshContainer& m, int f) {
  const auto& t = m.triangles()[f];
  return (m.vertices()[t[0]] + m.vertices()[t[1]] + m.vertices()[t[2]]) / 3.0;
}

Vec3 outward_unit(const MeshContainer& m, int f) {
  const auto& t = m.triangles()[f];
  const auto& v = m.vertices();
  return (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized();
}

TEST(MeshContainer, CubeFromTrianglesWhateverTheOrientation) {
  std::vector<Vec3> v;
  Tris t;
  add_cube(v, t, 0.0, 1.0);
  Tris inverted = t, mixed = t;
  for (auto& f : inverted) std::swap(f[1], f[2]);
  for (std::size_t f = 0; f < mixed.size(); f += 3) std::swap(mixed[f][1], mixed[f][2]);
  for (const Tris& tris : {t, inverted, mixed}) {
    const auto m = MeshContainer::from_triangles(v, tris, "cube");
    EXPECT_NEAR(m->measure(), 1.0, 1e-14);
    EXPECT_EQ(m->num_facets(), 12u);
    for (int f = 0; f < 12; ++f) {
      const Vec3 n = outward_unit(*m, f);
      EXPECT_FALSE(m->inside(centroid(*m, f) + 1e-3 * n));
      EXPECT_TRUE(m->inside(centroid(*m, f) - 1e-3 * n));
    }
    EXPECT_NEAR(m->signed_distance(m->interior_point()), -0.5, 2e-3);  // the centre, to the search's precision
    EXPECT_NEAR(m->signed_distance(Vec3(0.5, 0.5, 0.9)), -0.1, 1e-14);
    EXPECT_NEAR(m->signed_distance(Vec3(1.3, 1.4, 0.5)), 0.5, 1e-14);
    EXPECT_EQ(m->signed_distance(Vec3(1.0, 0.3, 0.5)), 0.0);
    EXPECT_TRUE(m->inside(Vec3(1.0, 0.3, 0.5)));  // closed
  }
}

TEST(MeshContainer, CavityIsOrientedAndSubtracted) {
  // A cube [0,3]^3 with a cubic cavity [1,2]^3: volume 26, cavity facets face away from the cavity.
  std::vector<Vec3> v;
  Tris t;
  add_cube(v, t, 0.0, 3.0);
  add_cube(v, t, 1.0, 1.0);
  const auto m = MeshContainer::from_triangles(v, t, "hollow cube");
  EXPECT_NEAR(m->measure(), 26.0, 1e-12);
  EXPECT_FALSE(m->inside(Vec3::Constant(1.5)));
  EXPECT_TRUE(m->inside(Vec3(0.5, 1.5, 1.5)));
  EXPECT_NEAR(m->signed_distance(Vec3::Constant(1.5)), 0.5, 1e-14);
  std::vector<Wall<3>> walls;
  m->walls_near(Vec3(0.9, 1.5, 1.5), 0.2, walls);  // in the material, 0.1 from the cavity face x = 1
  ASSERT_EQ(walls.size(), 2u);                     // the two triangles of that face
  for (const auto& w : walls) {
    EXPECT_NEAR((w.normal - Vec3(-1, 0, 0)).norm(), 0.0, 1e-15);
    EXPECT_NEAR(w.gap(Vec3(0.9, 1.5, 1.5), 0.05), 0.05, 1e-14);
  }
}

TEST(MeshContainer, ReadsAsciiStlBinaryStlAndObj) {
  const auto cube = MeshContainer::from_file(data("cube.stl"));
  EXPECT_EQ(cube->vertices().size(), 8u);  // shared corners merged
  EXPECT_EQ(cube->num_facets(), 12u);
  EXPECT_NEAR(cube->measure(), 1.0, 1e-14);
  EXPECT_TRUE(cube->inside(Vec3(0.2, 0.7, 0.99)));
  EXPECT_FALSE(cube->inside(Vec3(0.2, 0.7, 1.01)));
  EXPECT_EQ(cube->describe(), "mesh cube.stl (12 facets, volume 1)");

  const auto doubled = MeshContainer::from_file(data("cube.stl"), 2.0);
  EXPECT_NEAR(doubled->measure(), 8.0, 1e-13);
  EXPECT_TRUE(doubled->inside(Vec3(1.9, 1.9, 1.9)));

  const auto oct = MeshContainer::from_file(data("octahedron_binary.stl"));
  EXPECT_EQ(oct->vertices().size(), 6u);
  EXPECT_EQ(oct->num_facets(), 8u);
  EXPECT_NEAR(oct->measure(), 4.0 / 3.0, 1e-14);
  EXPECT_NEAR(oct->signed_distance(Vec3::Zero()), -1.0 / std::sqrt(3.0), 1e-7);  // float coordinates

  const auto box = MeshContainer::from_file(data("box_quads.obj"));
  EXPECT_EQ(box->num_facets(), 12u);  // 6 quads, fan-triangulated
  EXPECT_NEAR(box->measure(), 1.0, 1e-14);
  EXPECT_NEAR(box->bounds().hi.x(), 2.0, 0.0);
  EXPECT_NEAR(box->signed_distance(Vec3(1.0, 0.5, 0.2)), -0.2, 1e-14);
}

TEST(MeshContainer, RefusesBadFilesNamingThem) {
  testref::expect_invalid([] { MeshContainer::from_file(data("open_cube.off")); },
                          {"mesh 'open_cube.off' is not closed: 4 boundary edges"});
  testref::expect_invalid([] { MeshContainer::from_file(data("nonmanifold_edge.off")); },
                          {"nonmanifold_edge.off", "not manifold: 1 non-manifold edges"});
  testref::expect_invalid([] { MeshContainer::from_file(data("nonmanifold_vertex.off")); },
                          {"nonmanifold_vertex.off", "not manifold: 1 non-manifold vertices"});
  testref::expect_invalid([] { MeshContainer::from_file(data("empty.off")); }, {"empty.off", "empty"});
  testref::expect_invalid([] { MeshContainer::from_file(data("no_such_file.off")); },
                          {"no_such_file.off", "cannot be read", "cannot open"});
  testref::expect_invalid([] { MeshContainer::from_file(data("README.md")); }, {"README.md", "unknown extension"});
  const std::string garbage = std::string(FRONTPACK_BINARY_DIR) + "/garbage_mesh_test.off";
  std::ofstream(garbage) << "this is not an OFF file\n1 2 three\n";
  testref::expect_invalid([&] { MeshContainer::from_file(garbage); }, {"garbage_mesh_test.off", "cannot be read"});
  testref::expect_invalid([] { MeshContainer::from_file(data("self_intersecting.off")); },
                          {"self_intersecting.off", "intersects itself"});
  testref::expect_invalid([] { MeshContainer::from_file(data("overlapping_cubes.off")); },
                          {"overlapping_cubes.off", "intersects itself"});
  testref::expect_invalid([] { MeshContainer::from_file(data("cube.stl"), 0.0); }, {"scale", "cube.stl"});
  testref::expect_invalid([] { MeshContainer::from_file(data("cube.stl"), std::nan("")); }, {"scale"});
}

/// The address space this process maps now (VmSize in /proc/self/status), in bytes.
rlim_t mapped_bytes() {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmSize:", 0) == 0) return static_cast<rlim_t>(std::stoull(line.substr(7))) * 1024;
  return 0;
}

// A mesh whose index would not fit is refused once its faces are counted, before anything large
// is built, naming the file, the faces and the limit that binds.
TEST(MeshContainer, RefusesAMeshTooLargeForTheMemoryLeft) {
  const int n = 100000;  // a fan of 100,000 triangles: about 50 MB to index
  const std::string path = std::string(FRONTPACK_BINARY_DIR) + "/mesh_too_large_test.off";
  {
    std::ofstream out(path);
    out << "OFF\n" << n + 2 << " " << n << " 0\n0 0 0\n";
    for (int i = 0; i <= n; ++i) out << std::cos(i * 1e-5) << " " << std::sin(i * 1e-5) << " 0\n";
    for (int i = 0; i < n; ++i) out << "3 0 " << i + 1 << " " << i + 2 << "\n";
  }
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &saved), 0);
  const rlim_t mapped = mapped_bytes();
  ASSERT_GT(mapped, 0u);
  const rlimit tight{mapped + (rlim_t{40} << 20), saved.rlim_max};  // 40 MB more than is mapped now
  ASSERT_EQ(setrlimit(RLIMIT_AS, &tight), 0);
  std::string message;
  try {
    MeshContainer::from_file(path);
  } catch (const std::invalid_argument& e) {
    message = e.what();
  }
  ASSERT_EQ(setrlimit(RLIMIT_AS, &saved), 0);
  for (const char* word : {"mesh_too_large_test.off", "100000 faces", "50 MB", "ulimit -v", "simplify the surface"})
    EXPECT_NE(message.find(word), std::string::npos) << "'" << word << "' not in: " << message;
  // Without the limit the same file gets past the memory check (and is refused as an open fan).
  testref::expect_invalid([&] { MeshContainer::from_file(path); }, {"mesh_too_large_test.off", "boundary edges"});
  std::remove(path.c_str());
}

// Shells that overlap are refused; shells that touch nowhere are a solid and its cavity, or two
// solids side by side.
TEST(MeshContainer, OverlappingShellsAreRefusedSeparateOnesAccepted) {
  for (const double second_lo : {0.5, 3.0}) {
    std::vector<Vec3> v;
    Tris t;
    add_cube(v, t, 0.0, 2.0);
    add_cube(v, t, second_lo, 2.0);
    if (second_lo < 2.0) testref::expect_invalid([&] { MeshContainer::from_triangles(v, t, "two"); }, {"two", "intersects itself"});
    else EXPECT_NEAR(MeshContainer::from_triangles(v, t, "two")->measure(), 16.0, 1e-12);
  }
}

TEST(MeshContainer, RefusesBadTriangles) {
  std::vector<Vec3> v;
  Tris t;
  add_cube(v, t, 0.0, 1.0);
  Tris out_of_range = t;
  out_of_range[3][1] = 8;
  testref::expect_invalid([&] { MeshContainer::from_triangles(v, out_of_range, "bad"); }, {"'bad'", "out of range"});
  std::vector<Vec3> nan_v = v;
  nan_v[2].y() = std::nan("");
  testref::expect_invalid([&] { MeshContainer::from_triangles(nan_v, t, "nanny"); }, {"'nanny'", "non-finite vertex 2"});
  // Two copies of one triangle, back to back: closed and manifold, but encloses nothing.
  testref::expect_invalid([] { MeshContainer::from_triangles({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)},
                                                             {{0, 1, 2}, {0, 2, 1}}, "flat"); },
                          {"'flat'"});
  testref::expect_invalid([] { MeshContainer::from_triangles({}, {}, "nothing"); }, {"'nothing'", "empty"});
}

class Femur : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { mesh_ = MeshContainer::from_file(data("femur.off")); }
  static void TearDownTestSuite() { mesh_.reset(); }
  static std::shared_ptr<MeshContainer> mesh_;

  /// Uniform in the bounding box grown by 5 % on each side.
  static Vec3 random_point(Rng& rng) {
    const Aabb<3> b = mesh_->bounds();
    const Vec3 pad = 0.05 * b.size();
    return Vec3(rng.uniform(b.lo.x() - pad.x(), b.hi.x() + pad.x()), rng.uniform(b.lo.y() - pad.y(), b.hi.y() + pad.y()),
                rng.uniform(b.lo.z() - pad.z(), b.hi.z() + pad.z()));
  }
  /// A point near the surface: a random point of a random facet, moved along its normal.
  static Vec3 random_near_surface(Rng& rng, double spread) {
    const auto& t = mesh_->triangles()[rng.below(mesh_->num_facets())];
    const auto& v = mesh_->vertices();
    double a = rng.uniform01(), b = rng.uniform01();
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const Vec3 p = v[t[0]] + a * (v[t[1]] - v[t[0]]) + b * (v[t[2]] - v[t[0]]);
    const Vec3 n = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized();
    return p + rng.uniform(-spread, spread) * n;
  }
  static double diag() { return mesh_->bounds().size().norm(); }
};
std::shared_ptr<MeshContainer> Femur::mesh_;

TEST_F(Femur, LoadsAsAClosedSurface) {
  EXPECT_EQ(mesh_->num_facets(), 7798u);
  EXPECT_EQ(mesh_->vertices().size(), 3897u);
  EXPECT_EQ(mesh_->dropped_degenerate_facets(), 0);
  EXPECT_GT(mesh_->measure(), 0.0);
  EXPECT_EQ(mesh_->describe().rfind("mesh femur.off (7798 facets, volume ", 0), 0u) << mesh_->describe();
  std::printf("[ info     ] %s\n", mesh_->describe().c_str());
}

TEST_F(Femur, InsideMatchesRayParity) {
  Rng rng(51);
  int inside = 0, compared = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p = i % 2 ? random_point(rng) : random_near_surface(rng, 0.02 * diag());
    if (std::abs(mesh_->signed_distance(p)) < 1e-9 * diag()) continue;  // on the surface: either answer is fine
    const bool ref = testref::inside_by_ray_parity(mesh_->vertices(), mesh_->triangles(), p);
    EXPECT_EQ(mesh_->inside(p), ref) << "p = " << p.transpose();
    inside += ref;
    ++compared;
  }
  EXPECT_GT(compared, 1900);
  EXPECT_GT(inside, 300);
}

TEST_F(Femur, SignedDistanceMatchesBruteForce) {
  Rng rng(52);
  for (int i = 0; i < 600; ++i) {
    const Vec3 p = i % 2 ? random_point(rng) : random_near_surface(rng, 0.05 * diag());
    const double ref = testref::mesh_distance(mesh_->vertices(), mesh_->triangles(), p);
    const double sd = mesh_->signed_distance(p);
    EXPECT_NEAR(std::abs(sd), ref, 1e-12 * diag());
    EXPECT_EQ(sd <= 0, mesh_->inside(p));
  }
}

TEST_F(Femur, FacetsAreOrientedOutward) {
  Rng rng(53);
  for (int k = 0; k < 300; ++k) {
    const int f = static_cast<int>(rng.below(mesh_->num_facets()));
    const auto& t = mesh_->triangles()[f];
    const auto& v = mesh_->vertices();
    const double size = std::min({(v[t[1]] - v[t[0]]).norm(), (v[t[2]] - v[t[1]]).norm(), (v[t[0]] - v[t[2]]).norm()});
    const Vec3 n = outward_unit(*mesh_, f), g = centroid(*mesh_, f);
    EXPECT_FALSE(testref::inside_by_ray_parity(v, mesh_->triangles(), g + 1e-3 * size * n)) << "facet " << f;
    EXPECT_TRUE(testref::inside_by_ray_parity(v, mesh_->triangles(), g - 1e-3 * size * n)) << "facet " << f;
  }
}

TEST_F(Femur, VolumeMatchesMonteCarlo) {
  Rng rng(54);
  const Aabb<3> b = mesh_->bounds();
  const int N = 200000;
  int hits = 0;
  for (int i = 0; i < N; ++i) {
    const Vec3 p(rng.uniform(b.lo.x(), b.hi.x()), rng.uniform(b.lo.y(), b.hi.y()), rng.uniform(b.lo.z(), b.hi.z()));
    hits += mesh_->inside(p);
  }
  const double frac = double(hits) / N, box = b.size().prod();
  const double sigma = box * std::sqrt(frac * (1 - frac) / N);
  EXPECT_NEAR(mesh_->measure(), frac * box, 4 * sigma);
  std::printf("[ info     ] femur volume %.6g, Monte Carlo %.6g +- %.2g\n", mesh_->measure(), frac * box, sigma);
}

TEST_F(Femur, WallsNearAreExactlyTheFacetsWithinReach) {
  Rng rng(55);
  std::vector<Wall<3>> walls;
  std::size_t total = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 p = random_near_surface(rng, 0.03 * diag());
    const double reach = rng.uniform(0.0, 0.04 * diag());
    walls.clear();
    mesh_->walls_near(p, reach, walls);
    std::set<int> got;
    for (const auto& w : walls) {
      ASSERT_EQ(w.kind, WallKind::Plane);
      got.insert(w.id);
      EXPECT_NEAR(w.normal.norm(), 1.0, 1e-12);
      EXPECT_NEAR(w.normal.dot(outward_unit(*mesh_, w.id)), -1.0, 1e-12);  // inward
      EXPECT_EQ(w.point, mesh_->vertices()[mesh_->triangles()[w.id][0]]);
    }
    EXPECT_EQ(got.size(), walls.size());
    for (std::size_t f = 0; f < mesh_->num_facets(); ++f) {
      const auto& t = mesh_->triangles()[f];
      const double d = testref::triangle_distance(p, mesh_->vertices()[t[0]], mesh_->vertices()[t[1]], mesh_->vertices()[t[2]]);
      if (d <= reach * (1 - 1e-9)) { EXPECT_TRUE(got.count(static_cast<int>(f))) << "facet " << f << " at " << d; }
      if (d > reach * (1 + 1e-9)) { EXPECT_FALSE(got.count(static_cast<int>(f))) << "facet " << f << " at " << d; }
    }
    total += walls.size();
  }
  EXPECT_GT(total, 1000u);
}

TEST_F(Femur, WallGapAgreesWithSignedDistanceNearASingleFacet) {
  Rng rng(56);
  std::vector<Wall<3>> walls;
  int checked = 0;
  for (int k = 0; k < 3000; ++k) {
    const int f = static_cast<int>(rng.below(mesh_->num_facets()));
    const auto& t = mesh_->triangles()[f];
    const auto& v = mesh_->vertices();
    const double size = std::min({(v[t[1]] - v[t[0]]).norm(), (v[t[2]] - v[t[1]]).norm(), (v[t[0]] - v[t[2]]).norm()});
    const Vec3 c = centroid(*mesh_, f) - rng.uniform(0.01, 0.2) * size * outward_unit(*mesh_, f);
    const double sd = mesh_->signed_distance(c);
    if (sd >= 0) continue;
    walls.clear();
    mesh_->walls_near(c, -sd * (1 + 1e-9), walls);
    if (walls.size() != 1) continue;  // then the nearest point is inside that facet (maybe not f)
    const double r = rng.uniform(0.0, -sd);
    EXPECT_NEAR(walls[0].gap(c, r), -sd - r, 1e-12 * diag());
    EXPECT_TRUE(mesh_->contains_ball(c, r));
    EXPECT_FALSE(mesh_->contains_ball(c, -sd * (1 + 1e-6)));
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST_F(Femur, ContainsBallAgreesWithSignedDistance) {
  Rng rng(59);
  int accepted = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 c = random_near_surface(rng, 0.03 * diag());
    const double r = rng.uniform(0.0, 0.03 * diag());
    const bool expected = mesh_->signed_distance(c) <= -r + 1e-9 * r;
    EXPECT_EQ(mesh_->contains_ball(c, r), expected) << "c = " << c.transpose() << ", r = " << r;
    accepted += expected;
  }
  EXPECT_GT(accepted, 500);
}

TEST_F(Femur, InteriorPointIsInsideDeepAndReproducible) {
  const Vec3 p = mesh_->interior_point();
  EXPECT_TRUE(mesh_->inside(p));
  EXPECT_GT(-mesh_->signed_distance(p), 0.02 * diag());
  EXPECT_EQ(MeshContainer::from_file(data("femur.off"))->interior_point(), p);
}

TEST_F(Femur, ConstQueriesFromTwoThreadsAgree) {
  Rng rng(57);
  std::vector<Vec3> pts(4000);
  for (auto& p : pts) p = random_near_surface(rng, 0.02 * diag());
  std::vector<double> expected(pts.size()), got(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) expected[i] = mesh_->signed_distance(pts[i]);
  auto work = [&](std::size_t begin) {
    std::vector<Wall<3>> walls;
    for (std::size_t i = begin; i < pts.size(); i += 2) {
      got[i] = mesh_->signed_distance(pts[i]);
      mesh_->walls_near(pts[i], 0.01 * diag(), walls);
    }
  };
  std::thread a(work, 0), b(work, 1);
  a.join();
  b.join();
  EXPECT_EQ(got, expected);
}

TEST_F(Femur, TimingPerQuery) {
  // Printed, not asserted: the numbers go into the design notes.
  Rng rng(58);
#ifdef NDEBUG
  const int N = 20000;
#else
  const int N = 500;  // unoptimised builds only check that the loop runs
#endif
  std::vector<Vec3> box_pts(N), near_pts(N);
  for (auto& p : box_pts) p = random_point(rng);
  for (auto& p : near_pts) p = random_near_surface(rng, 0.02 * diag());
  auto per_query_ns = [&](const std::vector<Vec3>& pts, auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    for (const Vec3& p : pts) f(p);
    return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / pts.size();
  };
  double sink = 0;
  std::vector<Wall<3>> walls;
  const double reach_small = 0.01 * diag(), reach_large = 0.05 * diag();
  const double t_in_box = per_query_ns(box_pts, [&](const Vec3& p) { sink += mesh_->inside(p); });
  const double t_in_near = per_query_ns(near_pts, [&](const Vec3& p) { sink += mesh_->inside(p); });
  const double t_sd_box = per_query_ns(box_pts, [&](const Vec3& p) { sink += mesh_->signed_distance(p); });
  const double t_sd_near = per_query_ns(near_pts, [&](const Vec3& p) { sink += mesh_->signed_distance(p); });
  const double t_cb = per_query_ns(near_pts, [&](const Vec3& p) { sink += mesh_->contains_ball(p, reach_small); });
  std::size_t n_small = 0, n_large = 0;
  const double t_w_small = per_query_ns(near_pts, [&](const Vec3& p) {
    walls.clear();
    mesh_->walls_near(p, reach_small, walls);
    n_small += walls.size();
  });
  const double t_w_large = per_query_ns(near_pts, [&](const Vec3& p) {
    walls.clear();
    mesh_->walls_near(p, reach_large, walls);
    n_large += walls.size();
  });
  std::printf("[ timing   ] femur (%zu facets, bbox diagonal %.4g), ns/query:\n", mesh_->num_facets(), diag());
  std::printf("[ timing   ]   inside           %8.0f (bbox points)  %8.0f (near surface)\n", t_in_box, t_in_near);
  std::printf("[ timing   ]   signed_distance  %8.0f (bbox points)  %8.0f (near surface)\n", t_sd_box, t_sd_near);
  std::printf("[ timing   ]   contains_ball    %8.0f (near surface, r = 1%% diag)\n", t_cb);
  std::printf("[ timing   ]   walls_near       %8.0f (reach 1%% diag, %.1f walls)  %8.0f (reach 5%% diag, %.1f walls)\n",
              t_w_small, double(n_small) / N, t_w_large, double(n_large) / N);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
}  // namespace fp
