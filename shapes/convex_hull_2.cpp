#include "shapes/convex_hull_2.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fp {

namespace {

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

std::vector<Vec2> convex_hull_2(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  const std::size_t n = points.size();
  if (n < 3) throw std::invalid_argument("a polygon needs at least 3 distinct vertices");
  // Lower then upper chain; a turn that is not strictly left drops the middle point, so
  // collinear points and duplicates leave no vertex.
  std::vector<Vec2> hull(2 * n);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = n - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point is the first one again
  double extent = 0.0, twice_area = 0.0;
  for (const Vec2& p : hull) extent = std::max(extent, (p - hull[0]).norm());
  for (std::size_t i = 1; i + 1 < hull.size(); ++i) twice_area += cross(hull[0], hull[i], hull[i + 1]);
  if (hull.size() < 3 || !(twice_area > 1e-12 * extent * extent))
    throw std::invalid_argument("the vertices span no area (collinear or coincident points)");
  return hull;
}

}  // namespace fp
