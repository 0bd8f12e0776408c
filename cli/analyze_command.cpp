#include "cli/analyze_command.hpp"

#include <stdlib.h>  // mkdtemp
#include <sys/wait.h>

#include <cerrno>
#include <cstring>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "cli/failure_report.hpp"
#include "cli/packing_input.hpp"
#include "contact/shape_validation.hpp"
#include "core/io/analysis_json.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/output_paths.hpp"
#include "core/io/temp_file_registry.hpp"
#include "core/io/text_buffer.hpp"
#include "core/metrics/fabric.hpp"
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

/// The figures python/plot_analysis.py draws (keep in step with the script).
const char* const kPlotFiles[] = {"vf_curve.png", "coordination.png", "radii.png",
                                  "rdf.png",      "partial_coordination.png", "fabric.png"};

/// A private folder inside the plots folder (mkdtemp: never one of the user's) for the script's
/// input and output. Its files are registered for removal on Ctrl-C; removed with it at the end.
class PlotWorkFolder {
 public:
  explicit PlotWorkFolder(const std::string& plots_dir) {
    std::string name = (std::filesystem::path(plots_dir) / ".frontpack-plot-XXXXXX").string();
    if (!::mkdtemp(name.data()))
      throw std::runtime_error("cannot create a temporary folder in '" + plots_dir + "': " + std::strerror(errno));
    path_ = name;
    slots_.push_back(register_temp_path(path_, true));
  }
  ~PlotWorkFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
    for (int s : slots_) unregister_temp_path(s);
  }
  PlotWorkFolder(const PlotWorkFolder&) = delete;
  PlotWorkFolder& operator=(const PlotWorkFolder&) = delete;

  /// A file inside, registered before it exists.
  std::string file(const std::string& name) {
    const std::string p = (std::filesystem::path(path_) / name).string();
    slots_.push_back(register_temp_path(p));
    return p;
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<int> slots_;
};

/// Runs the plot script into a private folder and moves the figures into the plots folder only
/// when every one was drawn; returns an empty string on success, else what went wrong.
std::string draw_plots(const AnalyzeCommandOptions& o, const std::string& json_text, const std::string& cdf_text) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(o.python, ec))
    return o.python + " not found: the plots need Debian's python3 and python3-matplotlib (apt-get install python3-matplotlib)";
  PlotWorkFolder work(o.plots_dir);
  const std::string json_path = work.file("analysis.json"), cdf_path = work.file("radius_cdf.csv");
  std::vector<std::string> drawn;
  for (const char* name : kPlotFiles) drawn.push_back(work.file(name));
  write_text_file_atomically(json_path, json_text);
  write_text_file_atomically(cdf_path, cdf_text);
  const std::string cmd = shell_quoted(o.python) + " " + shell_quoted(FRONTPACK_PLOT_SCRIPT) + " " +
                          shell_quoted(json_path) + " " + shell_quoted(cdf_path) + " " + shell_quoted(work.path());
  const int status = std::system(cmd.c_str());
  if (!WIFEXITED(status)) return "the plot script did not finish";
  switch (WEXITSTATUS(status)) {
    case 0: break;
    case 3: return "matplotlib is missing: apt-get install python3-matplotlib (the numeric analysis is complete)";
    default: return "the plot script failed (exit " + std::to_string(WEXITSTATUS(status)) + ")";
  }
  for (const std::string& f : drawn)
    if (!fs::is_regular_file(f, ec)) return "the plot script did not draw " + fs::path(f).filename().string();
  const CleanupSignalsBlocked hold;  // all figures or none, Ctrl-C included
  std::size_t moved = 0;
  for (; moved < drawn.size(); ++moved) {
    const std::string target = (fs::path(o.plots_dir) / kPlotFiles[moved]).string();
    if (std::rename(drawn[moved].c_str(), atomic_write_target(target).c_str()) != 0)
      return "cannot move " + target + " into place: " + std::strerror(errno) + " (" + std::to_string(moved) +
             " of " + std::to_string(drawn.size()) + " figures were replaced)";
  }
  return "";
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

