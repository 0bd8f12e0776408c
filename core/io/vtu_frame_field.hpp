#pragma once
// The VTU field that says in which frame a file's exact positions are: VTU points are Float64
// absolute positions, which far from the origin cannot hold a contact exact to 1e-9 r
// (core/geometry/local_frame.hpp). Such files also carry point data `local_position`, exact,
// relative to this field `frame_origin` (three numbers, ascii, shortest round-trip form).
// Written by the sphere and shape VTU writers, read by core/io/packing_readers.cpp.
#include <charconv>
#include <string>

namespace fp {

/// The <FieldData> element holding frame_origin = (x, y, z), indented for <UnstructuredGrid>.
inline std::string vtu_frame_origin_field(double x, double y, double z) {
  std::string values;
  for (const double v : {x, y, z}) {
    char tmp[32];
    const auto res = std::to_chars(tmp, tmp + sizeof tmp, v);
    values += (values.empty() ? "" : " ") + std::string(tmp, res.ptr);
  }
  return "    <FieldData>\n      <DataArray type=\"Float64\" Name=\"frame_origin\" NumberOfTuples=\"1\" "
         "NumberOfComponents=\"3\" format=\"ascii\">" +
         values + "</DataArray>\n    </FieldData>\n";
}

}  // namespace fp
