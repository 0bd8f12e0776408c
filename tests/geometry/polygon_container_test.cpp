// PolygonContainer against brute force: distance to every edge, winding number by angle sums;
// and against the loops over every edge it ran before its edges were indexed, double for double.
#include "core/geometry/polygon_container.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

#include "core/sampling/rng.hpp"
#include "tests/geometry/polygon_loops.hpp"
#include "tests/geometry/reference_geometry.hpp"

namespace fp {
namespace {

std::vector<Vec2> l_shape() {  // area 3: a 2x2 square minus the unit square at its top right
  return {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)};
}

std::vector<Vec2> star(int points, double r_in, double r_out, const Vec2& c) {
  std::vector<Vec2> v;
  for (int k = 0; k < 2 * points; ++k) {
    const double phi = kPi * k / points;
    const double r = k % 2 ? r_in : r_out;
    v.emplace_back(c.x() + r * std::cos(phi), c.y() + r * std::sin(phi));
  }
  return v;
}

/// A random star-shaped (hence simple) polygon, clockwise.
std::vector<Vec2> random_star_shaped(Rng& rng, int n) {
  std::vector<double> angles(n);
  for (double& a : angles) a = rng.uniform(0.0, 2 * kPi);
  std::sort(angles.begin(), angles.end(), std::greater<>());
  std::vector<Vec2> v;
  for (double a : angles) {
    const double r = rng.uniform(0.2, 1.0);
    v.emplace_back(3.0 + r * std::cos(a), -1.0 + r * std::sin(a));
  }
  return v;
}

double shoelace(const std::vector<Vec2>& v) {
  double s = 0;
  for (std::size_t i = 0; i < v.size(); ++i) s += v[i].x() * v[(i + 1) % v.size()].y() - v[(i + 1) % v.size()].x() * v[i].y();
  return 0.5 * s;
}

void check_against_brute_force(const std::vector<Vec2>& input, std::uint64_t seed) {
  const PolygonContainer poly(input);
  const Aabb<2> b = poly.bounds();
  const Vec2 pad = 0.2 * b.size();
  Rng rng(seed);
  int inside = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec2 p(rng.uniform(b.lo.x() - pad.x(), b.hi.x() + pad.x()), rng.uniform(b.lo.y() - pad.y(), b.hi.y() + pad.y()));
    const double dist = testref::polygon_boundary_distance(input, p);
    const bool in = testref::winding_by_angles(input, p) != 0;
    if (dist > 1e-12) {
      EXPECT_EQ(poly.inside(p), in) << "p = " << p.transpose();
      EXPECT_NEAR(poly.signed_distance(p), in ? -dist : dist, 1e-13);
    }
    inside += in;
  }
  EXPECT_GT(inside, 200);
  // The vertices and edge midpoints are on the (closed) boundary.
  for (std::size_t i = 0; i < input.size(); ++i) {
    EXPECT_TRUE(poly.inside(input[i]));
    EXPECT_EQ(poly.signed_distance(input[i]), 0.0);
    const Vec2 mid = 0.5 * (input[i] + input[(i + 1) % input.size()]);
    EXPECT_TRUE(poly.inside(mid) || std::abs(poly.signed_distance(mid)) < 1e-15);
  }
}

TEST(PolygonContainer, LShapeAgainstBruteForce) { check_against_brute_force(l_shape(), 41); }
TEST(PolygonContainer, StarAgainstBruteForce) { check_against_brute_force(star(7, 0.4, 1.0, Vec2(-2, 5)), 42); }
TEST(PolygonContainer, RandomPolygonsAgainstBruteForce) {
  Rng rng(43);
  for (int k = 0; k < 10; ++k) check_against_brute_force(random_star_shaped(rng, 5 + 4 * k), 100 + k);
}

TEST(PolygonContainer, OrientationIsNormalisedAndReflexCornersFound) {
  std::vector<Vec2> cw = l_shape();
  std::reverse(cw.begin(), cw.end());
  const PolygonContainer poly(cw);
  EXPECT_GT(shoelace(poly.vertices()), 0.0);  // stored counter-clockwise
  int reflex = 0;
  for (int i = 0; i < 6; ++i) reflex += poly.is_reflex(i);
  EXPECT_EQ(reflex, 1);
  const PolygonContainer s(star(5, 0.3, 1.0, Vec2::Zero()));
  reflex = 0;
  for (int i = 0; i < 10; ++i) reflex += s.is_reflex(i);
  EXPECT_EQ(reflex, 5);
}

