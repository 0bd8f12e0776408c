#include "cli/validate_command.hpp"

#include <cstdio>
#include <exception>

#include "cli/failure_report.hpp"
#include "cli/packing_input.hpp"
#include "core/metrics/validate.hpp"

namespace fp {
namespace {

template <int D>
int validate(const Scene& scene, const Packing<D>& P, const ValidateCommandOptions& o) {
  const Container<D>& container = *scene.container<D>();
  const double tol = o.tolerance >= 0 ? o.tolerance : scene.packer.contact_tolerance;
  const ValidationReport r = validate_packing<D>(P, container, scene.radii.get(), tol);
  // An empty packing has no radii to test: that is not evidence against the distribution.
  const bool radii_ok = P.size() < 2 || !(r.radii_ks_pvalue < o.ks_alpha);
  const bool ok = r.ok && radii_ok;
  if (!o.quiet) {
    std::printf("frontpack validate   %s   against %s (%dD)\n", o.packing_path.c_str(), scene.source_path.c_str(), D);
    std::printf("  container      %s\n", container.describe().c_str());
    std::printf("  particles      %llu; %llu pairs checked\n", static_cast<unsigned long long>(r.particles),
                static_cast<unsigned long long>(r.pairs_checked));
    std::printf("  overlaps       %llu beyond %.3g r_min   (max overlap %.3g r_min)\n",
                static_cast<unsigned long long>(r.overlap_count), tol, r.max_overlap_rel);
    std::printf("  outside        %llu   (max protrusion %.3g r)\n", static_cast<unsigned long long>(r.outside_count),
                r.max_outside_rel);
    std::printf("  radii          %llu outside [%.6g, %.6g]; K-S D = %.4g, p = %.3g (fails below %.3g)\n",
                static_cast<unsigned long long>(r.radius_count), scene.radii->r_min(), scene.radii->r_max(),
                r.radii_ks_statistic, r.radii_ks_pvalue, o.ks_alpha);
    if (r.non_finite_count) std::printf("  non-finite     %llu\n", static_cast<unsigned long long>(r.non_finite_count));
    std::printf("  result         %s\n", ok ? "ok" : "FAILED");
    if (!r.worst.empty()) {
      std::printf("  worst offenders (ids as in the file, values relative to r_min for pairs, to r otherwise):\n");
      for (const ValidationIssue& w : r.worst) std::printf("    %s\n", describe(w).c_str());
    }
  }
  return ok ? 0 : 3;
}

}  // namespace

int run_validate_command(const ValidateCommandOptions& o) {
  PackingInput in;
  try {
    const Activity doing("reading packing '" + o.packing_path + "'");
    in = read_packing_input(o.packing_path, o.format, o.scene_path);
  } catch (...) {  // the scene parser and the readers name file, line and key
    return report_failure(2);
  }
  try {
    const Activity doing("validating packing '" + o.packing_path + "'");
    return in.dimension == 2 ? validate<2>(*in.scene, in.packing2, o) : validate<3>(*in.scene, in.packing3, o);
  } catch (...) {
    return report_failure(1);
  }
}

}  // namespace fp
