#pragma once
// Plane sections of a packing of spheres (disks), the picture a researcher looks at before any
// number: in 3D the three planes through the container's centre normal to x, y and z, each
// sphere the plane cuts giving its exact section (a disk of radius sqrt(r^2 - h^2), h the centre's
// distance to the plane); in 2D the packing itself. The container's section is traced by marching
// squares on its signed distance over a grid of the plane (every container kind alike, meshes
// included), as segments. Absolute coordinates (the packing's origin added).
#include <array>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"

namespace fp {

struct SectionDisk {
  double u = 0.0, v = 0.0;  ///< the centre in the plane's axes
  double radius = 0.0;      ///< of the section
  double size = 0.0;        ///< the particle's radius
};

/// A particle of another shape cut by the plane: its section as closed loops (u, v) of the
/// particle's surface mesh cut by the plane (exact for polyhedra and polygons; curved shapes to
/// their mesh), drawn filled.
struct SectionPolygon {
  std::vector<std::array<double, 2>> points;  ///< a closed loop (the last point joins the first)
  double size = 0.0;                          ///< the particle's size (on its template's dimension)
  int template_id = 0;
  std::size_t particle = 0;                   ///< its index in the packing (a cluster cut gives several loops)
};

struct PackingSection {
  /// The axis the plane is normal to (0: x = offset, drawn in y, z; 1: y, drawn in x, z; 2: z,
  /// drawn in x, y); in 2D 2, the packing's own plane.
  int normal_axis = 2;
  double offset = 0.0;  ///< the plane's coordinate along its normal (absolute; 0 in 2D)
  double local_offset = 0.0;  ///< the same in the packing's frame (exactly, not offset less the origin)
  int u_axis = 0, v_axis = 1;
  std::vector<SectionDisk> disks;
  std::vector<SectionPolygon> polygons;
  std::vector<std::array<double, 4>> outline;  ///< the container's section: segments (u0, v0, u1, v1)
};

/// The planes (3D: normal to x, y, z through the centre of the container's bounds; 2D: one),
/// each with the container's outline and no particles yet; `origin`: the packing's frame origin
/// (added to every coordinate). `grid`: cells per side of the marching-squares grid of the outline.
template <int D>
std::vector<PackingSection> section_planes(const Container<D>& container, const Vec<D>& origin, int grid = 512);

/// The planes with the balls' sections. Balls with a non-finite centre or radius are left out.
template <int D>
std::vector<PackingSection> packing_sections(const Packing<D>& packing, const Container<D>& container, int grid = 512);

}  // namespace fp
