#pragma once
// Every quality figure of a packing, computed once by one function: what `frontpack analyze`
// prints, what `frontpack pack` records and what the analysis JSON (core/io/analysis_json.hpp)
// carries. Definitions, each in its own file:
//   VF in a reference ball and the VF-vs-r_ref curve ... volume_fraction.hpp (paper 002 Eq. 2, Sect. 5)
//   VF of the container and of its core ............... container_volume_fraction.hpp (paper 000 Eq. 16)
//   VF in cells of a few mean diameters (uniformity) ... cell_volume_fraction.hpp
//   coordination, walls, rattlers, max overlap ......... contact_stats.hpp (paper 000 Eq. 15)
//   partial coordination z(xi) ......................... partial_coordination.hpp (paper 000 Sect. 3.2)
//   fabric tensors ..................................... fabric.hpp (paper 000 Eq. 17, paper 002 Eq. 1)
//   K-S of centre coordinates .......................... homogeneity.hpp (paper 002 Sect. 4)
//   the radii against the requested distribution ....... radii_fit.hpp
//   relative projections ............................... contact_normals.hpp (paper 002 Sect. 1)
//   g(r) ............................................... radial_distribution.hpp (paper 000 Sect. 3.3)
//   validation ......................................... validate.hpp
// Plain data, the same for 2D and 3D (per-axis figures are vectors of D entries).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/metrics/bed_profile.hpp"
#include "core/metrics/contact_normals.hpp"
#include "core/metrics/contact_stats.hpp"
#include "core/metrics/cell_volume_fraction.hpp"
#include "core/metrics/container_volume_fraction.hpp"
#include "core/metrics/fabric.hpp"
#include "core/metrics/homogeneity.hpp"
#include "core/metrics/ks_result.hpp"
#include "core/metrics/partial_coordination.hpp"
#include "core/metrics/radial_distribution.hpp"
#include "core/metrics/radii_fit.hpp"
#include "core/metrics/validate.hpp"
#include "core/metrics/wall_profile.hpp"
#include "core/sampling/radius_distribution.hpp"

namespace fp {

/// The wall profile's shells: kWallShells of r_max / kWallShells * 2 (out to the core's 2 r_max).
inline constexpr int kWallShells = 8;

struct AnalysisOptions {
  double contact_tolerance = 1e-9;      ///< relative: a contact is gap <= tol * min(ri, rj)
  int vf_curve_points = 31;             ///< paper 002: 31 equispaced r_ref in [r_max, a]
  int partial_coordination_points = 21; ///< xi = 0, 0.05, ..., 1
  int projection_bins = 20;
  RdfOptions rdf;
  QmcOptions qmc;                       ///< container and core VF
  bool validate = true;                 ///< also run validate_packing (overlap tolerance = contact_tolerance)
  double radii_alpha = kRadiiAlpha;     ///< the validation's level for the radii test (0: their range only)
  int threads = 1;                      ///< threads sharing the work; the figures are the same for every count
};

struct PackingAnalysis {
  int dimension = 3;
  std::uint64_t particles = 0;          ///< all balls, including any with non-finite data
  double r_min = 0.0, r_max = 0.0, r_mean = 0.0;  ///< of the positive finite radii; r_mean by count
  /// What r_min, r_max, r_mean, z(xi) and g(r)'s <d> are radii of: "r" (spheres), or "r_eq" for a
  /// packing of shapes (the radius of the ball of the same volume, contact/shape_analysis.hpp).
  std::string radius_name = "r";
  std::vector<std::pair<std::string, std::uint64_t>> templates;  ///< shapes: family and count per template id
  std::string container;                ///< description
  bool container_from_particles = false;  ///< no container given: the bounding box of the balls
  double container_measure = 0.0;
  double contact_tolerance = 0.0;

