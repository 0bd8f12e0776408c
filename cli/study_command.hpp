#pragma once
// `frontpack study STUDY.yaml` (and frontpack.study from Python): every run of a study
// (core/io/study_yaml.hpp) packed by the frontpack command in its own process, `jobs` at once,
// into OUTPUT/runs/<run>/ (record.json, the packing, log.txt); runs whose record is already
// there are kept (a study killed and started again goes on where it was); OUTPUT/results.csv,
// one row per run with its main figures, and OUTPUT/results-full.csv with every figure
// (cli/study_table.hpp), rewritten as each run ends; the standard figures in
// OUTPUT/plots (python/plot_study.py, Debian's python3-matplotlib).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "cli/study_runs.hpp"
#include "cli/study_table.hpp"
#include "core/io/study_yaml.hpp"

namespace fp {

struct StudyOptions {
  std::string executable;                ///< the frontpack command that packs each run
  int jobs = 0;                          ///< > 0: replaces the study's `jobs`
  bool plots = true;
  std::string python = "/usr/bin/python3";
  bool quiet = false;                    ///< no line per run on stdout
  bool list_only = false;                ///< --list: the runs (checked), each kept or to run, and nothing run
  std::function<void()> poll;            ///< called about every 20 ms while runs go on; may throw to stop them
  /// After each run, kept or ended: the run, its row, runs ended so far, runs in all.
  std::function<void(const StudyRun&, const StudyRow&, std::size_t, std::size_t)> on_run;
};

struct StudyOutcome {
  std::string csv_path;            ///< the main figures (results.csv)
  std::string full_csv_path;       ///< every figure of every run (results-full.csv)
  std::vector<std::string> plots;  ///< the figures drawn
  std::string plots_problem;       ///< why there are none, when plots were asked for
  std::size_t runs = 0, kept = 0, ran = 0, invalid = 0, incomplete = 0, failed = 0;
  std::vector<StudyRow> rows;      ///< the CSV's rows, in its order
};

/// Runs the study. Every run's scene is read and checked first (a problem names the study
/// file's line or the scene file's, and the run), and every file it writes against every file
/// it reads (core/io/output_paths.hpp: no output is an input or another output); throws
/// SceneError / OutputPathError / std::runtime_error then, before anything is written.
StudyOutcome run_study(const StudySpec& spec, const StudyOptions& options);

/// The command: returns its exit code (0; 1 a run failed or the figures could not be drawn;
/// 2 bad study, or one that would write over what it reads; 3 a packing failed its validation).
int run_study_command(const std::string& study_path, StudyOptions options);

}  // namespace fp
