#include "core/geometry/delaunay_cgal.hpp"

#include <algorithm>
#include <utility>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <Eigen/Geometry>

namespace fp {

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
  // A stable order for byte-identical reruns: by sorted vertex indices.
  std::sort(tets.begin(), tets.end(), [](std::array<std::uint32_t, 4> x, std::array<std::uint32_t, 4> y) {
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    return x < y;
  });
  return tets;
}

}  // namespace fp