TEST(PolygonContainer, MeasureAgainstClosedFormAndMonteCarlo) {
  EXPECT_NEAR(PolygonContainer(l_shape()).measure(), 3.0, 1e-14);
  // Regular star: 2n triangles (centre, outer, inner) of area r_in r_out sin(pi/n) / 2.
  const int n = 6;
  const double ri = 0.45, ro = 1.3;
  const PolygonContainer s(star(n, ri, ro, Vec2(1e3, -2e3)));  // far from the origin on purpose
  EXPECT_NEAR(s.measure(), 2 * n * 0.5 * ri * ro * std::sin(kPi / n), 1e-10);

  Rng rng(44);
  const std::vector<Vec2> v = random_star_shaped(rng, 23);
  const PolygonContainer p(v);
  const Aabb<2> b = p.bounds();
  const int N = 200000;
  int hits = 0;
  for (int i = 0; i < N; ++i) {
    const Vec2 q(rng.uniform(b.lo.x(), b.hi.x()), rng.uniform(b.lo.y(), b.hi.y()));
    hits += testref::winding_by_angles(v, q) != 0;
  }
  const double frac = double(hits) / N, box = b.size().prod();
  const double sigma = box * std::sqrt(frac * (1 - frac) / N);
  EXPECT_NEAR(p.measure(), frac * box, 4 * sigma);
  EXPECT_NEAR(p.measure(), std::abs(shoelace(v)), 1e-13);
}

TEST(PolygonContainer, WallsNearAreExactlyTheEdgesAndReflexCornersWithinReach) {
  Rng rng(45);
  for (const auto& input : {l_shape(), star(7, 0.4, 1.0, Vec2(-2, 5)), random_star_shaped(rng, 30)}) {
    const PolygonContainer poly(input);
    const auto& v = poly.vertices();
    const int n = static_cast<int>(v.size());
    const Aabb<2> b = poly.bounds();
    std::vector<Wall<2>> walls;
    for (int i = 0; i < 2000; ++i) {
      const Vec2 p(rng.uniform(b.lo.x() - 0.2, b.hi.x() + 0.2), rng.uniform(b.lo.y() - 0.2, b.hi.y() + 0.2));
      const double reach = rng.uniform(0.0, 0.6);
      walls.clear();
      poly.walls_near(p, reach, walls);
      std::set<int> got;
      for (const auto& w : walls) {
        got.insert(w.id);
        if (w.id < n) {
          ASSERT_EQ(w.kind, WallKind::Plane);
          // Inward: the edge midpoint nudged along the normal is inside.
          const Vec2 mid = 0.5 * (v[w.id] + v[(w.id + 1) % n]);
          EXPECT_TRUE(testref::winding_by_angles(v, mid + 1e-6 * w.normal) != 0);
          EXPECT_NEAR(w.normal.norm(), 1.0, 1e-15);
          EXPECT_NEAR(w.normal.dot(v[(w.id + 1) % n] - v[w.id]), 0.0, 1e-14);
        } else {
          ASSERT_EQ(w.kind, WallKind::Vertex);
          EXPECT_EQ(w.point, v[w.id - n]);
        }
      }
      EXPECT_EQ(got.size(), walls.size());
      for (int e = 0; e < n; ++e) {
        const double d = testref::segment_distance<2>(p, v[e], v[(e + 1) % n]);
        if (d <= reach * (1 - 1e-12)) { EXPECT_TRUE(got.count(e)); }
        if (d > reach * (1 + 1e-12)) { EXPECT_FALSE(got.count(e)); }
        // Reflex: the turn at vertex e is clockwise in the counter-clockwise polygon.
        const Vec2 a = v[(e + n - 1) % n] - v[e], c = v[(e + 1) % n] - v[e];
        const bool reflex = a.x() * c.y() - a.y() * c.x() > 0;
        const double dv = (p - v[e]).norm();
        if (reflex && dv <= reach * (1 - 1e-12)) { EXPECT_TRUE(got.count(n + e)); }
        if (!reflex || dv > reach * (1 + 1e-12)) { EXPECT_FALSE(got.count(n + e)); }
      }
    }
  }
}

