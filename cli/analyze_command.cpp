#include "cli/analyze_command.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "cli/packing_input.hpp"
#include "core/io/analysis_json.hpp"
#include "core/io/atomic_file.hpp"
#include "core/metrics/packing_analysis.hpp"

#ifndef FRONTPACK_PLOT_SCRIPT
#error "FRONTPACK_PLOT_SCRIPT must name python/plot_analysis.py"
#endif

namespace fp {
namespace {

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// The radii's empirical CDF beside the requested one, for the radius figure (CSV: r,empirical,requested).
std::string radius_cdf_csv(std::vector<double> radii, const RadiusDistribution* dist) {
  std::sort(radii.begin(), radii.end());
  std::ostringstream os;
  os.precision(17);
  os << "r,empirical,requested\n";
  const std::size_t n = radii.size(), step = std::max<std::size_t>(1, n / 2000);
  for (std::size_t i = 0; i < n; i += step) {
    os << radii[i] << ',' << static_cast<double>(i + 1) / static_cast<double>(n) << ',';
    if (dist) os << dist->cdf(radii[i]);
    os << '\n';
  }
  return os.str();
}

/// Runs the plot script; returns an empty string on success, else what went wrong.
std::string draw_plots(const AnalyzeCommandOptions& o, const std::string& json_text, const std::string& cdf_text) {
  namespace fs = std::filesystem;
  if (!fs::exists(o.python))
    return o.python + " not found: the plots need Debian's python3 and python3-matplotlib (apt-get install python3-matplotlib)";
  const fs::path tmp = fs::path(o.plots_dir) / ".frontpack-plot-data";
  fs::create_directories(tmp);
  write_text_file_atomically((tmp / "analysis.json").string(), json_text);
  write_text_file_atomically((tmp / "radius_cdf.csv").string(), cdf_text);
  const std::string cmd = shell_quoted(o.python) + " " + shell_quoted(FRONTPACK_PLOT_SCRIPT) + " " +
                          shell_quoted((tmp / "analysis.json").string()) + " " +
                          shell_quoted((tmp / "radius_cdf.csv").string()) + " " + shell_quoted(o.plots_dir);
  const int status = std::system(cmd.c_str());
  std::error_code ec;
  fs::remove_all(tmp, ec);
  if (!WIFEXITED(status)) return "the plot script did not finish";
  switch (WEXITSTATUS(status)) {
    case 0: return "";
    case 3: return "matplotlib is missing: apt-get install python3-matplotlib (the numeric analysis is complete)";
    default: return "the plot script failed (exit " + std::to_string(WEXITSTATUS(status)) + ")";
  }
}

template <int D>
int analyze(const std::optional<Scene>& scene, const Packing<D>& P, const AnalyzeCommandOptions& o) {
  const Container<D>* container = nullptr;
  const RadiusDistribution* dist = nullptr;
  AnalysisOptions opt;
  if (scene) {
    container = scene->container<D>();
    dist = scene->radii.get();
    opt.contact_tolerance = scene->packer.contact_tolerance;
  }
  if (o.tolerance >= 0) opt.contact_tolerance = o.tolerance;
  const PackingAnalysis a = analyze_packing<D>(P, container, dist, opt);
  const std::string json = analysis_json(a);
  if (!o.json_path.empty()) write_text_file_atomically(o.json_path, json);
  if (!o.quiet) {
    std::printf("frontpack analyze   %s%s%s (%dD)\n", o.packing_path.c_str(), scene ? "   scene " : "",
                scene ? scene->source_path.c_str() : "", D);
    std::printf("%s\n", a.summary().c_str());
  }
  if (o.plots_dir.empty()) return 0;
  const std::string problem = draw_plots(o, json, radius_cdf_csv(P.radii, dist));
  if (!problem.empty()) {
    std::fprintf(stderr, "frontpack: error: no plots: %s\n", problem.c_str());
    return 1;
  }
  if (!o.quiet) std::printf("  plots          %s\n", o.plots_dir.c_str());
  return 0;
}

}  // namespace

int run_analyze_command(const AnalyzeCommandOptions& o) {
  PackingInput in;
  try {
    if (!o.plots_dir.empty() && !std::filesystem::is_directory(o.plots_dir))
      throw std::runtime_error("plots folder '" + o.plots_dir + "' does not exist");
    const auto json_parent = std::filesystem::path(o.json_path).parent_path();
    if (!o.json_path.empty() && !json_parent.empty() && !std::filesystem::is_directory(json_parent))
      throw std::runtime_error("output folder '" + json_parent.string() + "' does not exist (for --json " + o.json_path + ")");
    in = read_packing_input(o.packing_path, o.format, o.scene_path);
  } catch (const std::exception& e) {  // the scene parser and the readers name file, line and key
    std::fprintf(stderr, "frontpack: error: %s\n", e.what());
    return 2;
  }
  try {
    return in.dimension == 2 ? analyze<2>(in.scene, in.packing2, o) : analyze<3>(in.scene, in.packing3, o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "frontpack: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace fp
