#pragma once
// The steps of `frontpack pack` that are the same for a scene of spheres and one of shapes (the
// commands differ only in how they pack, check and summarise): packing with the progress line,
// writing every output and the run record together, and the summary's last lines.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

#include "cli/failure_report.hpp"
#include "cli/progress_line.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/output_format.hpp"
#include "core/io/run_record.hpp"
#include "core/io/scene.hpp"
#include "front/pack_result.hpp"

namespace fp {

/// `pack(progress)` with the progress line on stderr when `shown` (--progress, or a terminal).
template <class Pack>
auto pack_with_progress(bool shown, Pack&& pack) {
  ProgressLine progress(shown);
  ProgressFn fn;
  if (progress.on()) fn = [&](std::uint64_t n, double t, double vf) { progress(n, t, vf); };
  auto result = pack(fn);
  progress.finish();
  return result;
}

/// Every output of the scene (`write_one(format, path)`) and the run record (if `record_path`),
/// all or none of them; returns the seconds it took.
template <class WriteOne>
double write_outputs(const Scene& scene, const std::string& record_path, const RunRecord& record, WriteOne&& write_one) {
  const auto start = std::chrono::steady_clock::now();
  const Activity writing("writing the outputs of '" + scene.source_path + "'");
  AtomicFileGroup all_or_nothing;
  for (const OutputSpec& out : scene.outputs) write_one(parse_output_format(out.format), out.path);
  if (!record_path.empty()) write_run_record(record_path, record);
  all_or_nothing.commit();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The summary's last lines: each output and the run record.
inline void print_output_lines(const Scene& scene, const std::string& record_path) {
  for (const OutputSpec& out : scene.outputs) std::printf("  output         %s (%s)\n", out.path.c_str(), out.format.c_str());
  if (!record_path.empty()) std::printf("  run record     %s\n", record_path.c_str());
}

}  // namespace fp