TEST(PolygonContainer, WallGapsAgreeWithSignedDistance) {
  const PolygonContainer poly(star(7, 0.4, 1.0, Vec2(-2, 5)));
  const int n = 14;
  Rng rng(46);
  std::vector<Wall<2>> walls;
  int single_edge = 0, corner = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec2 c(rng.uniform(-3, -1), rng.uniform(4, 6));
    const double sd = poly.signed_distance(c);
    if (sd >= 0) continue;
    const double r = rng.uniform(0.0, -sd);
    walls.clear();
    poly.walls_near(c, -sd * (1 + 1e-9), walls);
    if (walls.size() == 1) {  // near a single edge: its line gives the clearance
      EXPECT_NEAR(walls[0].gap(c, r), -sd - r, 1e-13);
      ++single_edge;
    }
    for (const auto& w : walls)
      if (w.kind == WallKind::Vertex && std::abs((c - w.point).norm() + sd) < 1e-12) {
        EXPECT_NEAR(w.gap(c, r), -sd - r, 1e-13);  // nearest feature is the reflex corner itself
        ++corner;
      }
    for (const auto& w : walls)
      if (w.kind == WallKind::Vertex) { EXPECT_GE(w.id, n); }
  }
  EXPECT_GT(single_edge, 1000);
  EXPECT_GT(corner, 50);
}

TEST(PolygonContainer, InteriorPointIsDeep) {
  const PolygonContainer square({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)});
  EXPECT_NEAR(square.signed_distance(square.interior_point()), -0.5, 2e-4);
  const PolygonContainer l(l_shape());
  // Against the deepest point of a dense grid.
  double best = 0;
  for (int i = 0; i <= 400; ++i)
    for (int j = 0; j <= 400; ++j) best = std::max(best, -l.signed_distance(Vec2(2.0 * i / 400, 2.0 * j / 400)));
  EXPECT_TRUE(l.inside(l.interior_point()));
  EXPECT_GE(-l.signed_distance(l.interior_point()), best - 2e-4);
}

TEST(PolygonContainer, DescribeSaysWhatItIs) {
  EXPECT_EQ(PolygonContainer(l_shape()).describe(), "polygon (6 vertices, area 3)");
}

TEST(PolygonContainer, ImpossiblePolygonsAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  testref::expect_invalid([] { PolygonContainer({Vec2(0, 0), Vec2(1, 0)}); }, {"vertices", "at least 3"});
  testref::expect_invalid([] { PolygonContainer({Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)}); }, {"vertices", "zero area"});
  testref::expect_invalid([] { PolygonContainer({Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(0, 1)}); },
                          {"vertices", "same point"});
  testref::expect_invalid([] { PolygonContainer({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 0), Vec2(-1, 1)}); },
                          {"same point"});
  testref::expect_invalid([] { PolygonContainer({Vec2(0, 0), Vec2(2, 2), Vec2(2, 0), Vec2(0, 1)}); },  // bow-tie
                          {"vertices", "intersect"});
  testref::expect_invalid([] { PolygonContainer({Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)}); },  // zero area
                          {"vertices", "intersect"});
  testref::expect_invalid([] { PolygonContainer({Vec2(0, 0), Vec2(2, 0), Vec2(1, 0), Vec2(1, 1)}); },  // spike
                          {"vertices", "self-intersecting"});
  testref::expect_invalid([] { PolygonContainer({Vec2(0, 0), Vec2(4, 0), Vec2(4, 4), Vec2(2, 0.0), Vec2(0, 4)}); },
                          {"intersect"});  // a vertex touching another edge
  testref::expect_invalid([&] { PolygonContainer({Vec2(0, 0), Vec2(1, nan), Vec2(0, 1)}); }, {"vertex 1", "finite"});
}

// --- The indexed queries against the loops they replaced (polygon_loops.hpp), double for double.

