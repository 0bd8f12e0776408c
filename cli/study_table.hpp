#pragma once
// The study's table: one row per run, its parameters' values, seed and status, then every
// number, flag and name of its run record (`frontpack pack --record`: timings, metrics,
// counters, info, the analysis), flattened to dotted column names; lists (histograms, curves)
// stay in the record.
#include <map>
#include <string>
#include <vector>

#include "cli/study_runs.hpp"

namespace fp {

struct StudyRow {
  std::vector<std::string> keys;                 ///< in the record's order
  std::map<std::string, std::string> values;     ///< CSV text of each key
};

/// The row of a run: its identity, `status` — ok or invalid (the record's validation) when
/// `record_text` is given, else failed — `message` (why it failed: `failure`), and the record's scalars.
StudyRow study_row(const StudySpec& spec, const StudyRun& run, const std::string& record_text, const std::string& failure = "");

/// The CSV of `rows` (those of runs not ended yet, without keys, are left out): the columns are
/// the union of their keys, in order of first appearance; a value a run does not have is empty.
/// Text with a comma, quote or newline is quoted.
std::string study_csv(const std::vector<StudyRow>& rows);

/// The main figures of each run, to read at a glance: `run`, the parameters, `seed`, `status`,
/// then those of `kStudyMainFigures` some run has (to 5 significant digits), then `message`.
std::string study_short_csv(const StudySpec& spec, const std::vector<StudyRow>& rows);

/// The record's figures the short table keeps, in its order.
inline const char* const kStudyMainFigures[] = {
    "n", "metrics.volume_fraction_container", "metrics.volume_fraction_core", "metrics.volume_fraction_reference_sphere",
    "metrics.mean_coordination", "metrics.rattler_fraction", "metrics.orientation_order",
    "metrics.max_overlap_over_smaller_radius", "metrics.particles_per_second", "timings.pack"};

/// The figure of a column, read back from a row ("" when the run has none).
std::string study_value(const StudyRow& row, const std::string& key);

}  // namespace fp
