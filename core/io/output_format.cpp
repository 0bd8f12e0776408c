#include "core/io/output_format.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

namespace fp {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

const char* output_format_names() { return "vtu, yade, lammps, csv, json"; }

OutputFormat parse_output_format(const std::string& name) {
  const std::string n = lower(name);
  if (n == "vtu") return OutputFormat::Vtu;
  if (n == "yade") return OutputFormat::Yade;
  if (n == "lammps") return OutputFormat::Lammps;
  if (n == "csv") return OutputFormat::Csv;
  if (n == "json") return OutputFormat::Json;
  throw std::invalid_argument("unknown output format '" + name + "' (allowed: " + output_format_names() + ")");
}

const char* output_format_name(OutputFormat format) {
  switch (format) {
    case OutputFormat::Vtu: return "vtu";
    case OutputFormat::Yade: return "yade";
    case OutputFormat::Lammps: return "lammps";
    case OutputFormat::Csv: return "csv";
    case OutputFormat::Json: return "json";
  }
  throw std::invalid_argument("invalid OutputFormat value");
}

OutputFormat format_from_extension(const std::string& path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  if (ext == ".vtu") return OutputFormat::Vtu;
  if (ext == ".txt" || ext == ".yade") return OutputFormat::Yade;
  if (ext == ".data" || ext == ".lammps") return OutputFormat::Lammps;
  if (ext == ".csv") return OutputFormat::Csv;
  if (ext == ".json") return OutputFormat::Json;
  throw std::invalid_argument("cannot tell the output format of '" + path +
                              "' from its extension (known: .vtu, .txt/.yade, .data/.lammps, .csv, .json)");
}

SurfaceDetail parse_surface_detail(const std::string& name) {
  if (name == "fine") return SurfaceDetail::Fine;
  if (name == "coarse") return SurfaceDetail::Coarse;
  if (name == "none") return SurfaceDetail::None;
  throw std::invalid_argument("unknown surface detail '" + name + "' (known: fine, coarse, none)");
}

}  // namespace fp
