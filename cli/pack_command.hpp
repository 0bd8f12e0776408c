#pragma once
// `frontpack pack`: scene -> packing -> metrics -> validation -> outputs -> summary; and
// `frontpack densify`: packing file + scene -> void filling -> the same checks and outputs.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/io/scene_override.hpp"

namespace fp {

class BlockExchange;

struct PackCommandOptions {
  std::string scene_path;
  std::vector<SceneOverride> scene_overrides;  ///< --set KEY=VALUE, in order
  std::string input_path;              ///< densify: the packing to fill (else the scene is packed)
  std::string input_format;            ///< densify: its format (default: from its extension)
  std::vector<std::string> output_paths;  ///< -o, repeatable: replace the scene's outputs
  std::string format;                  ///< --format for a single -o
  std::string surfaces;                ///< --surfaces fine | coarse | none: every vtu output's (shapes)
  std::string record_path;             ///< --record: JSON run record without particles
  std::optional<std::uint64_t> seed;   ///< --seed
  std::optional<int> threads;          ///< -j/--threads (replaces the scene's packer.threads)
  bool quiet = false;
  bool progress = false;               ///< progress line on stderr
  bool force_progress = false;
  /// Under mpirun (cli/mpi_exchange.hpp): the ranks grow the blocks together; rank 0 checks,
  /// writes and summarises, the others only pack.
  BlockExchange* exchange = nullptr;
};

/// Runs the command; returns the process exit code (0, 1, 2 or 3, see main.cpp).
int run_pack_command(const PackCommandOptions& options);

}  // namespace fp
