#pragma once
// Readers for the files packing_writers.hpp writes: YADE text, CSV, LAMMPS data file
// (diameter column -> radius), frontpack's own VTU layout (appended raw binary) and the json
// output (record + particles). Errors are std::runtime_error naming the file (and the line
// for text formats).
#include <string>

#include "core/geometry/packing.hpp"
#include "core/io/output_format.hpp"

namespace fp {

/// What the readers say of a file of non-spherical particles (shapes/io/shape_packing_writers).
inline constexpr const char* kSpheresAndDisksOnly =
    "these readers take packings of spheres and disks; a packing of shapes is read from its json output (which "
    "carries the shapes) with the scene it fills: frontpack validate (or analyze) PACKING.json --scene SCENE";

/// The whole text of a packing file; std::runtime_error naming it if it is missing, unreadable or
/// not a regular file.
std::string read_packing_text(const std::string& path);

/// Reads a D-dimensional packing into the frame of `origin` (the container's frame origin,
/// core/geometry/local_frame.hpp): centres = absolute - origin, the subtraction done exactly on
/// the file's text (core/io/exact_decimal.hpp), so a file read in the frame it was written in
/// gives back the packer's doubles. A 2D read requires every z to be 0 (and the CSV header of
/// the right dimension). Particles come back in id order.
template <int D>
Packing<D> read_packing(OutputFormat format, const std::string& path, const Vec<D>& origin = Vec<D>::Zero());

/// Same, in the frame that frame_origin() gives the particles' centres (no container known).
template <int D>
Packing<D> read_packing_in_own_frame(OutputFormat format, const std::string& path);

/// 2 or 3: from the CSV header or the JSON "dimension"; for the other formats 2 iff every
/// z is exactly 0. Throws like read_packing.
int packing_file_dimension(OutputFormat format, const std::string& path);

}  // namespace fp
