#pragma once
// `frontpack analyze PACKING [--scene SCENE] [--json OUT] [--plots DIR]`: every quality figure of
// core/metrics/packing_analysis.hpp, as a table, as JSON, and as PNG figures drawn by
// python/plot_analysis.py (Debian's python3-matplotlib).
#include <string>
#include <vector>

#include "core/io/scene_override.hpp"

namespace fp {

struct PackingInput;
struct PackingAnalysis;

struct AnalyzeCommandOptions {
  std::string packing_path;
  std::string scene_path;   ///< optional: container, requested distribution, contact tolerance
  std::vector<SceneOverride> scene_overrides;  ///< --set KEY=VALUE, in order
  std::string format;       ///< of PACKING; default from its extension
  std::string json_path;    ///< --json
  std::string plots_dir;    ///< --plots (must exist)
  double tolerance = -1;    ///< contact tolerance; < 0: the scene's, or 1e-9 without a scene
  std::string python = "/usr/bin/python3";  ///< the interpreter that has matplotlib (Debian's)
  int threads = 0;          ///< -j: 0 = every hardware thread (the figures do not depend on it)
  bool quiet = false;
};

/// Exit code: 0 done; 1 the plots could not be drawn (the table and JSON are still written);
/// 2 bad input.
int run_analyze_command(const AnalyzeCommandOptions& options);

/// The figures `analyze --plots DIR` draws, of a packing read and analysed (`a`, from
/// analyze_input), into the existing folder `plots_dir`: every figure or none. Returns "" when
/// drawn, else what went wrong (no folder, no matplotlib, a failed script).
std::string draw_analysis_figures(const PackingInput& in, const PackingAnalysis& a, const std::string& plots_dir,
                                  const std::string& python = "/usr/bin/python3");

}  // namespace fp