/// A packing of shapes (read from its json output with its scene): the figures of `pack` for
/// shapes (contacts, coordination, overlaps, sizes and mix: contact/shape_validation.hpp, same
/// tolerance), the fraction of the container filled (the shapes' exact measures), and the
/// orientation order of the body x axes (the capsule's and cylinder's axis): the orientation
/// tensor <u u^T> (core/metrics/fabric.hpp, trace 1) and the nematic order S = (D λmax - 1) / (D - 1),
/// 0 for isotropic orientations (to ~1/sqrt(N)), 1 for all axes parallel.
template <int D>
int analyze_shapes(const Scene& scene, const ShapePacking<D>& P, const AnalyzeCommandOptions& o) {
  const Container<D>& container = *scene.container<D>();
  const double tol = o.tolerance >= 0 ? o.tolerance : scene.packer.minimisation.gap_tolerance;
  const std::vector<RequestedTemplate> requested = requested_templates(scene);
  std::vector<std::uint64_t> count(requested.size(), 0);
  double solid = 0;
  std::vector<Vec<D>> axes;
  for (const Particle<D>& p : P.particles) {
    ++count[static_cast<std::size_t>(p.template_id)];
    solid += p.shape->measure();
    axes.push_back(p.pose.rotation.col(0));
  }
  const ValidationReport v = validate_shapes<D>(P, container, tol, requested);
  const double vf = solid / container.measure();
  const FabricTensor orientation = fabric_of_directions<D>(axes);
  const double order = orientation.eigenvalues.empty() ? 0.0 : (D * orientation.eigenvalues.back() - 1) / (D - 1);

  std::ostringstream json;
  {
    TextBuffer b(json);
    b.text("{\n  \"dimension\": ").integer(D).text(",\n  \"particles\": ").integer(static_cast<std::int64_t>(P.size()));
    b.text(",\n  \"templates\": [");
    for (std::size_t t = 0; t < count.size(); ++t) {
      b.text(t ? ", " : "").text("{\"family\": ").json_string(scene.particle_templates[t].family);
      b.text(", \"count\": ").integer(static_cast<std::int64_t>(count[t])).ch('}');
    }
    b.text("],\n  \"volume_fraction_container\": ").json_number(vf);
    b.text(",\n  \"contact_tolerance\": ").json_number(tol);
    b.text(",\n  \"mean_coordination\": ").json_number(v.mean_coordination());
    b.text(",\n  \"contacts\": ").integer(static_cast<std::int64_t>(v.contacts));
    b.text(",\n  \"wall_contacts\": ").integer(static_cast<std::int64_t>(v.wall_contacts));
    b.text(",\n  \"max_overlap_over_rmin\": ").json_number(v.max_overlap_rel);
    b.text(",\n  \"max_contact_gap_over_rmin\": ").json_number(v.max_contact_gap_rel);
    b.text(",\n  \"orientation_tensor\": [");
    for (std::size_t k = 0; k < orientation.tensor.size(); ++k) b.text(k ? ", " : "").json_number(orientation.tensor[k]);
    b.text("],\n  \"orientation_order\": ").json_number(order);
    b.text(",\n  \"validation\": ").json_string(v.ok ? "ok" : "FAILED");
    b.text(",\n  \"validation_summary\": ").json_string(v.summary()).text("\n}\n");
    b.flush();
  }
  if (!o.json_path.empty()) write_text_file_atomically(o.json_path, json.str());
  if (!o.quiet) {
    std::printf("frontpack analyze   %s   scene %s (%dD, particles of shapes)\n", o.packing_path.c_str(), scene.source_path.c_str(), D);
    std::printf("particles            %zu:", P.size());
    for (std::size_t t = 0; t < count.size(); ++t)
      std::printf("%s %llu %s", t ? "," : "", static_cast<unsigned long long>(count[t]), scene.particle_templates[t].family.c_str());
    std::printf("\ncontainer            %s\n", container.describe().c_str());
    std::printf("%s container         %.6g (exact: the shapes' own measures)\n", D == 3 ? "VF" : "AF", vf);
    std::printf("coordination z       %.4f, tol %.3g of the smaller circumscribed radius\n", v.mean_coordination(), tol);
    std::printf("contacts             %llu between particles, %llu with walls\n", static_cast<unsigned long long>(v.contacts),
                static_cast<unsigned long long>(v.wall_contacts));
    std::printf("max overlap / gap    %.3g / %.3g of the smaller circumscribed radius\n", v.max_overlap_rel, v.max_contact_gap_rel);
    std::printf("orientation order    S = %.4f (body x axes; 0 isotropic, 1 parallel), tensor eigenvalues", order);
    for (const double e : orientation.eigenvalues) std::printf(" %.4f", e);
    std::printf("\n%s\n", v.summary().c_str());
  }
  return 0;
}

}  // namespace

int run_analyze_command(const AnalyzeCommandOptions& o) {
  PackingInput in;
  try {
    const Activity doing("reading packing '" + o.packing_path + "'");
    std::vector<NamedPath> writes;
    if (!o.json_path.empty()) writes.push_back({o.json_path, "option --json", "analysis JSON"});
    if (!o.plots_dir.empty()) {
      std::error_code ec;
      if (!std::filesystem::is_directory(o.plots_dir, ec))
        throw std::runtime_error("option --plots: plots folder '" + o.plots_dir +
                                 "' does not exist (frontpack does not create folders)");
      for (const char* name : kPlotFiles)
        writes.push_back({(std::filesystem::path(o.plots_dir) / name).string(), "option --plots", "figure"});
    }
    check_output_paths(writes, {});  // before reading: a bad path is refused at once
    in = read_packing_input(o.packing_path, o.format, o.scene_path, /*shapes_too=*/true);
    if (in.shapes && !o.plots_dir.empty())
      throw std::runtime_error("option --plots: the figures are drawn for packings of spheres and disks (" + o.scene_path +
                               " describes shapes; --json writes the figures of a packing of shapes)");
    std::vector<NamedPath> reads = {{o.packing_path, "argument PACKING", "packing file"}};
    if (in.scene)
      for (const NamedPath& r : scene_reads(*in.scene, "option --scene")) reads.push_back(r);
    check_output_paths(writes, reads);
  } catch (...) {  // the scene parser and the readers name file, line and key
    return report_failure(2);
  }
  try {
    const Activity doing("analysing packing '" + o.packing_path + "'");
    if (in.shapes)
      return in.dimension == 2 ? analyze_shapes<2>(*in.scene, in.shapes2, o) : analyze_shapes<3>(*in.scene, in.shapes3, o);
    return in.dimension == 2 ? analyze<2>(in.scene, in.packing2, o) : analyze<3>(in.scene, in.packing3, o);
  } catch (...) {
    return report_failure(1);
  }
}

}  // namespace fp
