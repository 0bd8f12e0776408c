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
  rec.seed = scene.seed;
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
  if (scene.particle_templates.empty()) return scene.radii->describe();
  std::string d;
  for (const ParticleTemplateSpec& t : scene.particle_templates) d += (d.empty() ? "" : "; ") + t.family + " " + t.size->describe();
  return d;
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
