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
#include "cli/pack_api.hpp"
#include "cli/packing_input.hpp"
#include "contact/shape_analysis.hpp"
#include "contact/shape_sections.hpp"
#include "contact/shape_validation.hpp"
#include "core/io/analysis_json.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/output_paths.hpp"
#include "core/io/temp_file_registry.hpp"
#include "core/metrics/packing_analysis.hpp"
#include "core/metrics/packing_sections.hpp"

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

/// The figures python/plot_analysis.py draws for every packing (keep in step with the script).
const char* const kPlotFiles[] = {"vf_curve.png", "coordination.png", "radii.png",
                                  "rdf.png",      "partial_coordination.png", "fabric.png"};
/// And the sections of a packing of spheres: 3D the planes normal to x, y, z through the
/// container's centre; 2D the packing's own plane (section_xy.png).
const char* const kSectionFiles[] = {"section_yz.png", "section_xz.png", "section_xy.png"};
/// And the profiles: the wall layers (every packing with a size), the bed's (a bed).
const char* const kProfileFiles[] = {"wall_profile.png", "bed_profile.png"};

/// A section's name in its file and the CSV: the plane's two axes.
std::string plane_name(const PackingSection& s) { return std::string(1, "xyz"[s.u_axis]) + "xyz"[s.v_axis]; }

/// The sections as the plot script reads them: disks (plane,normal,offset,u,v,radius,size: a
/// plane that cuts none has one row without a disk), the container's outline
/// (plane,u0,v0,u1,v1), and the other shapes' loops (plane,particle,loop,size,template,u,v: a
/// loop's points in order).
struct SectionsCsv {
  std::string disks, outline, polygons;
};
SectionsCsv sections_csv(const std::vector<PackingSection>& sections) {
  std::ostringstream disks, outline, polygons;
  for (std::ostringstream* o : {&disks, &outline, &polygons}) o->precision(17);
  disks << "plane,normal,offset,u,v,radius,size\n";
  outline << "plane,u0,v0,u1,v1\n";
  polygons << "plane,particle,loop,size,template,u,v\n";
  for (const PackingSection& s : sections) {
    const std::string plane = plane_name(s);
    for (const SectionDisk& d : s.disks)
      disks << plane << ',' << "xyz"[s.normal_axis] << ',' << s.offset << ',' << d.u << ',' << d.v << ',' << d.radius << ','
            << d.size << '\n';
    if (s.disks.empty()) disks << plane << ',' << "xyz"[s.normal_axis] << ',' << s.offset << ",,,,\n";
    for (const auto& seg : s.outline) outline << plane << ',' << seg[0] << ',' << seg[1] << ',' << seg[2] << ',' << seg[3] << '\n';
    for (std::size_t k = 0; k < s.polygons.size(); ++k) {
      const SectionPolygon& p = s.polygons[k];
      for (const auto& q : p.points)
        polygons << plane << ',' << p.particle << ',' << k << ',' << p.size << ',' << p.template_id << ',' << q[0] << ',' << q[1] << '\n';
    }
  }
  return {disks.str(), outline.str(), polygons.str()};
}

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
std::string draw_plots(const std::string& plots_dir, const std::string& python, const PackingAnalysis& a,
                       const std::string& json_text, const std::string& cdf_text, const std::vector<PackingSection>& sections) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(python, ec))
    return python + " not found: the plots need Debian's python3 and python3-matplotlib (apt-get install python3-matplotlib)";
  PlotWorkFolder work(plots_dir);
  const std::string json_path = work.file("analysis.json"), cdf_path = work.file("radius_cdf.csv");
  std::vector<std::string> names(std::begin(kPlotFiles), std::end(kPlotFiles));
  if (a.wall_profile.computed()) names.push_back("wall_profile.png");
  if (a.bed.computed()) names.push_back("bed_profile.png");
  for (const PackingSection& s : sections) names.push_back("section_" + plane_name(s) + ".png");
  std::vector<std::string> drawn;
  for (const std::string& name : names) drawn.push_back(work.file(name));
  write_text_file_atomically(json_path, json_text);
  write_text_file_atomically(cdf_path, cdf_text);
  std::string cmd = shell_quoted(python) + " " + shell_quoted(FRONTPACK_PLOT_SCRIPT) + " " + shell_quoted(json_path) + " " +
                    shell_quoted(cdf_path) + " " + shell_quoted(work.path());
  if (!sections.empty()) {
    const SectionsCsv csv = sections_csv(sections);
    const std::string disks_path = work.file("sections.csv"), outline_path = work.file("outline.csv"),
                      polygons_path = work.file("polygons.csv");
    write_text_file_atomically(disks_path, csv.disks);
    write_text_file_atomically(outline_path, csv.outline);
    write_text_file_atomically(polygons_path, csv.polygons);
    cmd += " " + shell_quoted(disks_path) + " " + shell_quoted(outline_path) + " " + shell_quoted(polygons_path);
  }
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
    const std::string target = (fs::path(plots_dir) / names[moved]).string();
    if (std::rename(drawn[moved].c_str(), atomic_write_target(target).c_str()) != 0)
      return "cannot move " + target + " into place: " + std::strerror(errno) + " (" + std::to_string(moved) +
             " of " + std::to_string(drawn.size()) + " figures were replaced)";
  }
  return "";
}

