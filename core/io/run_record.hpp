#pragma once
// The JSON run record: what was run (scene text, seed, version) and what came out (counts,
// timings, metrics). Only run_record.cpp and analysis_json.cpp include nlohmann_json.
//
// Layout (keys always present, in this order, so identical input gives identical bytes):
//   frontpack_version, dimension, seed, n, scene {path, text}, container, distribution,
//   bounds ({lo:[x,y,z], hi:[x,y,z]} absolute, or null), frame_origin [x,y,z], density,
//   timings {name: seconds},
//   metrics {name: value}, counters {name: integer}, info {name: string},
//   and, when embedded, particles {x:[...], y:[...], (z:[...] in 3D), r:[...]}.
// Doubles are printed in the shortest form that reads back to the same double; NaN and
// infinities become null (JSON has no spelling for them). Particle coordinates are absolute,
// written as the exact decimal of frame_origin + local (core/io/exact_decimal.hpp).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/packing.hpp"
#include "core/geometry/vec.hpp"

namespace fp {

struct RunRecord {
  std::string version;
  std::string scene_path;
  std::string scene_text;
  std::vector<std::string> scene_overrides;  ///< Scene::overrides ("KEY=VALUE", in order)
  std::uint64_t seed = 1;
  int dimension = 3;
  std::uint64_t n = 0;
  std::string container_description;
  std::string distribution_description;
  std::optional<Aabb<3>> bounds;  ///< container bounds in the local frame (2D: z = 0); also the LAMMPS box
  Vec3 origin = Vec3::Zero();     ///< the frame origin of the bounds and of the particles (absolute)
  double density = 1.0;           ///< particle density for the LAMMPS data file
  std::vector<std::pair<std::string, double>> timings;  ///< seconds
  std::vector<std::pair<std::string, double>> metrics;
  std::vector<std::pair<std::string, std::uint64_t>> counters;
  std::vector<std::pair<std::string, std::string>> info;
  /// The packing's full analysis as JSON text (core/io/analysis_json.hpp), embedded under
  /// "analysis"; empty: none.
  std::string analysis_json;
  /// Embed the particles when a packing is passed to run_record_json. write_packing(Json)
  /// always embeds them (that is what the json output format is).
  bool embed_particles = false;
};

/// The record alone (no particles), pretty-printed, ending with a newline.
std::string run_record_json(const RunRecord& record);

/// The record, plus the particles of `packing` if record.embed_particles.
template <int D>
std::string run_record_json(const RunRecord& record, const Packing<D>& packing);

/// Writes run_record_json(record) atomically to `path` (see atomic_file.hpp).
void write_run_record(const std::string& path, const RunRecord& record);

/// Reads the particles embedded in a json output, into the frame of `origin` (centres =
/// absolute - origin, subtracted exactly on the text; see packing_readers.hpp). Throws
/// std::runtime_error naming `source_name` (and line/column for syntax errors) if the text is
/// not such a file or its dimension is not D.
template <int D>
Packing<D> packing_from_json(const std::string& text, const std::string& source_name,
                             const Vec<D>& origin = Vec<D>::Zero());

/// The "dimension" of a run record or json output. Throws like packing_from_json.
int run_record_dimension(const std::string& text, const std::string& source_name);

/// Picks arrays of a JSON text by their path from the top level (the keys, "[]" for an item of an
/// array): a slot index, or -1.
using JsonArraySelect = std::function<int(const std::vector<std::string>& path)>;

/// The text of every number directly inside the arrays `select` picks, per slot (`slots` of
/// them), in the order of the text: a DOM keeps only the rounded doubles, and the readers subtract
/// a far frame's origin from the text itself (core/io/exact_decimal.hpp).
std::vector<std::vector<std::string>> json_number_texts(const std::string& text, std::size_t slots, const JsonArraySelect& select);

/// A JSON parser's message without nlohmann's "[json.exception.parse_error.101] " prefix (an
/// internal id): what a user is shown.
std::string json_error_text(const char* what);

}  // namespace fp
