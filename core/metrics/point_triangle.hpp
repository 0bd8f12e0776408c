#pragma once
// The closest point of a triangle to a point, with the feature it lies on (a vertex, an edge or
// the face): the validator's own primitive for mesh containers (Ericson, Real-Time Collision
// Detection, 5.1.5: Voronoi regions of the triangle by signs of dot products). The feature is what
// gives the distance its sign (mesh_distance.hpp: pseudo-normals).
#include <cmath>

#include <Eigen/Geometry>

#include "core/geometry/vec.hpp"

namespace fp {

struct TriangleFeature {
  enum Kind { Vertex, Edge, Face };
  Kind kind = Face;
  int index = 0;  ///< vertex k (0..2); edge k runs from vertex k to vertex (k + 1) % 3
};

struct TriangleClosest {
  Vec3 point = Vec3::Zero();
  double distance = 0.0;  ///< |p - point|; on the face, |(p - a) . n| / |n| (no cancellation in p - point)
  TriangleFeature feature;
};

namespace point_triangle_detail {

inline TriangleClosest on_segment(const Vec3& p, const Vec3& a, const Vec3& b, int edge, int va, int vb) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? (p - a).dot(ab) / len2 : 0.0;
  TriangleClosest c;
  if (t <= 0.0) {
    c.point = a;
    c.feature = {TriangleFeature::Vertex, va};
  } else if (t >= 1.0) {
    c.point = b;
    c.feature = {TriangleFeature::Vertex, vb};
  } else {
    c.point = a + t * ab;
    c.feature = {TriangleFeature::Edge, edge};
  }
  c.distance = (p - c.point).norm();
  return c;
}

}  // namespace point_triangle_detail

/// The point of triangle (a, b, c) nearest to p. A triangle of zero area is treated as its three
/// edges (it has no face).
inline TriangleClosest closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  using point_triangle_detail::on_segment;
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  TriangleClosest out;
  auto at_vertex = [&](const Vec3& v, int k) {
    out.point = v;
    out.distance = (p - v).norm();
    out.feature = {TriangleFeature::Vertex, k};
    return out;
  };
  auto at_edge = [&](const Vec3& from, const Vec3& dir, double t, int k) {
    out.point = from + t * dir;
    out.distance = (p - out.point).norm();
    out.feature = {TriangleFeature::Edge, k};
    return out;
  };
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return at_vertex(a, 0);
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return at_vertex(b, 1);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return at_edge(a, ab, d1 / (d1 - d3), 0);
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return at_vertex(c, 2);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return at_edge(a, ac, d2 / (d2 - d6), 2);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return at_edge(b, c - b, (d4 - d3) / ((d4 - d3) + (d5 - d6)), 1);
  const double sum = va + vb + vc;
  const Vec3 n = ab.cross(ac);
  const double n_len = n.norm();
  if (!(sum > 0.0) || !(n_len > 0.0)) {  // zero area: the nearest of its edges
    TriangleClosest best = on_segment(p, a, b, 0, 0, 1);
    for (const TriangleClosest& e : {on_segment(p, b, c, 1, 1, 2), on_segment(p, c, a, 2, 2, 0)})
      if (e.distance < best.distance) best = e;
    return best;
  }
  const double v = vb / sum, w = vc / sum;
  out.point = a + v * ab + w * ac;
  out.distance = std::abs(ap.dot(n)) / n_len;
  out.feature = {TriangleFeature::Face, 0};
  return out;
}

}  // namespace fp
