#pragma once
// The runs of a study (core/io/study_yaml.hpp): every combination of its parameters' values
// (the first parameter varies slowest) times every seed, each with its own folder, and whether
// a run's folder already holds its result (a study resumes: done runs are kept).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/io/scene_override.hpp"
#include "core/io/study_yaml.hpp"

namespace fp {

struct StudyRun {
  std::vector<std::size_t> levels;  ///< per parameter, the index of its value
  std::uint64_t seed = 1;
  std::string name;                 ///< "shape=ellipse,ratio=2,seed=1": its folder under runs/, and the CSV's `run`
  std::vector<SceneOverride> overrides;
  std::string scene_path;           ///< its base scene: the study's, or the one its values name
  bool shapes = false;              ///< a scene of shapes (its packing is written as json), known once its scene is read
};

/// Every run of `spec`, in the CSV's order. Folder names are the labels made safe for a file
/// name (and unique: a suffix where two would be the same).
std::vector<StudyRun> study_runs(const StudySpec& spec);

/// Where a run's files are.
struct StudyRunFiles {
  std::string folder, record, packing, log;
};
StudyRunFiles study_run_files(const StudySpec& spec, const StudyRun& run);

/// The text of the run's record when it is there and is the record of this run: the same base
/// scene (path and text), the same changes, the same seed (and its packing is there when the
/// study keeps packings); nothing otherwise (the run is to be made).
std::optional<std::string> study_run_record(const StudySpec& spec, const StudyRun& run, const std::string& base_scene_text);

}  // namespace fp
