#pragma once
// What `frontpack pack` learns about a packing after packing it, whatever its particles: the full
// analysis of `frontpack analyze` (core/metrics/packing_analysis.hpp; for shapes
// contact/shape_analysis.hpp), the one verdict in it (core/metrics/validate.hpp), and what a kind
// of particle adds (cli/sphere_pack.hpp: the grid's memory; cli/shape_pack.hpp: the solvers').
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/metrics/packing_analysis.hpp"
#include "core/io/scene.hpp"
#include "core/metrics/validate.hpp"
#include "front/pack_result.hpp"

namespace fp {

/// How much of the analysis a run needs: all of it when it is shown (the summary) or stored (the
/// record, a JSON output); else the validation alone, which every packing gets (a user who asked
/// for neither does not wait for g(r) or the quasi-Monte Carlo volume fractions).
enum class CheckDepth { Validation, Analysis };

/// The record's verdict on a valid packing short of its size law for want of room (exit 4).
inline constexpr const char* kShortOfRoomVerdict = "sizes short of room";

struct PackCheck {
  ValidationReport validation;
  double volume_fraction = 0.0;   ///< of the container (2D: area fraction)
  std::string timing_name;        ///< the record's timing of the check ("metrics": the full analysis)
  std::vector<std::pair<std::string, double>> step_timings;  ///< the analysis' steps (wall seconds; some run at once)
  std::vector<std::pair<std::string, double>> metrics;           ///< after the record's common metrics
  std::vector<std::pair<std::string, std::uint64_t>> counters;   ///< after the common counters
  std::vector<std::pair<std::string, std::string>> info;         ///< after the common info
  std::string analysis_json;      ///< the full analysis (analysis_json.hpp), embedded in the record
  std::string summary_lines;      ///< the analysis' table, then the kind's own lines, each "  name  value\n"
  /// Why a valid packing is not what the scene asks, when it placed nearly nothing of it (a
  /// stacking that placed less than half its list, a region left empty) or is short of its size
  /// law for want of room (sizes_short_of_room), or missed its target solid fraction: exit 4, one
  /// code for every incomplete packing; no output replaces an existing file.
  std::vector<std::string> incomplete;
  /// Why the scene's own stop (stop.time, stop.particles, stop.volume_fraction) ended the front
  /// before it filled the container: the particles are a cluster around the seed point, not a
  /// packing of the container. Exit 4 as well, but the outputs are written: the scene asked for it.
  std::vector<std::string> cut_short;
  /// The only failure is the size test, and the drafts that never found room explain it (the
  /// test of the placed radii with theirs passes): a valid packing short of the law, exit 4.
  bool sizes_short_of_room = false;

  /// Valid, or short of its size law only for want of room (exit 4 rather than 3).
  bool valid() const { return validation.ok || sizes_short_of_room; }
  /// The record's verdict: "ok", kShortOfRoomVerdict or "FAILED".
  const char* verdict() const { return validation.ok ? "ok" : sizes_short_of_room ? kShortOfRoomVerdict : "FAILED"; }

  /// Exit 4: valid, but not the packing of the container the scene asks for.
  bool complete() const { return incomplete.empty() && cut_short.empty(); }
  /// The reasons of `cut_short` and `incomplete` in one text ("" when complete): stderr's, the
  /// record's and Python's.
  std::string incomplete_text() const {
    std::string why;
    for (const auto* reasons : {&cut_short, &incomplete})
      for (const std::string& w : *reasons) why += (why.empty() ? "" : "; ") + w;
    return why;
  }
};

/// The law a packing of spheres of `scene` is checked against (`pack` and `validate` alike): the
/// scene's, or with regions of laws of their own the uniform law over all their ranges (only the
/// range is then tested: their radii come from the voids).
/// With stop.scale_sizes, the scene's law scaled by the factor fitted from `radii`
/// (core/metrics/radius_scale_fit.hpp): the size test asks for the law's shape.
RadiusDistributionPtr radii_to_check(const Scene& scene, std::span<const double> radii);

/// The overlap a packing of `scene` may have, relative to the smaller radius of a pair (`pack` and
/// `validate` alike): the contact tolerance, plus the epsilon the tetrahedral-mesh packer or the
/// void filling allows (epsilon r_min is within epsilon of the smaller radius; the contact
/// tolerance absorbs the rounding of an overlap placed at exactly epsilon r_min); at least the
/// least-squares densification's tolerance when the scene asks for it.
double overlap_tolerance(const Scene& scene);

/// The level of the radii test for a packing of `scene`: 0 (their range only) where the radii are
/// the voids' own (method tet_mesh, densify radii: fit, regions) or least squares moved them
/// within it (least_squares radii: range), else kRadiiAlpha.
double radii_alpha_of(const Scene& scene);

/// The drafts a front set aside and never placed (`never_fit`: their radii): a summary line, and
/// when they alone make the size test of `placed` against `law` fail (at the validation's level;
/// with them it passes), the packing is short of its law for want of room: sizes_short_of_room
/// and the reason in `incomplete`. A class far larger than the rest needs room the growing
/// packing may no longer leave (a container a few of its diameters wide).
void add_never_fit_lines(PackCheck& c, const std::vector<double>& never_fit, std::vector<double> placed,
                         const RadiusDistribution* law);

/// A front that the scene's stop ended (`stop`: the time limit, stop.particles or
/// stop.volume_fraction; nothing when it ran empty) left the container unfilled: the reason in
/// `cut_short`, with `count` particles at `container_fraction` of the container.
void add_cut_short_reason(PackCheck& c, const StopCriteria& criteria, StopReason stop, std::size_t count,
                          double container_fraction);

/// The record's figures of an analysis (its validation included) and its table as summary lines.
PackCheck pack_check_of(const PackingAnalysis& analysis);
/// The validation alone (CheckDepth::Validation); `volume_fraction`: the packer's own figure.
PackCheck pack_check_of(const ValidationReport& validation, double volume_fraction);

}  // namespace fp
