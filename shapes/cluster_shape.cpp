#include "shapes/cluster_shape.hpp"

#include <fcl/geometry/shape/sphere.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "shapes/ball_union.hpp"
#include "shapes/contains_slack.hpp"
#include "shapes/json_text.hpp"
#include "shapes/round_families.hpp"
#include "shapes/round_surface.hpp"
#include "shapes/shape_parameters.hpp"

namespace fp {

template <int D>
ClusterShape<D>::ClusterShape(std::vector<Ball<D>> members)
    : ClusterShape(members, ball_union_measure<D>(std::span<const Ball<D>>(members))) {}

template <int D>
ClusterShape<D>::ClusterShape(std::vector<Ball<D>> members, double measure)
    : members_(std::move(members)), measure_(measure) {
  for (const Ball<D>& b : members_) {
    const double c = b.center.norm();
    bounding_ = std::max(bounding_, c + b.radius);
    inscribed_ = std::max(inscribed_, b.radius - c);
  }
}

template <int D>
Vec<D> ClusterShape<D>::support(const Vec<D>& u) const {
  const double n = u.norm();
  const Vec<D> dir = n > 0 ? Vec<D>(u / n) : Vec<D>::Zero();
  std::size_t best = 0;
  double best_value = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < members_.size(); ++i) {
    const double v = dir.dot(members_[i].center) + members_[i].radius;
    if (v > best_value) best_value = v, best = i;
  }
  return members_[best].center + members_[best].radius * dir;
}

template <int D>
bool ClusterShape<D>::contains(const Vec<D>& x) const {
  const double slack = kContainsSlack * bounding_;
  for (const Ball<D>& b : members_) {
    const double r = b.radius + slack;
    if ((x - b.center).squaredNorm() <= r * r) return true;
  }
  return false;
}

template <int D>
SurfaceMesh<D> ClusterShape<D>::surface(int resolution) const {
  SurfaceMesh<D> m;
  if constexpr (D == 2) {
    for (const ExposedArc& a : exposed_arcs(std::span<const Ball<2>>(members_))) {
      const Ball<2>& b = members_[a.ball];
      const int segments = std::max(1, static_cast<int>(std::ceil(resolution * (a.t1 - a.t0) / (2 * kPi))));
      const int first = static_cast<int>(m.vertices.size());
      for (int k = 0; k <= segments; ++k) {
        const double t = a.t0 + (a.t1 - a.t0) * k / segments;
        m.vertices.push_back(b.center + b.radius * Vec2(std::cos(t), std::sin(t)));
        if (k > 0) m.facets.push_back({first + k - 1, first + k});
      }
    }
  } else {
    for (const Ball<3>& b : members_) {
      const SurfaceMesh<3> s = capsule_surface<3>(0.0, b.radius, resolution);
      const int first = static_cast<int>(m.vertices.size());
      for (const Vec3& v : s.vertices) m.vertices.push_back(b.center + v);
      for (const auto& f : s.facets) m.facets.push_back({first + f[0], first + f[1], first + f[2]});
    }
  }
  return m;
}

template <int D>
std::vector<FclPart<D>> ClusterShape<D>::fcl_parts() const {
  std::vector<FclPart<D>> parts;
  for (const Ball<D>& b : members_) {
    FclPart<D> p;
    p.offset = b.center;
    p.geometry = std::make_shared<fcl::Sphered>(b.radius);
    parts.push_back(p);
  }
  return parts;
}

template <int D>
ShapePtr<D> ClusterShape<D>::scaled(double s) const {
  std::vector<Ball<D>> m = members_;
  for (Ball<D>& b : m) b.center *= s, b.radius *= s;
  return std::make_shared<ClusterShape<D>>(std::move(m), measure_ * std::pow(s, D));
}

template <int D>
std::string ClusterShape<D>::definition_json() const {
  return R"({"kind": "cluster", "centers": )" +
         json_list(members_, [](const Ball<D>& b) { return json_point<D>(b.center); }) + R"(, "radii": )" +
         json_list(members_, [](const Ball<D>& b) { return json_number(b.radius); }) + "}";
}

