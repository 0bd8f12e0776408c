#include "core/geometry/delaunay_cgal.hpp"

#include <algorithm>
#include <utility>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <Eigen/Geometry>

namespace fp {
namespace {

/// A stable order for byte-identical reruns: by sorted vertex indices (each key made once: a
/// comparison that sorted both keys was half the time of a triangulation).
template <std::size_t N>
void sort_simplices(std::vector<std::array<std::uint32_t, N>>& simplices) {
  std::vector<std::pair<std::array<std::uint32_t, N>, std::uint32_t>> keyed(simplices.size());
  for (std::size_t i = 0; i < simplices.size(); ++i) {
    keyed[i] = {simplices[i], static_cast<std::uint32_t>(i)};
    std::sort(keyed[i].first.begin(), keyed[i].first.end());
  }
  std::sort(keyed.begin(), keyed.end());  // keys are distinct: one cell per set of vertices
  std::vector<std::array<std::uint32_t, N>> sorted(simplices.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) sorted[i] = simplices[keyed[i].second];
  simplices = std::move(sorted);
}

}  // namespace

std::vector<std::array<std::uint32_t, 4>> delaunay_tetrahedra(const std::vector<Vec3>& points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb>;
  using Delaunay = CGAL::Delaunay_triangulation_3<K, Tds>;
  using Item = std::pair<K::Point_3, std::uint32_t>;
  std::vector<Item> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    input.emplace_back(K::Point_3(points[i].x(), points[i].y(), points[i].z()), static_cast<std::uint32_t>(i));
  // Inserted along a space-filling curve (each point near the last: fast location); a point
  // given twice is one vertex, which keeps the smaller index whatever the order.
  CGAL::spatial_sort(input.begin(), input.end(),
                     CGAL::Spatial_sort_traits_adapter_3<K, CGAL::First_of_pair_property_map<Item>>());
  Delaunay dt;
  Delaunay::Cell_handle hint;
  for (const auto& [p, i] : input) {
    const std::size_t before = dt.number_of_vertices();
    const Delaunay::Vertex_handle v = dt.insert(p, hint);
    v->info() = dt.number_of_vertices() > before ? i : std::min(v->info(), i);
    hint = v->cell();
  }
  std::vector<std::array<std::uint32_t, 4>> tets;
  if (dt.dimension() < 3) return tets;
  tets.reserve(dt.number_of_finite_cells());
  for (const auto c : dt.finite_cell_handles()) {
    std::array<std::uint32_t, 4> t = {c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()};
    const Vec3 &a = points[t[0]], &b = points[t[1]], &d = points[t[2]], &e = points[t[3]];
    if ((b - a).cross(d - a).dot(e - a) < 0) std::swap(t[2], t[3]);  // CGAL's cells are positive; rounding aside
    tets.push_back(t);
  }
  sort_simplices(tets);
  return tets;
}

std::vector<std::array<std::uint32_t, 3>> delaunay_triangles(const std::vector<Vec2>& points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using Delaunay = CGAL::Delaunay_triangulation_2<K, Tds>;
  using Item = std::pair<K::Point_2, std::uint32_t>;
  std::vector<Item> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    input.emplace_back(K::Point_2(points[i].x(), points[i].y()), static_cast<std::uint32_t>(i));
  CGAL::spatial_sort(input.begin(), input.end(),
                     CGAL::Spatial_sort_traits_adapter_2<K, CGAL::First_of_pair_property_map<Item>>());
  Delaunay dt;
  Delaunay::Face_handle hint;
  for (const auto& [p, i] : input) {
    const std::size_t before = dt.number_of_vertices();
    const Delaunay::Vertex_handle v = dt.insert(p, hint);
    v->info() = dt.number_of_vertices() > before ? i : std::min(v->info(), i);
    hint = v->face();
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  if (dt.dimension() < 2) return triangles;
  triangles.reserve(dt.number_of_faces());
  for (const auto f : dt.finite_face_handles()) {
    std::array<std::uint32_t, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    const Vec2 a = points[t[1]] - points[t[0]], b = points[t[2]] - points[t[0]];
    if (a.x() * b.y() - a.y() * b.x() < 0) std::swap(t[1], t[2]);
    triangles.push_back(t);
  }
  sort_simplices(triangles);
  return triangles;
}

}  // namespace fp
