#include "core/geometry/delaunay_cgal.hpp"

#include <algorithm>
#include <utility>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <Eigen/Geometry>

namespace fp {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

/// A cell's mark: returned by an earlier batch. A cell CGAL makes starts unmarked.
struct Returned {
  bool yes = false;
};

/// The types of the triangulation of each dimension.
template <int D>
struct Cgal;
template <>
struct Cgal<3> {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
  using Cb = CGAL::Triangulation_cell_base_with_info_3<Returned, K>;
  using Triangulation = CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb, Cb>>;
  using Point = K::Point_3;
  using Sort = CGAL::Spatial_sort_traits_adapter_3<K, CGAL::First_of_pair_property_map<std::pair<Point, std::uint32_t>>>;
  static Point point(const Vec3& p) { return Point(p.x(), p.y(), p.z()); }
  static auto cells(const Triangulation& t) { return t.finite_cell_handles(); }
  static auto hint(typename Triangulation::Vertex_handle v) { return v->cell(); }
  static bool positive(const std::vector<Vec3>& p, const std::array<std::uint32_t, 4>& s) {
    return (p[s[1]] - p[s[0]]).cross(p[s[2]] - p[s[0]]).dot(p[s[3]] - p[s[0]]) >= 0;
  }
};
template <>
struct Cgal<2> {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
  using Fb = CGAL::Triangulation_face_base_with_info_2<Returned, K>;
  using Triangulation = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb, Fb>>;
  using Point = K::Point_2;
  using Sort = CGAL::Spatial_sort_traits_adapter_2<K, CGAL::First_of_pair_property_map<std::pair<Point, std::uint32_t>>>;
  static Point point(const Vec2& p) { return Point(p.x(), p.y()); }
  static auto cells(const Triangulation& t) { return t.finite_face_handles(); }
  static auto hint(typename Triangulation::Vertex_handle v) { return v->face(); }
  static bool positive(const std::vector<Vec2>& p, const std::array<std::uint32_t, 3>& s) {
    const Vec2 a = p[s[1]] - p[s[0]], b = p[s[2]] - p[s[0]];
    return a.x() * b.y() - a.y() * b.x() >= 0;
  }
};

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

/// Inserts points[from], ... into t, each vertex's info its index.
template <int D>
void insert_points(typename Cgal<D>::Triangulation& t, const std::vector<Vec<D>>& points, std::size_t from) {
  using C = Cgal<D>;
  using Item = std::pair<typename C::Point, std::uint32_t>;
  std::vector<Item> input;
  input.reserve(points.size() - std::min(from, points.size()));
  for (std::size_t i = from; i < points.size(); ++i) input.emplace_back(C::point(points[i]), static_cast<std::uint32_t>(i));
  // Inserted along a space-filling curve (each point near the last: fast location); a point
  // given twice is one vertex, which keeps the smaller index whatever the order.
  CGAL::spatial_sort(input.begin(), input.end(), typename C::Sort());
  decltype(C::hint(typename C::Triangulation::Vertex_handle())) hint{};
  for (const auto& [p, i] : input) {
    const std::size_t before = t.number_of_vertices();
    const auto v = t.insert(p, hint);
    v->info() = t.number_of_vertices() > before ? i : std::min(v->info(), i);
    hint = C::hint(v);
  }
}

/// The two ends of each finite edge, the smaller index first.
std::array<std::uint32_t, 2> ends(const Cgal<3>::Triangulation::Edge& e) {
  const std::uint32_t a = e.first->vertex(e.second)->info(), b = e.first->vertex(e.third)->info();
  return {std::min(a, b), std::max(a, b)};
}
std::array<std::uint32_t, 2> ends(const Cgal<2>::Triangulation::Edge& e) {
  const std::uint32_t a = e.first->vertex(Cgal<2>::Triangulation::cw(e.second))->info(),
                      b = e.first->vertex(Cgal<2>::Triangulation::ccw(e.second))->info();
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

template <int D>
struct GrowingDelaunay<D>::Impl {
  typename Cgal<D>::Triangulation t;
};

template <int D>
GrowingDelaunay<D>::GrowingDelaunay() : impl_(std::make_unique<Impl>()) {}
template <int D>
GrowingDelaunay<D>::~GrowingDelaunay() = default;

template <int D>
std::vector<typename GrowingDelaunay<D>::Simplex> GrowingDelaunay<D>::insert(const std::vector<Vec<D>>& points,
                                                                            std::size_t from) {
  using C = Cgal<D>;
  auto& t = impl_->t;
  insert_points<D>(t, points, from);
  std::vector<Simplex> made;
  if (t.dimension() < D) return made;
  for (const auto c : C::cells(t)) {
    if (c->info().yes) continue;
    c->info().yes = true;
    Simplex s;
    for (int k = 0; k <= D; ++k) s[static_cast<std::size_t>(k)] = c->vertex(k)->info();
    if (!C::positive(points, s)) std::swap(s[D - 1], s[D]);  // CGAL's cells are positive; rounding aside
    made.push_back(s);
  }
  sort_simplices(made);
  return made;
}

template class GrowingDelaunay<2>;
template class GrowingDelaunay<3>;

template <int D>
std::vector<std::array<std::uint32_t, 2>> delaunay_edges(const std::vector<Vec<D>>& points) {
  typename Cgal<D>::Triangulation t;
  insert_points<D>(t, points, 0);
  std::vector<std::array<std::uint32_t, 2>> edges;
  if (t.dimension() < 1) return edges;
  edges.reserve(t.number_of_vertices() * (D == 3 ? 8 : 3));
  for (auto e = t.finite_edges_begin(); e != t.finite_edges_end(); ++e) edges.push_back(ends(*e));
  std::sort(edges.begin(), edges.end());
  return edges;
}
template std::vector<std::array<std::uint32_t, 2>> delaunay_edges<2>(const std::vector<Vec2>&);
template std::vector<std::array<std::uint32_t, 2>> delaunay_edges<3>(const std::vector<Vec3>&);

std::vector<std::array<std::uint32_t, 4>> delaunay_tetrahedra(const std::vector<Vec3>& points) {
  return GrowingDelaunay<3>().insert(points, 0);
}

std::vector<std::array<std::uint32_t, 3>> delaunay_triangles(const std::vector<Vec2>& points) {
  return GrowingDelaunay<2>().insert(points, 0);
}

}  // namespace fp