/// A regular n-gon.
std::vector<Vec2> regular(int n, double radius, const Vec2& c) {
  std::vector<Vec2> v;
  for (int k = 0; k < n; ++k) v.push_back(c + radius * Vec2(std::cos(2 * kPi * k / n), std::sin(2 * kPi * k / n)));
  return v;
}

/// A wavy coastline around c with a fine zig-zag on top of it (n even): non-convex at two scales.
std::vector<Vec2> coastline(int n, const Vec2& c) {
  std::vector<Vec2> v;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / n;
    const double r = 0.5 * (1 + 0.1 * std::sin(7 * a) + 0.03 * std::sin(53 * a)) + (k % 2 ? 0.002 : -0.002);
    v.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
  }
  return v;
}

/// A comb: `teeth` thin vertical slots cut into the top of the unit square, so that a horizontal
/// ray through the slots crosses about 4 * teeth edges.
std::vector<Vec2> comb(int teeth) {
  std::vector<Vec2> v{Vec2(0, 0), Vec2(1, 0)};
  for (int k = teeth - 1; k >= 0; --k) {
    const double x0 = (k + 0.25) / teeth, x1 = (k + 0.75) / teeth;
    v.insert(v.end(), {Vec2(x1 + 0.25 / teeth, 1), Vec2(x1, 1), Vec2(x1, 0.3), Vec2(x0, 0.3), Vec2(x0, 1)});
  }
  v.emplace_back(0, 1);
  return v;
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

void expect_same_walls(const std::vector<Wall<2>>& got, const std::vector<Wall<2>>& want, const Vec2& p) {
  ASSERT_EQ(got.size(), want.size()) << "p = " << p.transpose();
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_EQ(got[k].id, want[k].id);
    EXPECT_EQ(got[k].kind, want[k].kind);
    EXPECT_EQ(got[k].point, want[k].point);
    EXPECT_EQ(got[k].normal, want[k].normal);
  }
}

/// Random points over the padded box (some at a vertex's height), points within 1e-12 (relative)
/// of edges and vertices, the vertices and edge midpoints themselves, and points about the
/// interior point.
std::vector<Vec2> probe_points(const PolygonContainer& poly, Rng& rng, int count) {
  const auto& v = poly.vertices();
  const int n = static_cast<int>(v.size());
  const Aabb<2> b = poly.bounds();
  const double scale = b.size().norm();
  std::vector<Vec2> out;
  for (int k = 0; k < count; ++k) {
    const int i = static_cast<int>(rng.uniform(0.0, n - 1e-9));
    const Vec2 a = v[i], c = v[(i + 1) % n];
    const Vec2 normal = Vec2(a.y() - c.y(), c.x() - a.x()).normalized();
    switch (k % 6) {
      case 0: out.emplace_back(rng.uniform(b.lo.x() - 0.2 * scale, b.hi.x() + 0.2 * scale),
                               rng.uniform(b.lo.y() - 0.2 * scale, b.hi.y() + 0.2 * scale)); break;
      case 1: out.emplace_back(rng.uniform(b.lo.x() - 0.2 * scale, b.hi.x() + 0.2 * scale), a.y()); break;
      case 2: out.push_back(a + rng.uniform(0.0, 1.0) * (c - a) + rng.uniform(-1e-12, 1e-12) * scale * normal); break;
      case 3: out.push_back(a + scale * Vec2(rng.uniform(-1e-12, 1e-12), rng.uniform(-1e-12, 1e-12))); break;
      case 4: out.push_back(k % 12 == 4 ? a : Vec2(0.5 * (a + c))); break;
      case 5: out.push_back(poly.interior_point() + 1e-3 * scale * Vec2(rng.uniform(-1, 1), rng.uniform(-1, 1))); break;
    }
  }
  return out;
}

