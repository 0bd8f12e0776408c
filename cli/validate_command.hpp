#pragma once
// `frontpack validate PACKING --scene SCENE`: the independent check of a packing file against the
// scene it claims to fill (core/metrics/validate: its own cell list, not the packer's grid).
#include <string>

namespace fp {

struct ValidateCommandOptions {
  std::string packing_path;
  std::string scene_path;
  std::string format;          ///< --format of PACKING; default from its extension
  double tolerance = -1;       ///< overlap allowance relative to r_min; < 0: the scene's contact_tolerance
  double ks_alpha = 1e-3;      ///< the radii fail the check when their K-S p-value is below this
  bool quiet = false;
};

/// Returns the exit code: 0 every check holds, 2 bad input, 3 the packing fails a check.
int run_validate_command(const ValidateCommandOptions& options);

}  // namespace fp
