#include "cli/study_command.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <list>
#include <map>
#include <sstream>
#include <thread>

#include "cli/child_process.hpp"
#include "cli/failure_report.hpp"
#include "cli/pack_api.hpp"
#include "cli/packing_input.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/output_paths.hpp"
#include "core/io/scene_yaml.hpp"

#ifndef FRONTPACK_STUDY_PLOT_SCRIPT
#error "FRONTPACK_STUDY_PLOT_SCRIPT must name python/plot_study.py"
#endif

namespace fp {
namespace {

namespace fs = std::filesystem;

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// The last line of a run's log that says something: why it failed.
std::string last_line(const std::string& path) {
  std::istringstream in(read_text(path));
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last;
}

/// Reads every run's scene with its changes and checks it as `pack` would (once per combination
/// of the parameters: the seeds share it); marks the runs of shapes. Returns the text of each
/// base scene (a kept run's record must have it); adds every file read (scenes, meshes) to `reads`.
std::map<std::string, std::string> check_runs(const StudySpec& spec, std::vector<StudyRun>& runs, std::vector<NamedPath>& reads) {
  std::map<std::string, std::string> base_texts;
  std::map<std::vector<std::size_t>, bool> checked;  // levels -> shapes
  for (StudyRun& run : runs) {
    if (auto it = checked.find(run.levels); it != checked.end()) {
      run.shapes = it->second;
      continue;
    }
    try {
      Scene scene = load_scene(run.scene_path, run.overrides);
      prepare_scene(scene, run.seed, spec.threads);
      run.shapes = !scene.particle_templates.empty();
      base_texts[run.scene_path] = scene.source_text;
      for (const NamedPath& r : scene_reads(scene, "study " + spec.path + ", run " + run.name)) reads.push_back(r);
    } catch (const SceneError& e) {
      throw SceneError(e.file(), e.line(), e.column(), e.key(), e.message() + " (study " + spec.path + ", run " + run.name + ")");
    } catch (const std::exception& e) {
      throw std::runtime_error(spec.path + ": run " + run.name + ": " + e.what());
    }
    checked[run.levels] = run.shapes;
  }
  return base_texts;
}

/// Refuses, before anything is written, a study that would write over a file it reads (the study
/// file, a scene, a mesh: e.g. a base scene kept as OUTPUT/results.csv) or write one file twice.
void check_study_writes(const StudySpec& spec, const std::vector<StudyRun>& runs, std::vector<NamedPath> reads, bool plots) {
  if (spec.path != "<dict>") reads.insert(reads.begin(), {spec.path, "the study", "study file"});
  const fs::path out(spec.output_dir);
  const std::string where = spec.path + ": the study's output folder '" + spec.output_dir + "'";
  // The folder, or the first part of its path that exists, must be a folder ("Not a directory",
  // exit 1, once came after the scene checks).
  {
    std::error_code ec;
    fs::path p = fs::absolute(out, ec);
    while (!ec && !p.empty() && !fs::exists(p, ec) && p.has_parent_path() && p.parent_path() != p) p = p.parent_path();
    if (!ec && fs::exists(p, ec) && !fs::is_directory(p, ec))
      throw OutputPathError(where + ": '" + p.string() + "' is a file, not a folder; give 'output:' a folder");
  }
  std::vector<NamedPath> writes{{(out / "results.csv").string(), where, "results table"},
                                {(out / "results-full.csv").string(), where, "full results table"}};
  if (plots) {
    writes.push_back({(out / "plots.json").string(), where, "figure request"});
    writes.push_back({(out / "plots" / "figures.txt").string(), where, "list of figures"});
    writes.push_back({(out / "plots" / "plot.log").string(), where, "log of the figures"});
    // The figures' names are the plot script's: no input may be in their folder.
    const auto folder_of = [](const fs::path& p) {
      std::error_code ec;
      const fs::path c = fs::weakly_canonical(fs::absolute(p, ec), ec);
      return ec ? fs::path() : c.parent_path();
    };
    const fs::path figures = folder_of(out / "plots" / "figures.txt");
    for (const NamedPath& r : reads)
      if (!figures.empty() && folder_of(r.path) == figures)
        throw OutputPathError(where + ": the figures' folder '" + (out / "plots").string() + "' holds the " + r.what + " '" +
                              r.path + "' (" + r.where + "): frontpack never writes over what it reads");
  }
  for (const StudyRun& run : runs) {
    const StudyRunFiles f = study_run_files(spec, run);
    const std::string named = spec.path + ": run " + run.name;
    writes.push_back({f.record, named, "run record"});
    writes.push_back({f.packing, named, "packing"});
    writes.push_back({f.log, named, "log"});
  }
  check_distinct_files(writes, reads);
}

/// What the plot script needs besides the CSV: the parameters (their values in order, and each
/// value's number on a numeric axis) and the figures asked for.
std::string plot_request(const StudySpec& spec) {
  nlohmann::ordered_json j;
  j["parameters"] = nlohmann::json::array();
  for (const auto& p : spec.parameters) {
    nlohmann::ordered_json par{{"name", p.name}, {"numeric", p.numeric}, {"axis_label", p.axis_label},
                               {"values", nlohmann::json::array()}, {"axis", p.axis}};
    for (const auto& l : p.levels) par["values"].push_back(l.label);
    j["parameters"].push_back(par);
  }
  j["seeds"] = spec.seeds.size();
  j["plots"] = nlohmann::json::array();
  for (const auto& p : spec.plots) j["plots"].push_back({{"x", p.x}, {"y", p.y}});
  return j.dump(2) + "\n";
}

/// Draws the figures into OUTPUT/plots; returns them, or sets `problem`.
std::vector<std::string> draw_plots(const StudySpec& spec, const StudyOptions& o, const std::string& csv_path, std::string& problem) {
  std::error_code ec;
  if (!fs::exists(o.python, ec)) {
    problem = o.python + " not found: the figures need Debian's python3 and python3-matplotlib (apt-get install python3-matplotlib)";
    return {};
  }
  const fs::path dir = fs::path(spec.output_dir) / "plots";
  fs::create_directories(dir);
  const std::string request = (fs::path(spec.output_dir) / "plots.json").string();
  write_text_file_atomically(request, plot_request(spec));
  const std::string list = (dir / "figures.txt").string();
  ChildProcess script({o.python, FRONTPACK_STUDY_PLOT_SCRIPT, csv_path, request, dir.string()}, (dir / "plot.log").string());
  while (!script.finished()) {
    if (o.poll) o.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (script.exit_code() == 3) {
    problem = "matplotlib is missing: apt-get install python3-matplotlib (the CSV is complete)";
    return {};
  }
  if (script.exit_code() != 0) {
    problem = "the plot script failed (exit " + std::to_string(script.exit_code()) + "): " + last_line((dir / "plot.log").string());
    return {};
  }
  std::vector<std::string> figures;
  std::istringstream in(read_text(list));
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) figures.push_back((dir / line).string());
  return figures;
}

std::string summary_of(const StudyRow& row) {
  if (study_value(row, "status") == "failed") return "failed: " + study_value(row, "message");
  std::ostringstream os;
  os << study_value(row, "status") << "  n " << study_value(row, "n");
  const auto figure = [&](const char* label, const std::string& key) {
    const std::string v = study_value(row, key);
    if (!v.empty()) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "  %s %.4g", label, std::strtod(v.c_str(), nullptr));
      os << buf;
    }
  };
  figure("VF", "metrics.volume_fraction_container");
  figure("z", "metrics.mean_coordination");
  figure("/s", "metrics.particles_per_second");
  return os.str();
}

}  // namespace

