// The `frontpack` command. Exit codes: 0 success, 1 run-time failure (e.g. an output cannot be
// written), 2 bad input (scene file, options), 3 the finished packing failed validation, 4 it is
// valid but incomplete: the scene's stop ended the front before it filled the container, a target
// was missed, the packer placed nearly nothing of what the scene asks, or the packing falls short
// of its size law only for want of room.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/analyze_command.hpp"
#include "cli/failure_report.hpp"
#include "cli/pack_command.hpp"
#include "cli/study_command.hpp"
#include "cli/usage_error.hpp"
#include "cli/validate_command.hpp"
#include "core/io/scene_override.hpp"
#include "core/io/temp_file_registry.hpp"
#include "core/io/text_excerpt.hpp"
#include "frontpack/version.hpp"
#ifdef FRONTPACK_WITH_MPI
#include "cli/mpi_exchange.hpp"
#endif

namespace {

/// 1 without a launcher; under `mpirun -np K` (K > 1) the ranks pack together when this binary
/// was built with FRONTPACK_MPI, and refuse otherwise (each would write the same outputs).
int launched_processes() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
  return 1;
}

int run_pack(fp::PackCommandOptions& pack, int argc, char** argv) {
  if (launched_processes() == 1) return fp::run_pack_command(pack);
#ifdef FRONTPACK_WITH_MPI
  fp::MpiSession mpi(&argc, &argv);
  pack.exchange = &mpi.exchange();
  const int code = fp::run_pack_command(pack);
  if (code != 0) mpi.abort(code);
  return code;
#else
  (void)argc, (void)argv;
  std::cerr << "frontpack: error: started by an MPI launcher with " << launched_processes()
            << " processes, but this frontpack was built without MPI (configure with -DFRONTPACK_MPI=ON; see the README)\n";
  return 2;
#endif
}

/// The options `pack` and `densify` share: where and how the packing is written, the seed, the
/// record, quiet.
void add_output_options(CLI::App* cmd, fp::PackCommandOptions& o, std::string& seed_text, const CLI::Validator& decimal_seed) {
  cmd->add_option("-o,--output", o.output_paths,
                  "write the packing to PATH, repeatable (replaces the scene's output list; each format from its "
                  "extension, or --format for a single -o)")
      ->allow_extra_args(false);  // one PATH per -o: `-o a.csv scene.yaml` keeps the scene an argument
  cmd->add_option("--format", o.format, "format of a single -o: vtu | yade | lammps | csv | json");
  cmd->add_option("--surfaces", o.surfaces,
                  "the surfaces side file beside every vtu output of particles of shapes: fine (default) | coarse "
                  "(half the segments per turn: a sixth of the size for capsules) | none")
      ->check(CLI::IsMember({"fine", "coarse", "none"}));
  cmd->add_option("--seed", seed_text, "override the scene's 64-bit seed (decimal)")->check(decimal_seed);
  cmd->add_option("--record", o.record_path, "also write the JSON run record (without particles) to PATH");
  cmd->add_flag("-q,--quiet", o.quiet, "no summary on stdout");
}

