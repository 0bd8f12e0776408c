// Fuzz harness of the mesh readers: the input is written as x.off, x.stl and x.obj and each is
// read by fp::detail::read_polygon_soup (core/geometry/mesh_cgal.hpp: our strict OFF reader,
// CGAL's STL (binary, then ascii) and OBJ readers), then built into a fp::MeshContainer as a
// scene's `container: {type: mesh}` is.
// Property: the reader returns true, or false with a message; it never throws. What our OFF reader
// accepts has only polygons of 3 or more valid vertex indices. The container is built or refused
// with a std::invalid_argument naming the file; a container built is closed and finite (positive
// volume, finite bounds, its interior point inside). No message shows C++ internals.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/geometry/mesh_cgal.hpp"
#include "core/geometry/mesh_container.hpp"
#include "fuzz_support.hpp"

namespace {

using fp::fuzz::require;

void check_soup(const fp::detail::PolygonSoup& soup, const std::string& ext) {
  if (ext != "off") return;  // CGAL's readers promise less: the container checks their indices
  for (const auto& poly : soup.polygons) {
    require(poly.size() >= 3, "the OFF reader accepted a face of " + std::to_string(poly.size()) + " vertices");
    for (const std::size_t i : poly)
      require(i < soup.points.size(), "the OFF reader accepted vertex index " + std::to_string(i) + " of " +
                                          std::to_string(soup.points.size()));
  }
}

void check_container(const fp::MeshContainer& mesh) {
  const double volume = mesh.measure();
  require(std::isfinite(volume) && volume > 0, "mesh container of volume " + std::to_string(volume));
  require(mesh.num_facets() >= 4, "a closed mesh container with " + std::to_string(mesh.num_facets()) + " facets");
  const fp::Aabb<3> box = mesh.bounds();
  require(box.lo.allFinite() && box.hi.allFinite() && (box.lo.array() < box.hi.array()).all(),
          "mesh container bounds not finite or flat: " + mesh.describe());
  const fp::Vec3 deep = mesh.interior_point();
  require(deep.allFinite() && mesh.inside(deep) && mesh.signed_distance(deep) <= 0,
          "the mesh's interior point is not inside it: " + mesh.describe());
}

void read_as(const std::string& ext, const std::uint8_t* data, std::size_t size, std::string_view input) {
  const std::string path = fp::fuzz::write_scratch_file("x." + ext, data, size);
  fp::detail::PolygonSoup soup;
  std::string error;
  bool ok = false;
  try {
    ok = fp::detail::read_polygon_soup(path, soup, error);
  } catch (...) {
    fp::fuzz::unexpected_exception("read_polygon_soup(." + ext + ")");
  }
  if (!ok) {
    fp::fuzz::check_error_message(error, input, "read_polygon_soup(." + ext + ")");
    return;
  }
  check_soup(soup, ext);
  try {
    const auto mesh = fp::MeshContainer::from_file(path, 1.0, fp::FrameChoice::Local);
    require(mesh != nullptr, "MeshContainer::from_file returned null");
    check_container(*mesh);
  } catch (const std::invalid_argument& e) {
    fp::fuzz::check_error_message(e.what(), input, "MeshContainer(." + ext + ")");
    require(std::string_view(e.what()).find("x." + ext) != std::string_view::npos,
            "the mesh error does not name the file: " + std::string(e.what()));
  } catch (...) {
    fp::fuzz::unexpected_exception("MeshContainer(." + ext + ")");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > fp::fuzz::kMaxInputBytes) size = fp::fuzz::kMaxInputBytes;
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  for (const char* ext : {"off", "stl", "obj"}) read_as(ext, data, size, input);
  return 0;
}
