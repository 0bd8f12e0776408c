#include "contact/shape_sections.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace fp {
namespace {

/// Closed loops through points joined in pairs: each point has two neighbours on a closed
/// manifold surface; a loop that cannot close (a mesh with a boundary) ends where it stops.
std::vector<std::vector<std::size_t>> loops_of(std::size_t points, const std::vector<std::pair<std::size_t, std::size_t>>& joins) {
  std::vector<std::vector<std::size_t>> next(points);
  for (const auto& [a, b] : joins) next[a].push_back(b), next[b].push_back(a);
  std::vector<char> seen(points, 0);
  std::vector<std::vector<std::size_t>> loops;
  for (std::size_t start = 0; start < points; ++start) {
    if (seen[start] || next[start].empty()) continue;
    std::vector<std::size_t> loop{start};
    seen[start] = 1;
    for (std::size_t at = start;;) {
      const auto it = std::find_if(next[at].begin(), next[at].end(), [&](std::size_t n) { return !seen[n]; });
      if (it == next[at].end()) break;
      at = *it;
      seen[at] = 1;
      loop.push_back(at);
    }
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

/// The loops where a particle's surface crosses the plane x_k = c (3D), in the plane's axes.
std::vector<std::vector<std::array<double, 2>>> cut(const Particle<3>& p, const SurfaceMesh<3>& mesh, int k, double c, int U,
                                                    int V) {
  std::vector<Vec3> world;
  world.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) world.push_back(p.pose.to_world(v));
  // A vertex on the plane counts as above it, so that every crossing is of an edge's interior.
  auto above = [&](int i) { return world[static_cast<std::size_t>(i)][k] >= c; };
  std::map<std::pair<int, int>, std::size_t> on_edge;  // an edge's crossing, shared by its two facets
  std::vector<std::array<double, 2>> points;
  auto crossing = [&](int a, int b) {
    const std::pair<int, int> key = std::minmax(a, b);
    if (const auto it = on_edge.find(key); it != on_edge.end()) return it->second;
    const Vec3 &pa = world[static_cast<std::size_t>(key.first)], &pb = world[static_cast<std::size_t>(key.second)];
    const double t = (c - pa[k]) / (pb[k] - pa[k]);
    const Vec3 x = pa + t * (pb - pa);
    points.push_back({x[U], x[V]});
    return on_edge[key] = points.size() - 1;
  };
  std::vector<std::pair<std::size_t, std::size_t>> joins;
  for (const auto& f : mesh.facets) {
    std::size_t ends[3];
    int n = 0;
    for (int e = 0; e < 3; ++e)
      if (above(f[static_cast<std::size_t>(e)]) != above(f[static_cast<std::size_t>((e + 1) % 3)]))
        ends[n++] = crossing(f[static_cast<std::size_t>(e)], f[static_cast<std::size_t>((e + 1) % 3)]);
    if (n == 2) joins.emplace_back(ends[0], ends[1]);
  }
  std::vector<std::vector<std::array<double, 2>>> out;
  for (const auto& loop : loops_of(points.size(), joins)) {
    out.emplace_back();
    for (const std::size_t i : loop) out.back().push_back(points[i]);
  }
  return out;
}

/// A 2D particle's outline: its surface's segments joined into loops.
std::vector<std::vector<std::array<double, 2>>> outline(const Particle<2>& p, const SurfaceMesh<2>& mesh) {
  std::vector<std::pair<std::size_t, std::size_t>> joins;
  for (const auto& f : mesh.facets) joins.emplace_back(static_cast<std::size_t>(f[0]), static_cast<std::size_t>(f[1]));
  std::vector<std::vector<std::array<double, 2>>> out;
  for (const auto& loop : loops_of(mesh.vertices.size(), joins)) {
    out.emplace_back();
    for (const std::size_t i : loop) {
      const Vec2 x = p.pose.to_world(mesh.vertices[i]);
      out.back().push_back({x.x(), x.y()});
    }
  }
  return out;
}

}  // namespace

template <int D>
std::vector<PackingSection> shape_sections(const ShapePacking<D>& packing, const Container<D>& container, int grid) {
  std::vector<PackingSection> out = section_planes<D>(container, packing.origin, grid);
  for (PackingSection& s : out) {
    const int k = s.normal_axis, U = s.u_axis, V = s.v_axis;
    const double c = s.local_offset;
    for (std::size_t i = 0; i < packing.particles.size(); ++i) {
      const Particle<D>& p = packing.particles[i];
      if (!p.pose.position.allFinite()) continue;
      if (D == 3 && !(std::abs(p.pose.position[k] - c) < p.bounding_radius())) continue;
      std::vector<std::vector<std::array<double, 2>>> loops;
      if constexpr (D == 3) loops = cut(p, p.shape->surface(kSectionResolution), k, c, U, V);
      else loops = outline(p, p.shape->surface(kSectionResolution));
      for (auto& loop : loops) {
        for (auto& q : loop) q[0] += packing.origin[U], q[1] += packing.origin[V];
        s.polygons.push_back({std::move(loop), p.size, p.template_id, i});
      }
    }
  }
  return out;
}

template std::vector<PackingSection> shape_sections<2>(const ShapePacking<2>&, const Container<2>&, int);
template std::vector<PackingSection> shape_sections<3>(const ShapePacking<3>&, const Container<3>&, int);

}  // namespace fp
