#pragma once
// The scene's `target:` for every packer: a packing above the target solid fraction
// thinned down to it (densify/thinning.hpp), spheres and shapes alike; what the summary and the
// run record say of it, or that the target was not reached (with the value reached).
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cli/pack_check.hpp"
#include "core/geometry/container.hpp"
#include "core/io/scene.hpp"
#include "core/metrics/contacts.hpp"
#include "densify/thinning.hpp"

namespace fp {

/// What the thinning did, kept with the run.
struct TargetThinning {
  ThinningReport report;
  double seconds = 0.0;
};

/// Which particles to keep to bring `solid` (their measure summed) down to the scene's target:
/// empty when there is no target or the packing is not above it. `size` orders the size classes
/// (a radius; for shapes a rank by template and size); contacts as the check finds them.
template <int D>
std::vector<char> particles_to_keep(const Scene& scene, const Container<D>& container, std::span<const double> measure,
                                    std::span<const double> size, std::span<const Vec<D>> centres, double solid,
                                    const std::vector<PairContact>& pairs, const std::vector<WallContact>& walls,
                                    std::optional<TargetThinning>& done);

/// True when the scene has a target and `solid` is above it: the thinning has work.
template <int D>
bool above_target(const Scene& scene, double solid) {
  return scene.target_solid_fraction && solid > *scene.target_solid_fraction * scene.container<D>()->measure();
}

/// The line (and the record's info) saying a target solid fraction `phi` was not reached:
/// `solid_fraction` reached, and why the packer stopped; the packing is incomplete (exit 4).
void add_not_reached_line(PackCheck& c, double phi, double solid_fraction, const std::string& stop);

/// The summary line, metrics and counters of the thinning, or the line saying the target was not
/// reached (`solid`: the packing's measure, `container`: the container's). `listed`: the packer
/// placed a list made for the target in full (the stacking), within half a particle of it.
void add_target_lines(PackCheck& c, const Scene& scene, const std::optional<TargetThinning>& thinned, double solid,
                      double container, const std::string& stop, bool listed = false);

}  // namespace fp
