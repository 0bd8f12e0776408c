#pragma once
// What `frontpack pack` learns about a packing after packing it, whatever its particles: the one
// verdict (core/metrics/validate.hpp) and what a kind of particle adds to the run record and the
// summary (cli/sphere_pack.hpp: the full analysis; cli/shape_pack.hpp: the solvers' counters).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/metrics/validate.hpp"

namespace fp {

struct PackCheck {
  ValidationReport validation;
  double volume_fraction = 0.0;   ///< of the container (2D: area fraction)
  std::string timing_name;        ///< the record's timing of the check: "metrics" (full analysis) or "validation"
  std::vector<std::pair<std::string, double>> metrics;           ///< after the record's common metrics
  std::vector<std::pair<std::string, std::uint64_t>> counters;   ///< after the common counters
  std::vector<std::pair<std::string, std::string>> info;         ///< after the common info
  std::string analysis_json;      ///< the full analysis (spheres), empty otherwise
  std::string summary_lines;      ///< the kind's own lines of the summary, each "  name  value\n"
};

}  // namespace fp
