// CGAL translation unit 1 of 2: reading polygon soups from OBJ / STL files (OFF has its own
// strict reader, off_reader.hpp). Kept apart from the spatial queries (mesh_cgal.cpp) so the
// two heavy TUs build in parallel.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/STL.h>
#include <CGAL/exceptions.h>

#include <algorithm>
#include <cctype>
#include <fstream>

#include "core/geometry/mesh_cgal.hpp"
#include "core/geometry/off_reader.hpp"

namespace fp::detail {

bool read_polygon_soup(const std::string& path, PolygonSoup& soup, std::string& error) {
  using Point = CGAL::Epick::Point_3;
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) {
      error = "cannot open the file";
      return false;
    }
  }
  const std::size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });

  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  if (ext == "off") {
    return read_off(path, soup, error);
  } else if (ext == "obj" || ext == "stl") {
    try {
      ok = ext == "obj" ? CGAL::IO::read_OBJ(path, points, polygons)
                        : CGAL::IO::read_STL(path, points, polygons);  // binary first, then ascii; merges equal points
    } catch (const CGAL::Failure_exception& e) {  // its what() is a page of CGAL internals
      error = "a check of the reader failed (" + e.expression() + ")";
      return false;
    }
  } else {
    error = "unknown extension '." + ext + "' (supported: .off, .obj, .stl)";
    return false;
  }
  if (!ok) {
    error = "not a valid " + ext + " file";
    return false;
  }
  soup.points.clear();
  soup.points.reserve(points.size());
  for (const Point& p : points) soup.points.emplace_back(p.x(), p.y(), p.z());
  soup.polygons = std::move(polygons);
  return true;
}

}  // namespace fp::detail
