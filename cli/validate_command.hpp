#pragma once
// `frontpack validate PACKING --scene SCENE`: the independent check of a packing file against the
// scene it claims to fill (core/metrics/validate: its own cell list, not the packer's grid).
#include <string>
#include <vector>

#include "core/metrics/validate.hpp"
#include "core/io/scene_override.hpp"

namespace fp {

struct ValidateCommandOptions {
  std::string packing_path;
  std::string scene_path;
  std::vector<SceneOverride> scene_overrides;  ///< --set KEY=VALUE, in order
  std::string format;          ///< --format of PACKING; default from its extension
  double tolerance = -1;       ///< overlap allowance relative to min(ri, rj); < 0: the scene's contact_tolerance
  /// The radii fail when their test's p-value (radii_fit.hpp) is below this; negative: as `pack`
  /// checks the scene (radii_alpha_of in cli/pack_check.hpp: 0.001, or 0 for the voids' own radii).
  double ks_alpha = -1.0;
  int threads = 0;             ///< -j: 0 = every hardware thread (the report does not depend on it)
  bool quiet = false;
};

/// Returns the exit code: 0 every check holds, 2 bad input (also a scene of non-spherical
/// particles), 3 the packing fails a check (also a packing without particles).
int run_validate_command(const ValidateCommandOptions& options);

}  // namespace fp