StudyOutcome run_study(const StudySpec& spec, const StudyOptions& o) {
  std::vector<StudyRun> runs = study_runs(spec);
  std::vector<NamedPath> reads;
  const std::map<std::string, std::string> base_texts = check_runs(spec, runs, reads);
  check_study_writes(spec, runs, std::move(reads), o.plots && !o.list_only);

  StudyOutcome out;
  out.runs = runs.size();
  out.csv_path = (fs::path(spec.output_dir) / "results.csv").string();
  out.full_csv_path = (fs::path(spec.output_dir) / "results-full.csv").string();
  const auto write_tables = [&] {
    write_text_file_atomically(out.full_csv_path, study_csv(out.rows));
    write_text_file_atomically(out.csv_path, study_short_csv(spec, out.rows));
  };
  out.rows.resize(runs.size());
  std::size_t ended = 0;
  const auto finish = [&](std::size_t i, const std::string& record, const std::string& failure) {
    out.rows[i] = study_row(spec, runs[i], record, failure);
    ++ended;
    const std::string status = study_value(out.rows[i], "status");
    if (status == "invalid") ++out.invalid;
    if (status == "incomplete") ++out.incomplete;
    if (status == "failed") ++out.failed;
    if (o.on_run) o.on_run(runs[i], out.rows[i], ended, runs.size());
    if (!o.quiet) {
      std::printf("[%zu/%zu] %s  %s\n", ended, runs.size(), runs[i].name.c_str(), summary_of(out.rows[i]).c_str());
      std::fflush(stdout);
    }
  };
  if (o.list_only) {
    for (const StudyRun& run : runs) {
      const bool done = study_run_record(spec, run, base_texts.at(run.scene_path)).has_value();
      out.kept += done;
      std::printf("%s  %s\n", done ? "kept  " : "to run", run.name.c_str());
    }
    return out;
  }
  fs::create_directories(fs::path(spec.output_dir) / "runs");
  std::deque<std::size_t> waiting;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (const auto record = study_run_record(spec, runs[i], base_texts.at(runs[i].scene_path))) {
      ++out.kept;
      finish(i, *record, "");
    } else {
      waiting.push_back(i);
    }
  }
  if (out.kept > 0) write_tables();

  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int jobs = o.jobs > 0 ? o.jobs : spec.jobs > 0 ? spec.jobs : std::max(1, hardware / spec.threads);
  std::list<std::pair<std::size_t, ChildProcess>> running;  // a list: a child is never moved once started
  while (!waiting.empty() || !running.empty()) {
    while (!waiting.empty() && static_cast<int>(running.size()) < jobs) {
      const std::size_t i = waiting.front();
      waiting.pop_front();
      const StudyRunFiles files = study_run_files(spec, runs[i]);
      fs::create_directories(files.folder);
      std::error_code ec;
      fs::remove(files.record, ec);  // another study's, or a run killed before it ended
      std::vector<std::string> argv{o.executable, "pack", runs[i].scene_path};
      for (const auto& c : runs[i].overrides) argv.insert(argv.end(), {"--set", c.key + "=" + c.value});
      argv.insert(argv.end(), {"--seed", std::to_string(runs[i].seed), "-j", std::to_string(spec.threads), "-q", "--record",
                               files.record, "-o", files.packing});
      running.emplace_back(i, ChildProcess(argv, files.log));
    }
    if (o.poll) o.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    for (auto it = running.begin(); it != running.end();) {
      if (!it->second.finished()) {
        ++it;
        continue;
      }
      const std::size_t i = it->first;
      const int code = it->second.exit_code();
      const StudyRunFiles files = study_run_files(spec, runs[i]);
      ++out.ran;
      std::error_code ec;
      if ((code == 0 || code == 3 || code == 4) && fs::is_regular_file(files.record, ec)) {
        if (!spec.keep_packings) fs::remove(files.packing, ec);
        finish(i, read_text(files.record), "");
      } else {
        finish(i, "", "exit " + std::to_string(code) + ": " + last_line(files.log));
      }
      write_tables();
      it = running.erase(it);
    }
  }
  write_tables();
  if (o.plots) out.plots = draw_plots(spec, o, out.full_csv_path, out.plots_problem);
  return out;
}