  // Volume fraction.
  std::vector<double> reference_center;  ///< c_ref = the container's interior point
  double reference_radius = 0.0;         ///< a = its distance to the boundary (half the smallest side of a box)
  double vf_reference = 0.0;             ///< VF in the ball (c_ref, a): the figure paper 002 reports
  std::vector<std::pair<double, double>> vf_curve;  ///< (r_ref, VF) at equispaced r_ref in [r_max, a]
  RegionVolumeFraction vf_container;     ///< whole container
  RegionVolumeFraction vf_core;          ///< container shrunk by 2 r_max
  CellVolumeFraction vf_cells;           ///< cells of 8 mean diameters (fewer if too few fit), 2 r_max inside
  WallProfile wall_profile;              ///< shells of r_max / 4 from the boundary out to the core (2 r_max)
  BedProfile bed;                        ///< a bed (container.bed): the solid fraction against the height

  // Contacts.
  ContactStats coordination;             ///< z, z with walls, histogram, rattlers, max overlap (all pairs)
  PartialCoordination partial_coordination;
  double max_overlap_rel = 0.0;          ///< max over all pairs of (ri + rj - d) / r_min, 0 if none overlap
  double max_contact_gap_rel = 0.0;      ///< max over the contacts of |d - ri - rj| / r_min
  Fabric fabric;
  RelativeProjections projections;

  // Homogeneity and size distribution.
  CentreHomogeneity homogeneity;         ///< K-S of x, y (, z) against uniform, margin r_max
  std::string distribution;              ///< the requested one, "" when none
  RadiiFit radii_fit;                    ///< finite radii against it: validate's own test (not computed without one)

  RadialDistribution rdf;
  /// Shapes: the orientation tensor <u u^T> of the body x axes (fabric.hpp's per-contact form of
  /// the axes; trace 1) and the nematic order S = (D lambda_max - 1) / (D - 1): 0 for isotropic
  /// orientations (to ~1/sqrt(N)), 1 for parallel axes.
  std::optional<FabricTensor> orientation;
  double orientation_order = 0.0;
  /// Shapes: the body axes against the direction from the reference centre (the container's
  /// interior point, where the front grows from by default): 3D <P2(a.r)>, 2D <cos 2 psi_r>,
  /// over the particles more than r_max from it; 0 without such a texture (within
  /// radial_order_noise, the standard deviation of an isotropic sample's mean), > 0 axes along
  /// the radius, < 0 across it (an onion). The marginal orientation tests cannot see it.
  double radial_order = 0.0;
  double radial_order_noise = 0.0;
  /// The same texture seen by every body axis e_i: <sum_i (e_i . r)^4> less its isotropic mean
  /// (3/5 in 3D, 3/4 in 2D), within radial_axes_order_noise when there is none; > 0 a face or
  /// axis of the body along the radius, < 0 an edge or diagonal. It sees cubes, whose x axis'
  /// radial order is blind to them (any of their axes may be the radial one).
  double radial_axes_order = 0.0;
  double radial_axes_order_noise = 0.0;
  std::optional<ValidationReport> validation;
  std::vector<std::pair<std::string, double>> timings;  ///< seconds per part (not deterministic)

  /// A human-readable table of the headline figures (one per line, no trailing newline).
  std::string summary() const;
};

/// The bounding box of the balls (with a finite centre and a positive radius) as a container, in
/// the packing's frame: the analysis' container when none is given; null when there is no such ball.
template <int D>
std::unique_ptr<Container<D>> bounding_box_of_balls(const Packing<D>& packing);

/// Analyses a packing. container_or_null: without one, the bounding box of the balls stands in
/// (container_from_particles). dist_or_null: the requested radius distribution, for the radii
/// K-S and validation. O(N log N) overall; see each metric's file for its cost.
template <int D>
PackingAnalysis analyze_packing(const Packing<D>& packing, const Container<D>* container_or_null,
                                const RadiusDistribution* dist_or_null, const AnalysisOptions& options = {});

}  // namespace fp