/// --set KEY=VALUE, repeatable: a change to the scene as it is read (core/io/scene_override.hpp).
void add_set_option(CLI::App* cmd, std::vector<fp::SceneOverride>& overrides) {
  const CLI::Validator key_equals_value(
      [](const std::string& v) {
        try {
          fp::scene_override_argument(v);
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
        return std::string();
      },
      "KEY=VALUE");
  cmd->add_option_function<std::vector<std::string>>(
         "--set",
         [&overrides](const std::vector<std::string>& args) {
           for (const auto& a : args) overrides.push_back(fp::scene_override_argument(a));
         },
         "change the scene as it is read: a dotted key and a YAML value (packer.front=fifo, particles.radius.max=0.5, "
         "container.max=[2,2,2]); repeatable, applied in order")
      ->allow_extra_args(false)
      ->check(key_equals_value);
}

int run(int argc, char** argv) {
  CLI::App app{"frontpack: dense packings of spheres, disks and non-spherical particles (2D and 3D) by the advancing "
               "front, and the methods beside it"};
  app.set_version_flag("--version", std::string("frontpack ") + fp::kVersion);
  app.require_subcommand(1);

  fp::PackCommandOptions pack;
  CLI::App* pack_cmd = app.add_subcommand("pack", "pack the container of SCENE and write the outputs");
  pack_cmd->add_option("scene", pack.scene_path, "scene file (YAML; its relative paths start at its own folder, those of the options at the working directory)")->required();
  // Read as text and converted here: CLI11 would wrap "-1" round to 2^64-1, clamp a number past
  // 2^64-1 and read "042" as octal 34, where the scene's `seed: 042` is 42. Decimal digits only.
  std::string seed_text;
  // NonNegativeNumber let "nan" through: a tolerance every comparison fails against.
  const CLI::Validator tolerance_value(
      [](const std::string& v) {
        double t = 0;
        const auto res = std::from_chars(v.data(), v.data() + v.size(), t);
        if (res.ec != std::errc() || res.ptr != v.data() + v.size() || !(t >= 0 && t < 1))
          return "a tolerance is a number in [0, 1), relative to the smaller radius of each pair; got '" + fp::excerpt(v) + "'";
        return std::string();
      },
      "TOL");
  const CLI::Validator decimal_seed(
      [](const std::string& v) {
        std::uint64_t seed = 0;
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), seed, 10);
        if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos)
          return "a seed is an unsigned 64-bit decimal integer, got '" + v + "'";
        if (ec == std::errc::result_out_of_range || end != v.data() + v.size())
          return "the seed " + v + " is beyond 2^64-1 = 18446744073709551615";
        return std::string();
      },
      "UINT64");
  add_output_options(pack_cmd, pack, seed_text, decimal_seed);
  add_set_option(pack_cmd, pack.scene_overrides);
  pack_cmd->add_option("-j,--threads", pack.threads,
                       "threads (0: every hardware thread; replaces the scene's packer.threads). Above 1 the "
                       "container grows in blocks, with the same output for every thread count; the validation and analysis "
                       "use them too")
      ->check(CLI::Range(0, 4096));
  pack_cmd->add_flag("--progress", pack.force_progress, "progress line on stderr even when it is not a terminal");

  // CLI11 would answer "A subcommand is required" to a mistyped command.
  const std::string command = argc > 1 ? argv[1] : "";
  if (!command.empty() && command[0] != '-' && command != "pack" && command != "densify" && command != "validate" &&
      command != "analyze" && command != "study") {
    std::cerr << "frontpack: error: unknown command '" << command
              << "' (commands: pack, densify, validate, analyze, study; see frontpack --help)\n";
    return 2;
  }
  fp::PackCommandOptions densify;
  CLI::App* densify_cmd = app.add_subcommand(
      "densify", "fill the voids of a packing of spheres (disks) with more of the scene's spheres and write the outputs");
  densify_cmd->add_option("packing", densify.input_path, "packing file (vtu, yade, lammps, csv or json)")->required();
  densify_cmd->add_option("--scene", densify.scene_path, "the scene it fills: container, radii, `densify:` options")->required();
  densify_cmd->add_option("--input-format", densify.input_format, "format of PACKING (default: from its extension)");
  add_output_options(densify_cmd, densify, seed_text, decimal_seed);
  add_set_option(densify_cmd, densify.scene_overrides);
  densify_cmd->add_option("-j,--threads", densify.threads, "threads of the validation and analysis (0: every hardware thread)")
      ->check(CLI::Range(0, 4096));

  fp::ValidateCommandOptions check;
  CLI::App* validate_cmd = app.add_subcommand(
      "validate", "check a packing file against its scene: no overlap, every particle inside, the radii");
  validate_cmd->add_option("packing", check.packing_path, "packing file (vtu, yade, lammps, csv or json)")->required();
  validate_cmd->add_option("--scene", check.scene_path, "the scene the packing fills")->required();
  add_set_option(validate_cmd, check.scene_overrides);
  validate_cmd->add_option("--format", check.format, "format of PACKING (default: from its extension)");
  validate_cmd->add_option("--tolerance", check.tolerance,
                           "overlap allowed, relative to the smaller radius of each pair (default: the scene's contact_tolerance)")
      ->check(tolerance_value);
  validate_cmd->add_option("--ks-alpha", check.ks_alpha, "level of the radii test (K-S; chi-square for a discrete law, exact match for a constant one): "
                           "the radii fail when its p-value is below this (default as pack: 0.001, or 0 (the range only) for the voids' own radii of method tet_mesh or densify radii: fit)")
      ->check(CLI::Range(0.0, 1.0));
  validate_cmd->add_option("-j,--threads", check.threads,
                           "threads (default 0: every hardware thread); the report is the same for every count")
      ->check(CLI::Range(0, 4096));
  validate_cmd->add_flag("-q,--quiet", check.quiet, "no report; the exit code only");

  fp::AnalyzeCommandOptions an;
  CLI::App* analyze_cmd =
      app.add_subcommand("analyze", "quality figures of a packing file: VF, coordination, fabric, K-S, g(r)");
  analyze_cmd->add_option("packing", an.packing_path, "packing file (vtu, yade, lammps, csv or json)")->required();
  analyze_cmd->add_option("--scene", an.scene_path,
                          "the scene it fills: container, requested radii, contact tolerance (default: the "
                          "particles' bounding box, no distribution)");
  add_set_option(analyze_cmd, an.scene_overrides);
  analyze_cmd->add_option("--format", an.format, "format of PACKING (default: from its extension)");
  analyze_cmd->add_option("--json", an.json_path, "write every figure as JSON to OUT");
  analyze_cmd->add_option("--plots", an.plots_dir, "draw PNG figures into DIR (needs python3-matplotlib)");
  analyze_cmd->add_option("--tolerance", an.tolerance, "contact tolerance relative to min(ri, rj)")
      ->check(tolerance_value);
  analyze_cmd->add_option("--python", an.python, "interpreter with matplotlib (default /usr/bin/python3)");
  analyze_cmd->add_option("-j,--threads", an.threads,
                          "threads (default 0: every hardware thread); the figures are the same for every count")
      ->check(CLI::Range(0, 4096));
  analyze_cmd->add_flag("-q,--quiet", an.quiet, "no table");

  std::string study_path;
  fp::StudyOptions study;
  bool no_plots = false;
  CLI::App* study_cmd = app.add_subcommand(
      "study", "pack every run of a study (a base scene, parameters swept, seeds) in parallel processes: results.csv (main figures), results-full.csv (every figure), the plots");
  study_cmd->add_option("study", study_path, "study file (YAML; README: Comparative studies)")->required();
  study_cmd->add_option("-J,--jobs", study.jobs, "runs at once (replaces the study's jobs; default: hardware threads / threads)")
      ->check(CLI::Range(1, fp::kMaxStudyJobs));
  study_cmd->add_flag("--no-plots", no_plots, "the tables only (no figures)");
  study_cmd->add_flag("--list", study.list_only, "check every run's scene, list the runs (kept or to run) and run nothing");
  study_cmd->add_option("--python", study.python, "interpreter with matplotlib (default /usr/bin/python3)");
  study_cmd->add_flag("-q,--quiet", study.quiet, "no line per run");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::string command;
    for (const CLI::App* sub : app.get_subcommands()) command = sub->get_name();
    std::cerr << "frontpack: error: " << fp::usage_error_text(e, command) << "\n";
    return 2;
  }
  if (validate_cmd->parsed()) return fp::run_validate_command(check);
  if (densify_cmd->parsed()) {
    if (!seed_text.empty()) {
      std::uint64_t seed = 0;
      std::from_chars(seed_text.data(), seed_text.data() + seed_text.size(), seed, 10);  // checked above
      densify.seed = seed;
    }
    return fp::run_pack_command(densify);
  }
  if (analyze_cmd->parsed()) return fp::run_analyze_command(an);
  if (study_cmd->parsed()) {
    std::error_code ec;
    study.executable = std::filesystem::read_symlink("/proc/self/exe", ec).string();
    if (ec) study.executable = argv[0];
    study.plots = !no_plots;
    return fp::run_study_command(study_path, study);
  }
  if (pack_cmd->parsed()) {
    if (!seed_text.empty()) {
      std::uint64_t seed = 0;
      std::from_chars(seed_text.data(), seed_text.data() + seed_text.size(), seed, 10);  // checked above
      pack.seed = seed;
    }
    pack.progress = pack.force_progress || isatty(fileno(stderr));
    return run_pack(pack, argc, argv);
  }
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  fp::install_temp_file_cleanup();  // Ctrl-C or kill while writing leaves no *.tmp-PID behind
  try {  // the commands report their own failures; this is the net under them
    return run(argc, argv);
  } catch (...) {
    return fp::report_failure(1);
  }
}
