// CGAL translation unit 3: the simplicity test of polygon containers. The interface is
// polygon_cgal.hpp.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include "core/geometry/polygon_cgal.hpp"

namespace fp::detail {

bool is_simple_polygon(const std::vector<Vec2>& vertices) {
  using K = CGAL::Epick;
  std::vector<K::Point_2> points;
  points.reserve(vertices.size());
  for (const Vec2& v : vertices) points.emplace_back(v.x(), v.y());
  return CGAL::is_simple_2(points.begin(), points.end(), K());
}

}  // namespace fp::detail