/// Prints and writes an analysis, spheres or shapes alike: the table, the JSON, the figures
/// (`sizes` and `law`: the radius figure's sample and the law it is drawn against, if any).
int report(const PackingAnalysis& a, const std::optional<Scene>& scene, const std::vector<double>& sizes,
           const RadiusDistribution* law, const std::vector<PackingSection>& sections, const AnalyzeCommandOptions& o) {
  const std::string json = analysis_json(a);
  if (!o.json_path.empty()) write_text_file_atomically(o.json_path, json);
  if (!o.quiet) {
    std::printf("frontpack analyze   %s%s%s (%dD%s)\n", o.packing_path.c_str(), scene ? "   scene " : "",
                scene ? scene->source_path.c_str() : "", a.dimension, a.templates.empty() ? "" : ", particles of shapes");
    std::printf("%s\n", a.summary().c_str());
  }
  if (o.plots_dir.empty()) return 0;
  const std::string problem = draw_plots(o.plots_dir, o.python, a, json, radius_cdf_csv(sizes, law), sections);
  if (!problem.empty()) {
    std::fprintf(stderr, "frontpack: error: no plots: %s\n", problem.c_str());
    return 1;
  }
  if (!o.quiet) std::printf("  plots          %s\n", o.plots_dir.c_str());
  return 0;
}

/// The radius figure's sample and law: the radii against the scene's law; for shapes the sizes
/// against their law for one template, else the volume-equivalent radii.
template <int D>
std::pair<std::vector<double>, const RadiusDistribution*> radius_figure(const PackingInput& in, const Packing<D>& P) {
  return {P.radii, in.scene ? in.scene->radii.get() : nullptr};
}
template <int D>
std::pair<std::vector<double>, const RadiusDistribution*> radius_figure(const PackingInput& in, const ShapePacking<D>& P) {
  const std::vector<RequestedTemplate> requested = requested_templates(*in.scene);
  const bool one = requested.size() == 1 && requested[0].size;
  std::vector<double> sizes;
  for (const Particle<D>& p : P.particles) sizes.push_back(one ? p.size : equivalent_radius<D>(p.shape->measure()));
  return {sizes, one ? requested[0].size : nullptr};
}

/// The sections drawn with the figures: spheres (disks) in the scene's container, or the
/// bounding box of the balls without a scene; shapes in the scene's container.
template <int D>
std::vector<PackingSection> sections_of(const PackingInput& in, const Packing<D>& P) {
  if (in.scene) return packing_sections<D>(P, *in.scene->container<D>());
  const std::unique_ptr<Container<D>> box = bounding_box_of_balls(P);
  return box ? packing_sections<D>(P, *box) : std::vector<PackingSection>{};
}
template <int D>
std::vector<PackingSection> sections_of(const PackingInput& in, const ShapePacking<D>& P) {
  return in.scene ? shape_sections<D>(P, *in.scene->container<D>()) : std::vector<PackingSection>{};
}

/// The analysis of cli/pack_api.hpp (a packing of shapes at the scene's tolerance of `pack`,
/// minimisation.gap_tolerance), reported.
template <class P>
int analyze(const PackingInput& in, const P& packing, const AnalyzeCommandOptions& o) {
  const PackingAnalysis a = analyze_input(in, o.tolerance, o.threads);
  const auto [sizes, law] = radius_figure(in, packing);
  return report(a, in.scene, sizes, law, o.plots_dir.empty() ? std::vector<PackingSection>{} : sections_of(in, packing), o);
}

template <class P>
std::string figures_of(const PackingInput& in, const P& packing, const PackingAnalysis& a, const std::string& plots_dir,
                       const std::string& python) {
  const auto [sizes, law] = radius_figure(in, packing);
  return draw_plots(plots_dir, python, a, analysis_json(a), radius_cdf_csv(sizes, law), sections_of(in, packing));
}

}  // namespace

std::string draw_analysis_figures(const PackingInput& in, const PackingAnalysis& a, const std::string& plots_dir,
                                  const std::string& python) {
  std::error_code ec;
  if (!std::filesystem::is_directory(plots_dir, ec)) return "the plots folder '" + plots_dir + "' does not exist";
  if (in.shapes) return in.dimension == 2 ? figures_of(in, in.shapes2, a, plots_dir, python) : figures_of(in, in.shapes3, a, plots_dir, python);
  return in.dimension == 2 ? figures_of(in, in.packing2, a, plots_dir, python) : figures_of(in, in.packing3, a, plots_dir, python);
}

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
      std::vector<std::string> names(std::begin(kPlotFiles), std::end(kPlotFiles));
      names.insert(names.end(), std::begin(kSectionFiles), std::end(kSectionFiles));
      names.insert(names.end(), std::begin(kProfileFiles), std::end(kProfileFiles));
      for (const std::string& name : names)
        writes.push_back({(std::filesystem::path(o.plots_dir) / name).string(), "option --plots", "figure"});
    }
    check_output_paths(writes, {});  // before reading: a bad path is refused at once
    in = read_packing_input(o.packing_path, o.format, o.scene_path, /*shapes_too=*/true, o.scene_overrides);
    std::vector<NamedPath> reads = {{o.packing_path, "argument PACKING", "packing file"}};
    if (in.scene)
      for (const NamedPath& r : scene_reads(*in.scene, "option --scene")) reads.push_back(r);
    check_output_paths(writes, reads);
  } catch (...) {  // the scene parser and the readers name file, line and key
    return report_failure(2);
  }
  try {
    const Activity doing("analysing packing '" + o.packing_path + "'");
    if (in.shapes) return in.dimension == 2 ? analyze(in, in.shapes2, o) : analyze(in, in.shapes3, o);
    return in.dimension == 2 ? analyze(in, in.packing2, o) : analyze(in, in.packing3, o);
  } catch (...) {
    return report_failure(1);
  }
}

}  // namespace fp
