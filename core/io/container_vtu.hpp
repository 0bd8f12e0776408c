#pragma once
// The container's own boundary as a VTU file, beside a packing's VTU output, so that ParaView
// shows the particles inside their walls: "out/bed.vtu" -> "out/bed.container.vtu".
//   3D: triangles (a mesh container's own facets; a box's faces; a ball or a cylinder
//       tessellated, kContainerSegments around);
//   2D: the boundary as one closed polyline in the plane z = 0 (a polygon's own edges).
// Points are absolute, rounded to doubles, like the particles of the packing's VTU.
#include <string>

#include "core/geometry/container.hpp"

namespace fp {

/// Segments around a round container's boundary (a ball's or a cylinder's circle): a picture's
/// resolution, 0.5 % of the radius at most between the true surface and its chords.
inline constexpr int kContainerSegments = 64;

/// "out/bed.vtu" -> "out/bed.container.vtu" (the last extension replaced).
std::string container_vtu_path(const std::string& vtu_path);

/// Writes `container`'s boundary to `path` atomically (core/io/atomic_file.hpp). Throws
/// std::runtime_error naming `path` on an I/O error, std::logic_error for a kind of container
/// this file does not know.
template <int D>
void write_container_vtu(const std::string& path, const Container<D>& container);

}  // namespace fp
