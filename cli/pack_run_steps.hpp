#pragma once
// The steps of `frontpack pack` that are the same for a scene of spheres and one of shapes (the
// commands differ only in how they pack, check and summarise): packing with the progress line,
// writing every output and the run record together, and the summary's last lines.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "cli/failure_report.hpp"
#include "cli/progress_line.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/container_vtu.hpp"
#include "core/io/output_format.hpp"
#include "core/io/run_record.hpp"
#include "core/io/scene.hpp"
#include "front/pack_result.hpp"
#include "shapes/io/shape_packing_writers.hpp"

namespace fp {

/// The files an output writes besides its own path: a shape packing's companion (its surfaces
/// beside a vtu output, its clumps beside a lammps one), and beside every vtu output the
/// container's boundary (core/io/container_vtu.hpp), so that ParaView shows the walls.
inline std::vector<std::string> side_files(const Scene& scene, const OutputSpec& out) {
  const OutputFormat format = parse_output_format(out.format);
  std::vector<std::string> sides;
  if (!scene.particle_templates.empty()) sides = companion_paths(format, out.path, out.surfaces);
  if (format == OutputFormat::Vtu) sides.push_back(container_vtu_path(out.path));
  return sides;
}

/// `pack(progress)` with the progress line on stderr when `shown` (--progress, or a terminal).
template <class Pack>
auto pack_with_progress(bool shown, const Scene& scene, Pack&& pack) {
  ProgressLine progress(shown, scene);
  ProgressFn fn;
  if (progress.on()) fn = [&](std::uint64_t n, double t, double vf) { progress(n, t, vf); };
  auto result = pack(fn);
  progress.finish();
  return result;
}

/// Every output of the scene (`write_one(output)`) and the run record (if `record_path`),
/// all or none of them; returns the seconds it took. With `spare_existing` (a packing that failed
/// its validation) a path that already holds a file is left as it is (a good packing of an
/// earlier run is not replaced by a bad one) and added to *spared; the others are written, the
/// verdict in the record.
template <class WriteOne>
double write_outputs(const Scene& scene, const std::string& record_path, const RunRecord& record, WriteOne&& write_one,
                     bool spare_existing = false, std::vector<std::string>* spared = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  const Activity writing("writing the outputs of '" + scene.source_path + "'");
  const auto may_write = [&](const std::string& path) {
    std::error_code ec;
    if (!spare_existing || !std::filesystem::exists(path, ec)) return true;
    if (spared) spared->push_back(path);
    return false;
  };
  AtomicFileGroup all_or_nothing;
  for (const OutputSpec& out : scene.outputs)
    if (may_write(out.path)) write_one(out);
  if (!record_path.empty() && may_write(record_path)) write_run_record(record_path, record);
  all_or_nothing.commit();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The summary's last lines: each output and the run record (those in `spared` left unwritten).
inline void print_output_lines(const Scene& scene, const std::string& record_path, const std::vector<std::string>& spared = {}) {
  const auto note = [&](const std::string& path) {
    return std::find(spared.begin(), spared.end(), path) != spared.end() ? "; not written: the file there is kept" : "";
  };
  for (const OutputSpec& out : scene.outputs) {
    std::printf("  output         %s (%s%s)\n", out.path.c_str(), out.format.c_str(), note(out.path));
    for (const std::string& side : side_files(scene, out)) {
      std::error_code ec;
      const auto bytes = std::filesystem::file_size(side, ec);
      std::printf("  side file      %s (of %s%s%s)\n", side.c_str(), out.path.c_str(),
                  ec ? "" : (", " + std::to_string(bytes / 1000000.0).substr(0, 5) + " MB").c_str(), note(side));
    }
  }
  if (!record_path.empty()) std::printf("  run record     %s%s\n", record_path.c_str(), note(record_path));
}

}  // namespace fp