void expect_queries_equal_the_loops(const std::vector<Vec2>& input, const Vec2& origin, std::uint64_t seed, int count) {
  const PolygonContainer poly(input, origin);
  const auto& v = poly.vertices();
  Rng rng(seed);
  std::vector<Wall<2>> walls;
  int in = 0, out = 0;
  for (const Vec2& p : probe_points(poly, rng, count)) {
    const double sd = loops::signed_distance(v, p);
    ASSERT_EQ(bits(poly.signed_distance(p)), bits(sd)) << "p = " << p.transpose();
    ASSERT_EQ(poly.inside(p), loops::locate(v, p, nullptr)) << "p = " << p.transpose();
    (sd < 0 ? in : out) += 1;
    const double d = std::abs(sd);
    for (const double r : {d, d * (1 - 1e-9), d * (1 + 1e-9), std::nextafter(d, 0.0), rng.uniform(0.0, 0.1) * poly.bounds().size().norm(), 0.0})
      for (const double tol : {1e-9, 0.0, 2.0})
        ASSERT_EQ(poly.contains_ball(p, r, tol), sd <= -r + tol * r) << "p = " << p.transpose() << ", r = " << r;
    const double reach = 0.3 * poly.bounds().size().norm() * rng.uniform(0.0, 1.0);
    walls.clear();
    poly.walls_near(p, reach, walls);
    expect_same_walls(walls, loops::walls_near(v, p, reach), p);
  }
  EXPECT_GT(in, count / 10);
  EXPECT_GT(out, count / 10);
}

TEST(PolygonContainerIndexed, SmallPolygonsEqualTheLoops) {
  expect_queries_equal_the_loops(l_shape(), Vec2::Zero(), 50, 3000);
  expect_queries_equal_the_loops(star(7, 0.4, 1.0, Vec2(-2, 5)), Vec2(-2, 5), 51, 3000);
  Rng rng(52);
  for (int k = 0; k < 6; ++k) expect_queries_equal_the_loops(random_star_shaped(rng, 9 + 40 * k), Vec2::Zero(), 53 + k, 600);
}

TEST(PolygonContainerIndexed, FineRegularPolygonEqualsTheLoops) {
  expect_queries_equal_the_loops(regular(20000, 0.5, Vec2(3, 4)), Vec2(3, 4), 60, 300);
}

TEST(PolygonContainerIndexed, FineCoastlineEqualsTheLoops) {
  expect_queries_equal_the_loops(coastline(20000, Vec2(1e6, -2e6)), Vec2(1e6, -2e6), 61, 300);
}

TEST(PolygonContainerIndexed, FineStarEqualsTheLoops) {
  // 10^4 teeth 0.05 deep and 3e-4 wide: a point on a tooth is in the boxes of hundreds of others.
  expect_queries_equal_the_loops(star(10000, 0.45, 0.5, Vec2(-1, 2)), Vec2::Zero(), 66, 300);
}

TEST(PolygonContainerIndexed, CombEqualsTheLoops) {
  expect_queries_equal_the_loops(comb(500), Vec2::Zero(), 62, 600);
  // Points in the slots' band, where the ray crosses many edges, and exactly on slot walls.
  const PolygonContainer poly(comb(500));
  Rng rng(63);
  for (int k = 0; k < 300; ++k) {
    const Vec2 p(k % 3 ? rng.uniform(-0.1, 1.1) : (std::floor(rng.uniform(0, 500)) + 0.25) / 500, rng.uniform(0.29, 1.01));
    ASSERT_EQ(bits(poly.signed_distance(p)), bits(loops::signed_distance(poly.vertices(), p))) << p.transpose();
  }
}

TEST(PolygonContainerIndexed, NonFinitePointsEqualTheLoops) {
  const PolygonContainer poly(l_shape());
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const Vec2& p : {Vec2(nan, 1), Vec2(1, nan), Vec2(inf, 1), Vec2(1, -inf)}) {
    EXPECT_EQ(bits(poly.signed_distance(p)), bits(loops::signed_distance(poly.vertices(), p)));
    EXPECT_EQ(poly.inside(p), loops::locate(poly.vertices(), p, nullptr));
    EXPECT_EQ(poly.contains_ball(p, 0.1), loops::signed_distance(poly.vertices(), p) <= -0.1 + 1e-9 * 0.1);
  }
  std::vector<Wall<2>> walls;
  poly.walls_near(Vec2(1, 1), nan, walls);
  EXPECT_TRUE(walls.empty());
  poly.walls_near(Vec2(1, 1), -0.5, walls);  // the loops square the reach
  expect_same_walls(walls, loops::walls_near(poly.vertices(), Vec2(1, 1), -0.5), Vec2(1, 1));
}

