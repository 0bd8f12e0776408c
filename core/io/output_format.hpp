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

}  // namespace fp