int run_study_command(const std::string& study_path, StudyOptions options) {
  StudySpec spec;
  try {
    const Activity doing("reading study '" + study_path + "'");
    spec = load_study(study_path);
  } catch (...) {
    return report_failure(2);
  }
  StudyOutcome out;
  try {
    const Activity doing("running study '" + study_path + "'");
    out = run_study(spec, options);
  } catch (const SceneError&) {
    return report_failure(2);
  } catch (const OutputPathError&) {
    return report_failure(2);
  } catch (...) {
    return report_failure(1);
  }
  if (options.list_only) {
    std::printf("frontpack study   %s: %zu runs, %zu kept from before, %zu to run\n", study_path.c_str(), out.runs, out.kept,
                out.runs - out.kept);
    return 0;
  }
  if (!options.quiet) {
    std::printf("frontpack study   %s: %zu runs (%zu kept from before, %zu run now), %zu invalid, %zu incomplete, %zu failed\n",
                study_path.c_str(), out.runs, out.kept, out.ran, out.invalid, out.incomplete, out.failed);
    std::printf("  table          %s (main figures; every figure in %s)\n", out.csv_path.c_str(), out.full_csv_path.c_str());
    if (!out.plots.empty()) std::printf("  figures        %s (%zu)\n", (fs::path(spec.output_dir) / "plots").string().c_str(), out.plots.size());
  }
  if (!out.plots_problem.empty()) std::fprintf(stderr, "frontpack: error: no figures: %s\n", out.plots_problem.c_str());
  if (out.failed > 0) {
    std::fprintf(stderr, "frontpack: error: %zu of %zu runs failed (the table's message column; each run's log.txt)\n", out.failed, out.runs);
    return 1;
  }
  if (!out.plots_problem.empty()) return 1;
  return out.invalid > 0 ? 3 : out.incomplete > 0 ? 4 : 0;
}

}  // namespace fp
