#pragma once
// The parts of a run record and summary every `pack` fills the same way, spheres or shapes: what
// was run (version, scene, seed, dimension), the container (description, bounds; 2D with z = 0)
// and the front's counters.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "cli/pack_check.hpp"
#include "core/geometry/container.hpp"
#include "core/io/run_record.hpp"
#include "core/io/scene.hpp"
#include "front/pack_result.hpp"
#include "frontpack/version.hpp"

namespace fp {

template <int D>
RunRecord start_run_record(const Scene& scene, const Container<D>& container, std::size_t n) {
  RunRecord rec;
  rec.version = kVersion;
  rec.scene_path = scene.source_path;
  rec.scene_text = scene.source_text;
  rec.scene_overrides = scene.overrides;
  rec.seed = scene.seed;
  rec.density = scene.density;
  rec.dimension = D;
  rec.n = n;
  rec.container_description = container.describe();
  const Aabb<D> b = container.bounds();
  Aabb<3> b3;
  b3.lo.setZero();
  b3.hi.setZero();
  b3.lo.template head<D>() = b.lo;
  b3.hi.template head<D>() = b.hi;
  rec.bounds = b3;
  rec.origin.setZero();
  rec.origin.template head<D>() = container.origin();
  return rec;
}

/// The advancing front's counters, in the run record's order (both fronts fill FrontCounters).
inline std::vector<std::pair<std::string, std::uint64_t>> front_counter_entries(const FrontCounters& c) {
  std::vector<std::pair<std::string, std::uint64_t>> out;
  for (const FrontCounters::Field& f : FrontCounters::kFields) out.emplace_back(f.name, c.*f.member);
  return out;
}

/// One MPI rank's work in a line (run record `info` and summary): what it grew, against how
/// many particles of other blocks, what it sent, how long it grew and waited.
inline std::string rank_work_text(const RankWork& w) {
  char line[200];
  std::snprintf(line, sizeof line, "%llu blocks, %llu particles, %llu fixed, sent %.1f MB, grew %.2f s, waited %.2f s",
                static_cast<unsigned long long>(w.blocks), static_cast<unsigned long long>(w.particles),
                static_cast<unsigned long long>(w.fixed), static_cast<double>(w.doubles_sent) * 8 / 1e6, w.grow_seconds,
                w.wait_seconds);
  return line;
}

/// What the record and the summaries call the particles: the radius law, or each template's
/// family and size law.
inline std::string particles_description(const Scene& scene) {
  if (scene.particle_templates.empty())
    return scene.radii->describe() + (scene.stop.scale_sizes ? ", scaled so that stop.particles fill the container" : "");
  std::string d;
  for (const ParticleTemplateSpec& t : scene.particle_templates) {  // the size law with the dimension it is drawn on
    std::string on = t.size_on;
    for (char& c : on) c = c == '_' ? ' ' : c;
    d += (d.empty() ? "" : "; ") + t.family + " " + t.size->describe() + " on the " + on;
  }
  return d;
}

/// Particles placed per second of packing (0 for no time).
inline double particles_per_second(std::size_t n, double seconds) {
  return seconds > 0 ? static_cast<double>(n) / seconds : 0.0;
}

/// The run record of a packing run and its check (`Kind`: SpherePack or ShapePack): what
/// `frontpack pack --record` writes and the Python module's `Packing.record` holds.
template <int D, class Kind>
RunRecord pack_record(const Scene& scene, const typename Kind::Result& res, const PackCheck& check, double check_seconds) {
  const auto& P = res.packing;
  const ValidationReport& v = check.validation;
  const double rate = particles_per_second(P.size(), res.seconds);
  RunRecord rec = start_run_record<D>(scene, *scene.container<D>(), P.size());
  rec.distribution_description = particles_description(scene);
  rec.timings = {{"pack", res.seconds}, {check.timing_name, check_seconds}};
  for (const auto& [step, seconds] : check.step_timings) rec.timings.emplace_back(check.timing_name + ": " + step, seconds);
  rec.metrics = {{"volume_fraction_container", check.volume_fraction},
                 {"contact_tolerance", v.tolerance},
                 {"mean_coordination", v.mean_coordination()},
                 {"max_overlap_over_smaller_radius", v.max_overlap_rel},
                 {"max_contact_gap_over_smaller_radius", v.max_contact_gap_rel},
                 {"max_outside_over_r", v.max_outside_rel},
                 {"particles_per_second", rate}};
  rec.metrics.insert(rec.metrics.end(), check.metrics.begin(), check.metrics.end());
  rec.counters = front_counter_entries(res.counters);
  const std::vector<std::pair<std::string, std::uint64_t>> common = {
      {"contacts", v.contacts}, {"wall_contacts", v.wall_contacts}, {"pairs_checked", v.pairs_checked}};
  rec.counters.insert(rec.counters.end(), common.begin(), common.end());
  rec.counters.insert(rec.counters.end(), check.counters.begin(), check.counters.end());
  rec.info = {{"stop_reason", Kind::stop_text(res)}, {"validation", check.verdict()}};
  rec.info.insert(rec.info.end(), check.info.begin(), check.info.end());
  if (!check.complete()) rec.info.emplace_back("incomplete", check.incomplete_text());
  for (std::size_t r = 0; r < res.ranks.size(); ++r) rec.info.emplace_back("rank_" + std::to_string(r), rank_work_text(res.ranks[r]));
  rec.analysis_json = check.analysis_json;
  return rec;
}

/// The first two lines of the summary: what was run, and in which container.
template <int D>
void print_run_header(const Scene& scene, const Container<D>& container) {
  std::printf("frontpack %s   scene %s   seed %llu   %dD\n", kVersion, scene.source_path.c_str(),
              static_cast<unsigned long long>(scene.seed), D);
  std::printf("  container      %s, %s %.6g\n", container.describe().c_str(), D == 3 ? "volume" : "area",
              container.measure());
}

}  // namespace fp
