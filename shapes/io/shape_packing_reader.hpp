#pragma once
// Reader of the json output of a packing of shapes (shape_packing_writers.hpp): "shapes" gives
// each template's kind and its definition at a representative size, "particles" each particle's
// template (shape_id), position, quaternion and size. A particle's shape is its template's
// definition scaled by size / representative_size (every size a template draws is a length, so
// its shapes are one shape scaled). The json format is the one that carries the definitions: the
// others (csv, vtu, yade, lammps) describe the particles for their consumers, not for a reader.
#include <string>

#include "core/geometry/vec.hpp"
#include "shapes/particle.hpp"

namespace fp {

/// Whether the json text holds a packing of shapes (a top-level "shapes" list). False for
/// anything else, including text that is not json.
bool is_shape_packing_json(const std::string& text);

/// Reads the packing into the frame of `origin` (the container's frame origin): positions =
/// text - origin, the subtraction done exactly on the file's text (core/io/exact_decimal.hpp), so
/// a file read in the frame it was written in gives back the packer's positions. Throws
/// std::runtime_error naming `source_name` and the key on any bad input.
template <int D>
ShapePacking<D> read_shape_packing_json(const std::string& text, const std::string& source_name, const Vec<D>& origin);

}  // namespace fp
