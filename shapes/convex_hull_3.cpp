#include "shapes/convex_hull_3.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <Eigen/Geometry>

#include <map>
#include <stdexcept>

namespace fp {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

/// Index of the point farthest from the affine hull spanned so far (measured by `distance`).
template <class F>
std::size_t farthest(const std::vector<Vec3>& p, F distance, double& best) {
  std::size_t arg = 0;
  best = -1;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (const double d = distance(p[i]); d > best) best = d, arg = i;
  return arg;
}

}  // namespace

ConvexHull3 convex_hull_3(const std::vector<Vec3>& points) {
  if (points.size() < 4) throw std::invalid_argument("a polyhedron needs at least 4 vertices");
  // Reject flat input before CGAL (which would return a degenerate mesh), with a relative
  // tolerance: a hull thinner than 1e-12 of its extent is a polygon for every practical purpose.
  double extent, off_line, off_plane;
  const Vec3 a = points[farthest(points, [&](const Vec3& x) { return (x - points[0]).norm(); }, extent)];
  const Vec3 b = points[farthest(points, [&](const Vec3& x) { return (x - a).norm(); }, extent)];
  if (!(extent > 0)) throw std::invalid_argument("the vertices are all the same point");
  const Vec3 ab = (b - a) / extent;
  const Vec3 c = points[farthest(points, [&](const Vec3& x) { return (x - a).cross(ab).norm(); }, off_line)];
  if (!(off_line > 1e-12 * extent)) throw std::invalid_argument("the vertices are collinear: a polyhedron needs volume");
  const Vec3 n = ab.cross(c - a).normalized();
  farthest(points, [&](const Vec3& x) { return std::abs(n.dot(x - a)); }, off_plane);
  if (!(off_plane > 1e-12 * extent)) throw std::invalid_argument("the vertices are coplanar: a polyhedron needs volume");

  std::vector<Point> in;
  in.reserve(points.size());
  for (const Vec3& p : points) in.emplace_back(p.x(), p.y(), p.z());
  Mesh mesh;
  CGAL::convex_hull_3(in.begin(), in.end(), mesh);

  ConvexHull3 hull;
  std::map<Mesh::Vertex_index, int> index;
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    index[v] = static_cast<int>(hull.vertices.size());
    hull.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (Mesh::Face_index f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k == 3) throw std::logic_error("convex_hull_3: a face is not a triangle");
      t[k++] = index.at(v);
    }
    hull.triangles.push_back(t);
  }
  return hull;
}

}  // namespace fp
