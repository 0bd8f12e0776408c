#pragma once
// Reads a study file (YAML): a base scene, parameters swept over a grid of their values, and
// seeds; `frontpack study` (cli/study_command.hpp) packs every run. Every problem is a SceneError
// naming the study file, line, column and key.
//
// Schema ("*" = required):
//   scene*: the base scene file, relative to the study file's folder
//   seeds: [s, ...] (unsigned 64-bit) or a count N (= 1, 2, ..., N); default [1]
//   parameters: a list; the runs are every combination of their values, times every seed
//     - key: a dotted scene key (as --set: packer.front, particles.radius.max, particles[0].aspect_ratio)
//       values*: [v, ...] (any YAML: numbers, names, lists, mappings)
//       name: the CSV column and plot axis (default: the key)
//     - name*: a parameter whose value is put into one or more keys
//       values*: [v, ...]
//       set*: {dotted key: template, ...} where `$name` is the value (`[1, $b, $b]`), `${expression}`
//             a number computed from it (`${2 * r}`, core/io/study_expression.hpp), and `$$` a dollar
//             sign; the value as a whole (`$b`) may be any YAML, in text (`mesh-$b.stl`) a scalar
//     - name*: a parameter whose cases change several keys at once
//       cases*: {label: {dotted key: value, ...}, ...}  (e.g. ellipse: {dimension: 2, particles.shape: ellipse})
//     The key `scene` (a case's, or `key: scene` with file names as values) changes the base scene
//     itself: a file relative to the study file's folder (e.g. every named scene x a solver).
//   jobs: runs at once, >= 1 (default: hardware threads / threads)
//   threads: each run's threads, >= 1 (default 1)
//   output: the study's folder, relative to the study file's folder (default: <study file name>.out)
//   packings: keep each run's packing file (csv; json for shapes), default true
//   plots: more figures than the standard ones: [{x: parameter name, y: CSV column}, ...]
#include <cstdint>
#include <string>
#include <vector>

#include "core/io/scene.hpp"
#include "core/io/scene_override.hpp"

namespace fp {

/// One value of a parameter: its label (the CSV's, the plots') and the changes it makes.
struct StudyLevel {
  std::string label;
  std::string name_part;   ///< the value in run names: "0.5", "1_0.5_0.5" for [1, 0.5, 0.5], a case's label
  std::vector<SceneOverride> overrides;
  std::string scene_path;  ///< `scene: FILE` in a case (or `key: scene`): another base scene for its runs, resolved
};

struct StudyParameter {
  std::string name;
  std::string name_part;     ///< the parameter in run names: its name, or the last part of its key ("aspect_ratio")
  std::vector<StudyLevel> levels;
  bool numeric = false;      ///< every value has a number on the plots' axis (`axis`)
  std::vector<double> axis;  ///< per value: the number itself, or a list's varying entry ([1, b, b]: b)
  std::string axis_label;    ///< the axis's name: the parameter's, with the list's form ("axes [1, x, x]")
  SourceSpot spot;
};

struct StudyPlot {
  std::string x;  ///< a parameter's name
  std::string y;  ///< a CSV column
};

struct StudySpec {
  std::string path;        ///< the study file ("<dict>" from Python)
  std::string text;        ///< its text
  std::string scene_path;  ///< the base scene, resolved
  std::vector<std::uint64_t> seeds{1};
  std::vector<StudyParameter> parameters;
  int jobs = 0;            ///< 0: hardware threads / threads
  int threads = 1;
  std::string output_dir;  ///< resolved
  bool keep_packings = true;
  std::vector<StudyPlot> plots;
};

/// Most runs a study may have (each is a process and a folder).
inline constexpr std::size_t kMaxStudyRuns = 100000;
/// Most runs at once (`jobs`, -J, frontpack.study's jobs=).
inline constexpr int kMaxStudyJobs = 1024;

/// Reads `path`. Throws SceneError.
StudySpec load_study(const std::string& path);

/// Parses study text; `source_name` names it in messages and its folder resolves `scene` and
/// `output` (the working directory when it has none).
StudySpec parse_study(const std::string& text, const std::string& source_name);

}  // namespace fp