template <int D>
ShapePrototype<D> cluster_prototype(const ShapeParameters& p) {
  const ParameterReader r(p);
  std::vector<std::vector<double>> centers;
  std::vector<double> radii;
  if (r.has("preset")) {
    // Clumps that are the same in 2D and 3D (their members in the plane z = 0), so that one
    // template serves both dimensions (experiments/2d-vs-3d): equal members, each touching the others.
    if (r.has("centers") || r.has("radii")) r.fail("preset", "give either a preset or centers and radii");
    const std::string name = r.word("preset", "dimer | trimer");
    if (name == "dimer") {
      centers = {{-1, 0}, {1, 0}};
    } else if (name == "trimer") {
      const double c = 2 / std::sqrt(3.0);  // circumradius of the triangle of side 2
      centers = {{0, c}, {-1, -c / 2}, {1, -c / 2}};
    } else {
      r.fail("preset", "unknown cluster preset '" + name + "' (dimer: two touching equal members; trimer: three in a triangle)");
    }
    for (auto& x : centers) x.resize(D, 0.0);
    radii.assign(centers.size(), 1.0);
  } else {
    centers = r.points("centers", "the member centres, a list of points (or a preset: dimer | trimer)", D);
    radii = r.list("radii", "the member radii, one per centre");
  }
  if (centers.empty()) r.fail("centers", "a cluster needs at least one member");
  if (centers.size() > static_cast<std::size_t>(ClusterShape<D>::kMaxMembers))
    r.fail("centers", "at most " + std::to_string(ClusterShape<D>::kMaxMembers) + " members (got " + std::to_string(centers.size()) +
                          "): the union's volume and every contact problem grow faster than the square of the members' "
                          "count; a shape of many balls packs as the convex polyhedron of their hull, or as fewer, larger members");
  if (radii.size() != centers.size())
    r.fail("radii", "has " + std::to_string(radii.size()) + " radii for " + std::to_string(centers.size()) +
                        " centres (one radius per centre)");
  // The cluster is rescaled to circumscribed radius 1 anyway: scale the input first, by a power of
  // two (exact), so that r^D cannot overflow (radii: [1e308] made the centroid nan and the
  // measure's quadrature never ended).
  double largest = 0.0;
  for (std::size_t i = 0; i < centers.size(); ++i) {
    largest = std::max(largest, std::abs(radii[i]));
    for (int k = 0; k < D; ++k) largest = std::max(largest, std::abs(centers[i][k]));
  }
  const double unit = largest > 0 && std::isfinite(largest) ? std::ldexp(1.0, -std::ilogb(largest)) : 1.0;
  std::vector<Ball<D>> members;
  Vec<D> centroid = Vec<D>::Zero();
  double weight = 0.0;
  for (std::size_t i = 0; i < centers.size(); ++i) {
    if (!(radii[i] > 0)) r.fail("radii", "radius " + std::to_string(i) + " must be positive (got " + json_number(radii[i]) + ")");
    Ball<D> b;
    for (int k = 0; k < D; ++k) b.center[k] = unit * centers[i][k];
    b.radius = unit * radii[i];
    members.push_back(b);
    const double w = std::pow(b.radius, D);  // the member's own measure, up to a constant
    centroid += w * b.center;
    weight += w;
  }
  if (!(weight > 0))  // every r^D underflowed: radii below ~1e-100 of the largest coordinate
    r.fail("radii", "every radius is negligible against the distances between the centres");
  centroid /= weight;
  double circumscribed = 0.0;
  for (Ball<D>& b : members) {
    b.center -= centroid;
    circumscribed = std::max(circumscribed, b.center.norm() + b.radius);
  }
  for (Ball<D>& b : members) b.center /= circumscribed, b.radius /= circumscribed;
  auto shape = std::make_shared<ClusterShape<D>>(std::move(members));
  return {shape, {{"circumscribed_radius", 1.0}, {"equivalent_radius", equivalent_radius<D>(shape->measure())}}};
}

template class ClusterShape<2>;
template class ClusterShape<3>;
template ShapePrototype<2> cluster_prototype<2>(const ShapeParameters&);
template ShapePrototype<3> cluster_prototype<3>(const ShapeParameters&);

}  // namespace fp
