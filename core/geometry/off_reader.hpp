#pragma once
// A strict reader of OFF surface files (Geomview's text format, as CGAL writes it):
//   [C][N]OFF                 header keyword (C: a colour after each vertex, N: a normal)
//   nv nf [ne]                counts (may follow the keyword on its line)
//   x y z [nx ny nz] [r g b [a]]       nv vertex lines
//   k i1 ... ik [colour]               nf face lines (colour: 1, 3 or 4 numbers)
// '#' starts a comment; blank lines are skipped. Every deviation is an error naming the line:
// a vertex line with a number too many, an index out of range, a count the file is too small
// to hold (checked before anything is allocated: a header claiming 2e9 vertices is refused at
// once), text after the last face. CGAL's reader ignored the first two and allocated what the
// header claimed. No CGAL here: mesh_cgal_io.cpp hands OFF files to this reader.
#include <string>

#include "core/geometry/mesh_cgal.hpp"

namespace fp::detail {

/// Reads `path` into `soup`. On failure returns false and sets `error` ("line 7: ...").
bool read_off(const std::string& path, PolygonSoup& soup, std::string& error);

}  // namespace fp::detail
