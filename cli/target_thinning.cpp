#include "cli/target_thinning.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace fp {

template <int D>
std::vector<char> particles_to_keep(const Scene& scene, const Container<D>& container, std::span<const double> measure,
                                    std::span<const double> size, std::span<const Vec<D>> centres, double solid,
                                    const std::vector<PairContact>& pairs, const std::vector<WallContact>& walls,
                                    std::optional<TargetThinning>& done) {
  if (!above_target<D>(scene, solid)) return {};
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = measure.size();
  std::vector<ThinningContact> contacts;
  contacts.reserve(pairs.size());
  for (const PairContact& c : pairs) contacts.push_back({c.i, c.j});
  std::vector<std::uint32_t> wall_count(n, 0);
  for (const WallContact& w : walls) ++wall_count[w.i];
  // The walk: a Hilbert curve over cells of about a particle (the mean measure's ball diameter).
  double mean = 0;
  for (const double m : measure) mean += m / static_cast<double>(n);
  const double cell = 2 * std::pow(mean / ball_measure<D>(1.0), 1.0 / D);
  std::vector<std::uint64_t> place(n);
  for (std::size_t i = 0; i < n; ++i) place[i] = hilbert_key<D>(centres[i], container.bounds().lo, cell);
  Rng rng(scene.seed ^ 0x7417'7417'7417'7417ull);  // a stream of its own: the packer's draws are unchanged
  TargetThinning t;
  std::vector<char> keep = thin_to_measure({measure, size, contacts, wall_count, place},
                                           *scene.target_solid_fraction * container.measure(), D, rng, t.report);
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  done = t;
  return keep;
}

void add_not_reached_line(PackCheck& c, double phi, double solid_fraction, const std::string& stop) {
  char line[400];
  std::snprintf(line, sizeof line, "  target         volume fraction %.4g not reached: %.4f (stop: %s)\n", phi,
                solid_fraction, stop.c_str());
  c.summary_lines += line;
  c.info.emplace_back("target_volume_fraction", "not reached");
  std::snprintf(line, sizeof line, "the target volume fraction %.4g was not reached: %.4f (stop: %s)", phi, solid_fraction,
                stop.c_str());
  c.incomplete.push_back(line);
}

void add_target_lines(PackCheck& c, const Scene& scene, const std::optional<TargetThinning>& thinned, double solid,
                      double container, const std::string& stop, bool listed) {
  if (!scene.target_solid_fraction) return;
  const double phi = *scene.target_solid_fraction, solid_fraction = solid / container;
  char line[480];
  c.metrics.emplace_back("target_solid_fraction", phi);
  if (listed) {
    std::snprintf(line, sizeof line,
                  "  target         solid fraction %.4g (porosity %.4g, void ratio %.4g): %.4f of the container, its "
                  "list placed in full\n",
                  phi, 1 - phi, 1 / phi - 1, solid_fraction);
    c.summary_lines += line;
    return;
  }
  if (!thinned) {
    if (solid_fraction < phi) add_not_reached_line(c, phi, solid_fraction, stop);
    return;
  }
  const ThinningReport& t = thinned->report;
  const double measure = container;
  std::snprintf(line, sizeof line,
                "  target         solid fraction %.4g (porosity %.4g, void ratio %.4g): %.4f of the container; thinned "
                "from %.4f, %llu of %llu removed across the container, every one left kept min(%d, its contacts) "
                "(%llu lost all); %.3f s\n",
                phi, 1 - phi, 1 / phi - 1, solid_fraction, t.measure_before / measure,
                static_cast<unsigned long long>(t.removed), static_cast<unsigned long long>(t.before), t.level,
                static_cast<unsigned long long>(t.lost_every_contact), thinned->seconds);
  c.summary_lines += line;
  c.metrics.insert(c.metrics.end(), {{"thinning_volume_fraction_before", t.measure_before / measure},
                                     {"thinning_seconds", thinned->seconds}});
  c.counters.insert(c.counters.end(), {{"thinning_removed", t.removed},
                                       {"thinning_contact_level", static_cast<std::uint64_t>(t.level)},
                                       {"thinning_lost_every_contact", t.lost_every_contact}});
}

template std::vector<char> particles_to_keep<2>(const Scene&, const Container<2>&, std::span<const double>,
                                                std::span<const double>, std::span<const Vec2>, double,
                                                const std::vector<PairContact>&, const std::vector<WallContact>&,
                                                std::optional<TargetThinning>&);
template std::vector<char> particles_to_keep<3>(const Scene&, const Container<3>&, std::span<const double>,
                                                std::span<const double>, std::span<const Vec3>, double,
                                                const std::vector<PairContact>&, const std::vector<WallContact>&,
                                                std::optional<TargetThinning>&);

}  // namespace fp
