#include "cli/validate_command.hpp"

#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/failure_report.hpp"
#include "cli/pack_api.hpp"
#include "cli/packing_input.hpp"
#include "cli/run_record_start.hpp"
#include "core/metrics/validate.hpp"

namespace fp {
namespace {

/// The one verdict of `frontpack pack`, printed the same for every kind of particle: `r` comes
/// from validate_input (cli/pack_api.hpp: validate_packing or validate_shapes), as in `pack`:
/// same function, same tolerance, same size tests and level.
template <int D>
int report(const Scene& scene, const ValidationReport& r, const ValidateCommandOptions& o) {
  const Container<D>& container = *scene.container<D>();
  if (!o.quiet) {
    std::printf("frontpack validate   %s   against %s (%dD%s)\n", o.packing_path.c_str(), scene.source_path.c_str(), D,
                scene.particle_templates.empty() ? "" : ", particles of shapes");
    std::printf("  container      %s\n", container.describe().c_str());
    std::printf("  particles      %llu; %llu pairs checked\n", static_cast<unsigned long long>(r.particles),
                static_cast<unsigned long long>(r.pairs_checked));
    if (r.empty()) {
      std::printf("  result         FAILED: the packing holds no particles\n");
      return 3;
    }
    std::printf("  overlaps       %llu beyond %.3g of the smaller %s   (max overlap %.3g of the smaller %s)\n",
                static_cast<unsigned long long>(r.overlap_count), r.tolerance, r.unit_name.c_str(), r.max_overlap_rel,
                r.unit_name.c_str());
    std::printf("  outside        %llu   (max protrusion %.3g of the %s)\n", static_cast<unsigned long long>(r.outside_count),
                r.max_outside_rel, r.unit_name.c_str());
    std::printf("  contacts       %llu, %llu with the walls   (coordination %.3f; the largest |gap| %.3g)\n",
                static_cast<unsigned long long>(r.contacts), static_cast<unsigned long long>(r.wall_contacts),
                r.mean_coordination(), r.max_contact_gap_rel);
    std::string tests;
    for (std::size_t t = 0; t < r.sizes.size(); ++t)
      if (r.sizes[t].computed()) tests += (r.sizes.size() == 1 ? "; " : "; template " + std::to_string(t) + ": ") + r.sizes[t].describe();
    if (r.mix) {
      char mix[160];
      std::snprintf(mix, sizeof mix, "; mix of templates: chi-square X2 = %.4g (%d dof), p = %.3g", r.mix->statistic, r.mix->dof, r.mix->p);
      tests += mix;
    }
    std::printf("  sizes          %llu out of range of %s%s (each test fails below %.3g)\n",
                static_cast<unsigned long long>(r.radius_count), particles_description(scene).c_str(), tests.c_str(),
                r.test_level());
    if (r.non_finite_count) std::printf("  non-finite     %llu\n", static_cast<unsigned long long>(r.non_finite_count));
    std::printf("  result         %s\n", r.ok ? "ok" : "FAILED");
    if (!r.worst.empty()) {
      std::printf("  worst offenders (ids as in the file; overlaps relative to the smaller %s, others to the particle's):\n",
                  r.unit_name.c_str());
      for (const ValidationIssue& w : r.worst) std::printf("    %s\n", describe(w).c_str());
    }
  } else if (r.empty()) {
    std::fprintf(stderr, "frontpack: error: %s holds no particles\n", o.packing_path.c_str());
  }
  return r.ok ? 0 : 3;
}

}  // namespace

int run_validate_command(const ValidateCommandOptions& o) {
  PackingInput in;
  try {
    const Activity doing("reading packing '" + o.packing_path + "'");
    in = read_packing_input(o.packing_path, o.format, o.scene_path, /*shapes_too=*/true, o.scene_overrides);
  } catch (...) {  // the scene parser and the readers name file, line and key
    return report_failure(2);
  }
  try {
    const Activity doing("validating packing '" + o.packing_path + "'");
    const ValidationReport r = validate_input(in, o.tolerance, o.ks_alpha, o.threads);
    return in.dimension == 2 ? report<2>(*in.scene, r, o) : report<3>(*in.scene, r, o);
  } catch (...) {
    return report_failure(1);
  }
}

}  // namespace fp