TEST(PolygonContainerIndexed, ManyReflexCornersWithinReachComeAfterTheEdgesInOrder) {
  const PolygonContainer poly(star(100, 0.9, 1.0, Vec2::Zero()));  // 100 reflex corners, all within 1.0
  std::vector<Wall<2>> walls;
  poly.walls_near(Vec2::Zero(), 1.0, walls);
  expect_same_walls(walls, loops::walls_near(poly.vertices(), Vec2::Zero(), 1.0), Vec2::Zero());
  EXPECT_EQ(walls.size(), 300u);
}

// The simplicity test (an exact sweep) decides as the floating-point test of every pair did,
// whenever that one is exact: on small integer coordinates every orient() is.
TEST(PolygonContainerIndexed, SimplicityDecisionEqualsEveryPairOnGridPolygons) {
  Rng rng(64);
  int simple = 0, refused = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const int n = 3 + trial % 7;
    std::vector<Vec2> v;
    for (int k = 0; k < n; ++k) v.emplace_back(std::floor(rng.uniform(0, 5)), std::floor(rng.uniform(0, 5)));
    std::set<std::pair<double, double>> distinct;
    for (const Vec2& p : v) distinct.insert({p.x(), p.y()});
    if (distinct.size() < v.size()) continue;
    double twice_area = 0;
    for (int k = 0; k < n; ++k) twice_area += v[k].x() * v[(k + 1) % n].y() - v[(k + 1) % n].x() * v[k].y();
    const bool want = twice_area != 0 && loops::is_simple(v);
    bool got = true;
    try {
      PolygonContainer poly(v);
    } catch (const std::invalid_argument&) {
      got = false;
    }
    ASSERT_EQ(got, want) << "polygon of " << n << " vertices, first " << v[0].transpose();
    (got ? simple : refused) += 1;
  }
  EXPECT_GT(simple, 500);
  EXPECT_GT(refused, 2000);
}

TEST(PolygonContainerIndexed, SimplicityDecisionEqualsEveryPairOnRandomPolygons) {
  Rng rng(65);
  int simple = 0, refused = 0;
  for (int trial = 0; trial < 1200; ++trial) {
    std::vector<Vec2> v = random_star_shaped(rng, 5 + trial % 40);
    if (trial % 2) std::swap(v[0], v[1 + trial % (v.size() - 1)]);  // usually makes it cross itself
    bool got = true;
    try {
      PolygonContainer poly(v);
    } catch (const std::invalid_argument& e) {
      got = false;
      EXPECT_NE(std::string(e.what()).find("self-intersect"), std::string::npos) << e.what();
    }
    ASSERT_EQ(got, loops::is_simple(v)) << "trial " << trial;
    (got ? simple : refused) += 1;
  }
  EXPECT_GT(simple, 500);
  EXPECT_GT(refused, 400);
}

TEST(PolygonContainerIndexed, StraightVerticesAndAManyVertexCombAreAccepted) {
  // Collinear consecutive vertices (a straight angle) are fine; they are not reflex.
  const PolygonContainer square({Vec2(0, 0), Vec2(0.5, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)});
  EXPECT_FALSE(square.is_reflex(1));
  EXPECT_NEAR(square.measure(), 1.0, 1e-15);
  // A comb on its side: 40000 long horizontal edges whose x-ranges all overlap (a sweep over x
  // alone tested 10^9 pairs here).
  auto sideways = [](std::vector<Vec2> v) {
    for (Vec2& p : v) std::swap(p.x(), p.y());
    return v;
  };
  const PolygonContainer teeth(sideways(comb(20000)));
  EXPECT_EQ(teeth.vertices().size(), 100003u);
  testref::expect_invalid([&] {
    std::vector<Vec2> c = comb(20000);
    c[50001].x() += 0.6 / 20000;  // one slot wall into its neighbour
    PolygonContainer p(sideways(c));
  }, {"edges", "intersect"});
}

}  // namespace
}  // namespace fp
