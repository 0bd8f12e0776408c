#pragma once
// The packing file formats frontpack writes (and reads back, see packing_readers.hpp).
#include <string>

namespace fp {

enum class OutputFormat { Vtu, Yade, Lammps, Csv, Json };

/// "vtu" | "yade" | "lammps" | "csv" | "json" (case-insensitive). Throws std::invalid_argument
/// that lists the allowed names.
OutputFormat parse_output_format(const std::string& name);

/// Canonical lower-case name, the inverse of parse_output_format.
const char* output_format_name(OutputFormat format);

/// ".vtu" -> Vtu, ".txt"/".yade" -> Yade, ".data"/".lammps" -> Lammps, ".csv" -> Csv,
/// ".json" -> Json (case-insensitive). Throws std::invalid_argument naming the path and the
/// known extensions.
OutputFormat format_from_extension(const std::string& path);

/// "vtu, yade, lammps, csv, json": for error messages.
const char* output_format_names();

/// How finely a vtu output of particles of shapes draws their surfaces in its side file
/// "<stem>.surfaces.vtu": Fine (the default), Coarse (half the segments per turn of a curved
/// part: a sixth of the file for capsules), or None (no side file; the main file keeps each
/// particle's position, orientation and size).
enum class SurfaceDetail { Fine, Coarse, None };

/// "fine" | "coarse" | "none"; throws std::invalid_argument listing them.
SurfaceDetail parse_surface_detail(const std::string& name);

}  // namespace fp
