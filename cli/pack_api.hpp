#pragma once
// The command line's pipeline as functions, for programs that hold the packing in memory (the
// Python module, python/frontpack_module.cpp): `frontpack pack` without its files (pack,
// check with the full analysis, record), and the analysis and verdict of `frontpack analyze` and
// `frontpack validate` (which call these) of a packing in memory. The numbers are the commands' own: the same scene and seed give the same particles,
// record and analysis.
#include <cstdint>
#include <optional>
#include <string>

#include "cli/packing_input.hpp"
#include "core/io/run_record.hpp"
#include "core/metrics/packing_analysis.hpp"
#include "core/metrics/validate.hpp"
#include "core/io/scene.hpp"
#include "front/pack_result.hpp"

namespace fp {

/// What `frontpack pack` adds to a packing: its run record (the analysis embedded) and the verdict.
struct PackOutcome {
  PackingInput packed;  ///< the particles, with the scene (PackingInput: the same as `analyze` reads)
  RunRecord record;
  bool valid = false;          ///< the independent validation passed (the command exits 3 otherwise)
  std::string validation;      ///< its one line (the summary's `validation` line)
  /// Why the packing is not the packing of the container the scene asks for (the command exits 4
  /// when it is valid): the record's `info.incomplete`; "" when complete.
  std::string incomplete;
  std::string summary;         ///< the summary's analysis and packer lines, as the command prints them
};

/// `requested` threads (-j, packer.threads, a Python threads=): 0 (every hardware thread) to
/// kMaxThreads, as the command line takes them; std::invalid_argument naming `name` otherwise.
void check_threads(long long requested, const std::string& name);

/// `in`'s particles in `scene` instead of their own, as `frontpack validate --scene` reads them
/// from their file: re-expressed in the frame of the scene's container (absolute = origin +
/// local, less the new origin, exactly, rounded once). std::invalid_argument when they cannot
/// be in it: another dimension, spheres and a scene of shapes or the reverse, a template the
/// scene does not have.
PackingInput packing_in_scene(const PackingInput& in, Scene scene);

/// The overrides of `frontpack pack --seed/-j`, applied to `scene`, which is then checked as the
/// command checks it before any work (a scene of shapes resolved; what the run asks of the
/// machine; `threads` by check_threads). Throws SceneError or std::invalid_argument.
void prepare_scene(Scene& scene, std::optional<std::uint64_t> seed, std::optional<int> threads);

/// `frontpack pack` of a prepared scene, its outputs not written: packed (progress as the
/// command's progress line gets it), checked with the full analysis, recorded.
PackOutcome pack_scene(const Scene& scene, const ProgressFn& progress);

/// `frontpack analyze PACKING [--scene S]`'s analysis: with the scene's container, law and
/// contact tolerance when the packing has a scene (a packing of shapes needs it; spheres: the
/// scene's contact tolerance, shapes: its minimisation gap tolerance), at `tolerance` when >= 0.
PackingAnalysis analyze_input(const PackingInput& in, double tolerance, int threads);

/// `frontpack validate PACKING --scene S`'s verdict (the packing needs its scene): no overlap
/// beyond the tolerance (`tolerance` when >= 0, else the one `pack` checks against), every
/// particle inside, the size tests at level `alpha` (when >= 0, else pack's).
ValidationReport validate_input(const PackingInput& in, double tolerance, double alpha, int threads);

}  // namespace fp
