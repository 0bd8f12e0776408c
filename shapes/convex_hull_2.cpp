#include "shapes/convex_hull_2.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/geometry/convex_polygon.hpp"

namespace fp {

std::vector<Vec2> convex_hull_2(std::vector<Vec2> points) {
  // Lower then upper chain; a turn that is not strictly left drops the middle point, so
  // collinear points and duplicates leave no vertex.
  std::vector<Vec2> hull;
  convex_polygon::append_hull(points, hull);  // sorts and deduplicates `points`
  if (points.size() < 3) throw std::invalid_argument("a polygon needs at least 3 distinct vertices");
  double extent = 0.0, twice_area = 0.0;
  for (const Vec2& p : hull) extent = std::max(extent, (p - hull[0]).norm());
  for (std::size_t i = 1; i + 1 < hull.size(); ++i) twice_area += convex_polygon::cross(hull[i] - hull[0], hull[i + 1] - hull[0]);
  if (hull.size() < 3 || !(twice_area > 1e-12 * extent * extent))
    throw std::invalid_argument("the vertices span no area (collinear or coincident points)");
  return hull;
}

}  // namespace fp
