#include "shapes/convex_polytope_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include <Eigen/Geometry>

#include "shapes/contains_slack.hpp"
#include "shapes/convex_hull_2.hpp"
#include "shapes/convex_hull_3.hpp"
#include "shapes/fcl_embedding.hpp"
#include "shapes/json_text.hpp"
#include "shapes/regular_polytopes.hpp"
#include "shapes/round_families.hpp"
#include "shapes/shape_parameters.hpp"

namespace fp {

template <int D>
ConvexPolytopeShape<D>::ConvexPolytopeShape(std::vector<Vec<D>> vertices, std::vector<std::array<int, D>> facets)
    : vertices_(std::move(vertices)), facets_(std::move(facets)) {
  // Measure and centroid: a fan of triangles (tetrahedra) from the mean vertex, which keeps the
  // digits when the polytope sits far from the origin.
  Vec<D> o = Vec<D>::Zero();
  for (const Vec<D>& v : vertices_) o += v;
  o /= static_cast<double>(vertices_.size());
  Vec<D> moment = Vec<D>::Zero();
  for (const auto& f : facets_) {
    if constexpr (D == 2) {
      const Vec2 a = vertices_[f[0]] - o, b = vertices_[f[1]] - o;
      const double t = 0.5 * (a.x() * b.y() - a.y() * b.x());
      measure_ += t;
      moment += t * (a + b) / 3.0;
    } else {
      const Vec3 a = vertices_[f[0]] - o, b = vertices_[f[1]] - o, c = vertices_[f[2]] - o;
      const double t = a.dot(b.cross(c)) / 6.0;
      measure_ += t;
      moment += t * (a + b + c) / 4.0;
    }
  }
  centroid_ = o + moment / measure_;
  for (const Vec<D>& v : vertices_) bounding_ = std::max(bounding_, v.norm());

  // Face planes. The offset is the support value over all vertices, so each half-space holds the
  // whole polytope even when a thin triangle's normal carries rounding; coplanar triangles give
  // one plane.
  inscribed_ = std::numeric_limits<double>::infinity();
  for (const auto& f : facets_) {
    Vec<D> n;
    if constexpr (D == 2) {
      const Vec2 e = vertices_[f[1]] - vertices_[f[0]];
      n = Vec2(e.y(), -e.x());
    } else {
      n = (vertices_[f[1]] - vertices_[f[0]]).cross(vertices_[f[2]] - vertices_[f[0]]);
    }
    n.normalize();
    double h = -std::numeric_limits<double>::infinity();
    for (const Vec<D>& v : vertices_) h = std::max(h, n.dot(v));
    int plane = -1;
    for (std::size_t k = 0; k < normals_.size() && plane < 0; ++k)
      if ((normals_[k] - n).norm() <= 1e-12 && std::abs(offsets_[k] - h) <= 1e-12 * bounding_) plane = static_cast<int>(k);
    facet_plane_.push_back(plane >= 0 ? plane : static_cast<int>(normals_.size()));
    if (plane >= 0) continue;
    normals_.push_back(n);
    offsets_.push_back(h);
    inscribed_ = std::min(inscribed_, h);
  }
  inscribed_ = std::max(0.0, inscribed_);
  if constexpr (D == 3) {
    // Edges: triangle sides shared by triangles of two different planes (a side inside a
    // triangulated face is none), each once, with the planes on either side.
    for (std::size_t f = 0; f < facets_.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = facets_[f][k], b = facets_[f][(k + 1) % 3];
        if (a > b) continue;  // the side is met once in each direction: keep a < b
        for (std::size_t g = 0; g < facets_.size(); ++g) {
          if (g == f) continue;
          bool shares = false;
          for (int j = 0; j < 3 && !shares; ++j) shares = facets_[g][j] == b && facets_[g][(j + 1) % 3] == a;
          if (shares && facet_plane_[f] != facet_plane_[g]) edges_.push_back({a, b, facet_plane_[f], facet_plane_[g]});
        }
      }
  }
}

template <int D>
ConvexPolytopeShape<D> ConvexPolytopeShape<D>::hull_of(const std::vector<Vec<D>>& points) {
  if constexpr (D == 2) {
    std::vector<Vec2> hull = convex_hull_2(points);
    std::vector<std::array<int, 2>> edges;
    const int n = static_cast<int>(hull.size());
    for (int i = 0; i < n; ++i) edges.push_back({i, (i + 1) % n});
    return ConvexPolytopeShape(std::move(hull), std::move(edges));
  } else {
    ConvexHull3 hull = convex_hull_3(points);
    return ConvexPolytopeShape(std::move(hull.vertices), std::move(hull.triangles));
  }
}

template <int D>
Vec<D> ConvexPolytopeShape<D>::support(const Vec<D>& u) const {
  std::size_t best = 0;
  double best_value = u.dot(vertices_[0]);
  for (std::size_t i = 1; i < vertices_.size(); ++i)
    if (const double v = u.dot(vertices_[i]); v > best_value) best_value = v, best = i;
  return vertices_[best];
}

template <int D>
bool ConvexPolytopeShape<D>::contains(const Vec<D>& x) const {
  const double slack = kContainsSlack * bounding_;
  for (std::size_t k = 0; k < normals_.size(); ++k)
    if (normals_[k].dot(x) > offsets_[k] + slack) return false;
  return true;
}

template <int D>
std::vector<Ball<D>> ConvexPolytopeShape<D>::hull_balls() const {
  std::vector<Ball<D>> balls;
  for (const Vec<D>& v : vertices_) balls.push_back({v, 0.0});
  return balls;
}

template <int D>
SurfaceMesh<D> ConvexPolytopeShape<D>::surface(int) const {
  return {vertices_, facets_};
}

template <int D>
std::vector<FclPart<D>> ConvexPolytopeShape<D>::fcl_parts() const {
  FclPart<D> p;
  if constexpr (D == 2) {
    p.geometry = make_fcl_prism(vertices_, kEmbeddingDepth * bounding_);
  } else {
    std::vector<std::vector<int>> faces;
    for (const auto& f : facets_) faces.push_back({f[0], f[1], f[2]});
    p.geometry = make_fcl_convex(vertices_, faces);
  }
  return {p};
}

template <int D>
ShapePtr<D> ConvexPolytopeShape<D>::scaled(double s) const {
  auto copy = std::make_shared<ConvexPolytopeShape<D>>(*this);  // no hull nor planes to recompute
  for (Vec<D>& v : copy->vertices_) v *= s;
  for (double& h : copy->offsets_) h *= s;
  copy->centroid_ *= s;
  copy->measure_ *= std::pow(s, D);
  copy->bounding_ *= s;
  copy->inscribed_ *= s;
  return copy;
}

template <int D>
std::string ConvexPolytopeShape<D>::definition_json() const {
  auto facet = [](const std::array<int, D>& f) {
    std::string s = "[";
    for (int i = 0; i < D; ++i) s += (i ? ", " : "") + std::to_string(f[i]);
    return s + "]";
  };
  return std::string(R"({"kind": ")") + kKind + R"(", "vertices": )" +
         json_list(vertices_, [](const Vec<D>& v) { return json_point<D>(v); }) + R"(, "facets": )" +
         json_list(facets_, facet) + "}";
}

template <int D>
ShapePrototype<D> convex_polytope_prototype(const ShapeParameters& p) {
  const ParameterReader r(p);
  const std::string family = ConvexPolytopeShape<D>::kKind;
  const std::string shortcut = D == 2 ? "sides" : "platonic";
  const int given = int(r.has("vertices")) + int(r.has(shortcut)) + int(D == 3 && r.has("preset"));
  if (given > 1) r.fail(shortcut, "give one of 'vertices', '" + shortcut + "'" + (D == 3 ? " or 'preset'" : "") + ", not several");
  if (given == 0) r.fail("vertices", "missing: the " + family + "'s vertices (or '" + shortcut + "')");

  std::vector<Vec<D>> points;
  const std::string from = r.has(shortcut) ? shortcut : D == 3 && r.has("preset") ? "preset" : "vertices";
  if (from == "preset") {
    // A Platonic solid by name: preset: tetrahedron | cube | octahedron | dodecahedron | icosahedron.
    if constexpr (D == 3) {
      const std::string name = r.word("preset", "a Platonic solid's name");
      const std::vector<std::pair<std::string, int>> names = {
          {"tetrahedron", 4}, {"cube", 6}, {"octahedron", 8}, {"dodecahedron", 12}, {"icosahedron", 20}};
      for (const auto& [n, faces] : names)
        if (n == name) points = platonic_solid(faces);
      if (points.empty())
        r.fail("preset", "unknown preset '" + name + "' (known: tetrahedron, cube, octahedron, dodecahedron, icosahedron)");
    }
  } else if (r.has(shortcut)) {
    const double x = r.number(shortcut, D == 2 ? "the number of sides of a regular polygon"
                                               : "the number of faces of a Platonic solid");
    const int n = std::abs(x) < 1e6 ? static_cast<int>(x) : 0;
    if constexpr (D == 2) {
      if (n != x || n < 3) r.fail(shortcut, "must be a whole number >= 3 (got " + json_number(x) + ")");
      if (n > ConvexPolytopeShape<D>::kMaxTemplatePoints)
        r.fail(shortcut, "at most " + std::to_string(ConvexPolytopeShape<D>::kMaxTemplatePoints) + " sides (got " +
                             json_number(x) + "); a polygon that fine is a disk: shape: sphere");
      points = regular_polygon(n);
    } else {
      if (n == x) points = platonic_solid(n);
      if (points.empty())
        r.fail(shortcut, "must be 4, 6, 8, 12 or 20: the faces of a tetrahedron, cube, octahedron, dodecahedron "
                         "or icosahedron (got " + json_number(x) + ")");
    }
  } else {
    for (const auto& q : r.points("vertices", "the vertices, a list of points", D)) {
      Vec<D> v;
      for (int k = 0; k < D; ++k) v[k] = q[k];
      points.push_back(v);
    }
    if (points.size() > static_cast<std::size_t>(ConvexPolytopeShape<D>::kMaxTemplatePoints))
      r.fail("vertices", "at most " + std::to_string(ConvexPolytopeShape<D>::kMaxTemplatePoints) + " vertices (got " +
                             std::to_string(points.size()) + ")");
  }

  auto hull = [&] {
    try {
      return ConvexPolytopeShape<D>::hull_of(points);
    } catch (const std::invalid_argument& e) {
      r.fail(from, e.what());
    }
  }();
  // Reference point at the centroid, circumscribed radius 1.
  std::vector<Vec<D>> vertices = hull.vertices();
  double circumscribed = 0.0;
  for (Vec<D>& v : vertices) {
    v -= hull.centroid();
    circumscribed = std::max(circumscribed, v.norm());
  }
  for (Vec<D>& v : vertices) v /= circumscribed;
  auto shape = std::make_shared<ConvexPolytopeShape<D>>(std::move(vertices), hull.facets());
  return {shape,
          {{"circumscribed_radius", 1.0},
           {"inscribed_radius", shape->inscribed_radius()},
           {"equivalent_radius", equivalent_radius<D>(shape->measure())}}};
}

template class ConvexPolytopeShape<2>;
template class ConvexPolytopeShape<3>;
template ShapePrototype<2> convex_polytope_prototype<2>(const ShapeParameters&);
template ShapePrototype<3> convex_polytope_prototype<3>(const ShapeParameters&);

}  // namespace fp
