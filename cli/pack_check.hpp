#pragma once
// What `frontpack pack` learns about a packing after packing it, whatever its particles: the full
// analysis of `frontpack analyze` (core/metrics/packing_analysis.hpp; for shapes
// contact/shape_analysis.hpp), the one verdict in it (core/metrics/validate.hpp), and what a kind
// of particle adds (cli/sphere_pack.hpp: the grid's memory; cli/shape_pack.hpp: the solvers').
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/metrics/packing_analysis.hpp"
#include "core/metrics/validate.hpp"

namespace fp {

struct PackCheck {
  ValidationReport validation;
  double volume_fraction = 0.0;   ///< of the container (2D: area fraction)
  std::string timing_name;        ///< the record's timing of the check ("metrics": the full analysis)
  std::vector<std::pair<std::string, double>> metrics;           ///< after the record's common metrics
  std::vector<std::pair<std::string, std::uint64_t>> counters;   ///< after the common counters
  std::vector<std::pair<std::string, std::string>> info;         ///< after the common info
  std::string analysis_json;      ///< the full analysis (analysis_json.hpp), embedded in the record
  std::string summary_lines;      ///< the analysis' table, then the kind's own lines, each "  name  value\n"
};

/// The record's figures of an analysis (its validation included) and its table as summary lines.
PackCheck pack_check_of(const PackingAnalysis& analysis);

}  // namespace fp
