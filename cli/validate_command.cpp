#include "cli/validate_command.hpp"

#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/failure_report.hpp"
#include "cli/packing_input.hpp"
#include "contact/shape_validation.hpp"
#include "core/metrics/validate.hpp"

namespace fp {
namespace {

template <int D>
int validate(const Scene& scene, const Packing<D>& P, const ValidateCommandOptions& o) {
  const Container<D>& container = *scene.container<D>();
  const double tol = o.tolerance >= 0 ? o.tolerance : scene.packer.contact_tolerance;
  // The verdict of `frontpack pack`: same function, same tolerance, same radii test and level.
  const ValidationReport r = validate_packing<D>(P, container, scene.radii.get(), tol, o.ks_alpha);
  if (!o.quiet) {
    std::printf("frontpack validate   %s   against %s (%dD)\n", o.packing_path.c_str(), scene.source_path.c_str(), D);
    std::printf("  container      %s\n", container.describe().c_str());
    std::printf("  particles      %llu; %llu pairs checked\n", static_cast<unsigned long long>(r.particles),
                static_cast<unsigned long long>(r.pairs_checked));
    if (r.empty()) {
      std::printf("  result         FAILED: the packing holds no particles\n");
      return 3;
    }
    std::printf("  overlaps       %llu beyond %.3g of the smaller radius   (max overlap %.3g of the smaller radius)\n",
                static_cast<unsigned long long>(r.overlap_count), tol, r.max_overlap_rel);
    std::printf("  outside        %llu   (max protrusion %.3g r)\n", static_cast<unsigned long long>(r.outside_count),
                r.max_outside_rel);
    std::printf("  radii          %llu out of range of %s; %s (fails below %.3g)\n",
                static_cast<unsigned long long>(r.radius_count), scene.radii->describe().c_str(),
                r.radii.describe().c_str(), o.ks_alpha);
    if (r.non_finite_count) std::printf("  non-finite     %llu\n", static_cast<unsigned long long>(r.non_finite_count));
    std::printf("  result         %s\n", r.ok ? "ok" : "FAILED");
    if (!r.worst.empty()) {
      std::printf("  worst offenders (ids as in the file; overlaps relative to the smaller radius, others to r):\n");
      for (const ValidationIssue& w : r.worst) std::printf("    %s\n", describe(w).c_str());
    }
  } else if (r.empty()) {
    std::fprintf(stderr, "frontpack: error: %s holds no particles\n", o.packing_path.c_str());
  }
  return r.ok ? 0 : 3;
}

/// A packing of shapes: the verdict of `frontpack pack` for shapes (contact/shape_validation.hpp),
/// same tolerance (the scene's gap_tolerance unless --tolerance), same size and mix tests.
template <int D>
int validate_shape_packing(const Scene& scene, const ShapePacking<D>& P, const ValidateCommandOptions& o) {
  const Container<D>& container = *scene.container<D>();
  const double tol = o.tolerance >= 0 ? o.tolerance : scene.packer.minimisation.gap_tolerance;
  const std::vector<RequestedTemplate> requested = requested_templates(scene);
  const ShapeValidation v = validate_shapes<D>(P, container, tol, requested, o.ks_alpha);
  if (!o.quiet) {
    std::printf("frontpack validate   %s   against %s (%dD, particles of shapes)\n", o.packing_path.c_str(),
                scene.source_path.c_str(), D);
    std::printf("  container      %s\n", container.describe().c_str());
    std::printf("  particles      %zu; %llu pairs checked\n", P.size(), static_cast<unsigned long long>(v.pairs_checked));
    std::printf("  overlaps       %llu beyond %.3g of the smaller circumscribed radius   (max overlap %.3g)\n",
                static_cast<unsigned long long>(v.overlaps), tol, v.max_overlap_rel);
    std::printf("  outside        %llu   (max protrusion %.3g of the circumscribed radius)\n",
                static_cast<unsigned long long>(v.outside), v.max_outside_rel);
    std::printf("  contacts       %llu, %llu with the walls   (coordination %.3f)\n", static_cast<unsigned long long>(v.contacts),
                static_cast<unsigned long long>(v.wall_contacts), v.mean_coordination);
    std::printf("  result         %s\n", v.summary().c_str());
  } else if (!v.ok) {
    std::fprintf(stderr, "frontpack: error: %s: %s\n", o.packing_path.c_str(), v.summary().c_str());
  }
  return v.ok ? 0 : 3;
}

}  // namespace

int run_validate_command(const ValidateCommandOptions& o) {
  PackingInput in;
  try {
    const Activity doing("reading packing '" + o.packing_path + "'");
    in = read_packing_input(o.packing_path, o.format, o.scene_path, /*shapes_too=*/true);
  } catch (...) {  // the scene parser and the readers name file, line and key
    return report_failure(2);
  }
  try {
    const Activity doing("validating packing '" + o.packing_path + "'");
    if (in.shapes)
      return in.dimension == 2 ? validate_shape_packing<2>(*in.scene, in.shapes2, o) : validate_shape_packing<3>(*in.scene, in.shapes3, o);
    return in.dimension == 2 ? validate<2>(*in.scene, in.packing2, o) : validate<3>(*in.scene, in.packing3, o);
  } catch (...) {
    return report_failure(1);
  }
}

}  // namespace fp
