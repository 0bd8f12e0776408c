// FCL parts against references built only from our support functions. For convex bodies A and B
// the signed distance is max over unit u of g(u) = -(h_A(u) + h_B(-u)) (separating planes; any u
// gives a lower bound). In 2D a dense scan of the circle plus local refinement finds it, apart
// or overlapping. In 3D, for bodies apart, it is a concave maximisation over the unit ball,
// solved by the ellipsoid method with the support points as subgradients.
// 3D overlaps are checked for polytope pairs against the exact Minkowski difference (hull of the
// pairwise vertex differences). Clusters are the union of their members: least over member pairs.
// 2D bodies go through the z = 0 embedding (fcl_embedding.hpp) and meet the 2D reference.
//
// FCL's GJK stops at distance_tolerance (default 1e-6), which leaves errors up to ~1e-5 of the
// size on curved shapes; these tests tighten it to see our geometry, not GJK's stopping.
#include <gtest/gtest.h>

#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <functional>
#include <random>

#include "shape_test_support.hpp"
#include "shapes/cluster_shape.hpp"
#include "shapes/convex_hull_3.hpp"
#include "shapes/convex_polytope_shape.hpp"
#include "shapes/fcl_embedding.hpp"

namespace fp {
namespace {

template <int D>
struct Body {
  ShapePtr<D> shape;
  Pose<D> pose;
};

/// A convex piece in the world frame: its support point along u.
template <int D>
using SupportPoint = std::function<Vec<D>(const Vec<D>&)>;

template <int D>
std::vector<SupportPoint<D>> pieces(const Body<D>& b) {
  std::vector<SupportPoint<D>> out;
  if (auto cluster = std::dynamic_pointer_cast<const ClusterShape<D>>(b.shape)) {
    for (const Ball<D>& m : cluster->members()) {
      const Vec<D> c = b.pose.to_world(m.center);
      const double r = m.radius;
      out.push_back([c, r](const Vec<D>& u) { return Vec<D>(c + r * u.normalized()); });
    }
  } else {
    out.push_back([b](const Vec<D>& u) { return b.pose.to_world(b.shape->support(b.pose.direction_to_body(u))); });
  }
  return out;
}

/// max over unit u of -(h_A(u) + h_B(-u)) for separated 3D convex pieces: ellipsoid method on
/// the unit ball (the objective is concave there); returns the best value at a unit direction.
template <int D>
double ellipsoid_method_max(const SupportPoint<D>& sa, const SupportPoint<D>& sb) {
  auto g = [&](const Vec<D>& u) { return -(u.dot(sa(u)) - u.dot(sb(-u))); };
  using M = Eigen::Matrix<double, D, D>;
  Vec<D> c = Vec<D>::Zero();
  M P = M::Identity() * 1.21;  // contains the unit ball
  double best = -1e300;
  constexpr double n = D;
  for (int it = 0; it < 2000; ++it) {
    Vec<D> cut;  // keep the half {x : cut . (x - c) <= 0}
    if (c.norm() > 1) {
      cut = c.normalized();
    } else {
      if (c.norm() > 0) best = std::max(best, g(c.normalized()));
      cut = sa(c) - sb(-c);  // = -(a subgradient of the objective)
      if (c.norm() == 0) cut = sa(Vec<D>::UnitX()) - sb(-Vec<D>::UnitX());
    }
    const double q = cut.dot(P * cut);
    if (!(q > 1e-26)) break;
    const Vec<D> b = P * cut / std::sqrt(q);
    c -= b / (n + 1);
    P = n * n / (n * n - 1) * (P - 2 / (n + 1) * b * b.transpose());
    P = 0.5 * (P + P.transpose()).eval();
  }
  return best;
}

/// max of g over the circle (dense scan, then a shrinking local search around the best few
/// angles): g is unimodal when the pieces are apart, and the scan finds the best basin otherwise.
double circle_max(const SupportPoint<2>& sa, const SupportPoint<2>& sb) {
  auto g = [&](double t) {
    const Vec2 u(std::cos(t), std::sin(t));
    return -(u.dot(sa(u)) - u.dot(sb(-u)));
  };
  const int n = 4096;
  std::vector<std::pair<double, double>> seeds;
  for (int i = 0; i < n; ++i) seeds.push_back({g(2 * kPi * i / n), 2 * kPi * i / n});
  std::partial_sort(seeds.begin(), seeds.begin() + 8, seeds.end(), std::greater<>());
  double best = -1e300;
  for (int s = 0; s < 8; ++s) {
    auto [value, t] = seeds[s];
    for (double step = 2 * kPi / n; step > 1e-15;) {
      if (const double l = g(t - step); l > value) value = l, t -= step;
      else if (const double r = g(t + step); r > value) value = r, t += step;
      else step *= 0.5;
    }
    best = std::max(best, value);
  }
  return best;
}

/// Signed distance of two overlapping convex polyhedra: minus the distance from the origin to
/// the boundary of their Minkowski difference.
double overlap_polyhedra(const Body<3>& a, const Body<3>& b) {
  std::vector<Vec3> diff;
  for (const Vec3& p : std::dynamic_pointer_cast<const ConvexPolytopeShape<3>>(a.shape)->vertices())
    for (const Vec3& q : std::dynamic_pointer_cast<const ConvexPolytopeShape<3>>(b.shape)->vertices())
      diff.push_back(a.pose.to_world(p) - b.pose.to_world(q));
  const ConvexHull3 k = convex_hull_3(diff);
  double depth = 1e300;
  for (const auto& t : k.triangles) {
    const Vec3 n = (k.vertices[t[1]] - k.vertices[t[0]]).cross(k.vertices[t[2]] - k.vertices[t[0]]).normalized();
    depth = std::min(depth, n.dot(k.vertices[t[0]]));
  }
  return -depth;
}

template <int D>
double reference_signed_distance(const Body<D>& a, const Body<D>& b, bool overlapping) {
  if constexpr (D == 3)
    if (overlapping) return overlap_polyhedra(a, b);
  double d = 1e300;
  for (const auto& sa : pieces(a))
    for (const auto& sb : pieces(b)) {
      if constexpr (D == 2) d = std::min(d, circle_max(sa, sb));
      else d = std::min(d, ellipsoid_method_max<3>(sa, sb));
    }
  return d;
}

template <int D>
double fcl_signed_distance(const Body<D>& a, const Body<D>& b, bool overlapping) {
  double d = 1e300;
  for (const auto& pa : a.shape->fcl_parts())
    for (const auto& pb : b.shape->fcl_parts()) {
      fcl::CollisionObjectd oa(pa.geometry, fcl::Transform3d(fcl_part_transform(a.pose, pa)));
      fcl::CollisionObjectd ob(pb.geometry, fcl::Transform3d(fcl_part_transform(b.pose, pb)));
      fcl::DistanceRequestd request;
      request.gjk_solver_type = fcl::GST_LIBCCD;  // INDEP is wrong on some poses (dependencies.md)
      // Tighter for GJK alone; EPA on curved bodies trips an FCL assertion (abort) near 1e-10.
      request.distance_tolerance = overlapping ? 1e-8 : 1e-9;
      // Capsules are analytic and already signed; EPA on them costs ~400x (dependencies.md).
      request.enable_signed_distance =
          pa.geometry->getNodeType() != fcl::GEOM_CAPSULE && pb.geometry->getNodeType() != fcl::GEOM_CAPSULE;
      fcl::DistanceResultd result;
      fcl::distance(&oa, &ob, request, result);
      d = std::min(d, result.min_distance);
    }
  return d;
}

template <int D>
std::vector<test::Named> pick(const std::vector<std::string>& names) {
  std::vector<test::Named> out;
  for (const auto& c : test::catalogue<D>())
    if (std::find(names.begin(), names.end(), c.name) != names.end()) out.push_back(c);
  EXPECT_EQ(out.size(), names.size());
  return out;
}

/// Random poses of every pair of `shapes`; B is put at (R_A + R_B) t from A, t in [lo, hi]; the
/// configurations whose reference falls in the wanted class (apart, or overlapping, by more than
/// 1e-3 (R_A + R_B)) are compared with FCL, within tolerance (R_A + R_B): `flat` when both are
/// polytopes (GJK ends exactly on a face), `curved` otherwise (GJK converges, and stops, on a
/// curved surface: ~1e-7 even at distance_tolerance 1e-9). Returns the number of cases compared.
template <int D>
int compare_pairs(const std::vector<test::Named>& shapes, bool overlapping, int per_pair, double flat, double curved) {
  std::mt19937_64 rng(2024 + D);
  std::uniform_real_distribution<double> unit(0, 1);
  int cases = 0;
  for (std::size_t i = 0; i < shapes.size(); ++i)
    for (std::size_t j = i; j < shapes.size(); ++j) {
      SCOPED_TRACE(shapes[i].name + " vs " + shapes[j].name);
      const auto sa = test::prototype<D>(shapes[i].family, shapes[i].parameters).shape;
      const auto sb = test::prototype<D>(shapes[j].family, shapes[j].parameters).shape;
      auto is_flat = [](const std::string& f) { return f == "polygon" || f == "polyhedron"; };
      const double tolerance = is_flat(shapes[i].family) && is_flat(shapes[j].family) ? flat : curved;
      int found = 0;
      for (int attempt = 0; attempt < 50 * per_pair && found < per_pair; ++attempt) {
        Body<D> a{sa->scaled(0.5 + unit(rng)), {}};
        Body<D> b{sb->scaled(0.5 + unit(rng)), {}};
        a.pose.position = test::uniform_box<D>(rng, 1.0);
        a.pose.rotation = test::random_rotation<D>(rng);
        b.pose.rotation = test::random_rotation<D>(rng);
        const double scale = a.shape->bounding_radius() + b.shape->bounding_radius();
        const double t = overlapping ? 0.1 + 0.6 * unit(rng) : 0.5 + 0.7 * unit(rng);
        b.pose.position = a.pose.position + scale * t * test::random_unit<D>(rng);
        const double ref = reference_signed_distance(a, b, overlapping);
        if (overlapping ? ref > -1e-3 * scale : ref < 1e-3 * scale) continue;
        ++found;
        EXPECT_NEAR(fcl_signed_distance(a, b, overlapping), ref, tolerance * scale) << "attempt " << attempt;
      }
      EXPECT_EQ(found, per_pair);
      cases += found;
    }
  return cases;
}

TEST(FclParts, SeparatedDistanceAgreesWithSupportFunctions2D) {
  const auto shapes = pick<2>({"sphere", "spherocylinder 0.3", "cluster overlapping", "heptagon", "irregular polygon", "ellipse"});
  EXPECT_EQ(compare_pairs<2>(shapes, false, 12, 1e-10, 1e-6), 21 * 12);
}

TEST(FclParts, SeparatedDistanceAgreesWithSupportFunctions3D) {
  const auto shapes = pick<3>({"sphere", "spherocylinder 0.3", "cluster overlapping", "platonic 8", "irregular polyhedron",
                               "ellipsoid", "cylinder long"});
  EXPECT_EQ(compare_pairs<3>(shapes, false, 12, 1e-10, 1e-6), 28 * 12);
}

// The embedding's depth along z (kEmbeddingDepth) keeps the least penetration in the plane.
TEST(FclParts, PenetrationDepthOfPolygonsAndEllipsesStaysInThePlane) {
  const auto shapes = pick<2>({"triangle", "irregular polygon", "ellipse"});
  EXPECT_EQ(compare_pairs<2>(shapes, true, 10, 1e-10, 1e-6), 6 * 10);
}

TEST(FclParts, PenetrationDepthOfPolyhedraIsExact) {
  const auto shapes = pick<3>({"platonic 6", "platonic 8", "irregular polyhedron"});
  EXPECT_EQ(compare_pairs<3>(shapes, true, 8, 1e-10, 1e-10), 6 * 8);
}

}  // namespace
}  // namespace fp
