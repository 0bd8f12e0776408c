#pragma once
// A scene: everything a run needs, read from a YAML file (core/io/scene_yaml.cpp).
// Plain data plus the container and distribution objects the file describes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/tet_mesh.hpp"
#include "core/io/output_format.hpp"
#include "core/sampling/orientation_law.hpp"
#include "core/sampling/radius_distribution.hpp"

namespace fp {

/// Which front particle s0 is tried next (paper 002 uses Random).
enum class FrontPick { Random, Fifo, ClosestToSeed };
/// Which of the (up to two) valid candidates of a pair is kept, and whether all pairs are scanned.
enum class CandidateChoice { First, ClosestToSeed };
/// Order of the neighbour pairs (si, sj) tried around s0.
enum class PairOrder { Index, NearestFirst };
/// Which neighbours of s0 a new particle may be placed tangent to: all of V (paper 002), or only
/// those still in the front F. A closed particle is still an obstacle in both cases.
enum class ContactBodies { All, Front };
/// Non-spherical particles under the isotropic law: the frame their orientation is drawn in and
/// chosen in. Radial: relative to the radius from the seed point, the choices (trials, pocket
/// trials, roll) turning only about that radius, so that no texture about the seed point forms.
/// Lab: in the container's frame, turned about any axis (denser; elongated particles then lie
/// across the radius).
enum class OrientationFrame { Radial, Lab };

/// Widest size ratio for which probe_smallest is on by default (measured: experiments/front-levers).
inline constexpr double kProbeRatioLimit = 8.0;

/// The potential-minimisation contact solver (paper 004, Eq. 4): the speed-accuracy knobs,
/// measured in experiments/perez-morales2016.
struct MinimisationOptions {
  /// "newton" (Newton on the contact equations ω_i = 0 from each start, SLSQP where it fails),
  /// or an NLopt algorithm: "slsqp" (Σω² with gradients), "lbfgs" (Σω² with gradients),
  /// "nelder-mead" (Σ|ω|, the paper's choice), "cobyla" (Σ|ω|), "sbplx" (Σ|ω|).
  std::string algorithm = "slsqp";
  double gap_tolerance = 1e-6;  ///< accept a solution when every |ω_i| <= gap_tolerance * size
  int max_evaluations = 200;    ///< objective evaluations per minimisation (each solve runs two)
  bool polish = true;           ///< finish with Newton steps on ω_i(x) = 0 (gradients needed)
};

/// Which contact solvers place non-spherical particles: the closed-form ones (wrappers, analytic
/// spheres) where they reach and minimisation elsewhere, or minimisation for every problem (the
/// paper's Sect. 3.2 method alone; for comparisons).
enum class ContactSolverChoice { Auto, Minimisation };

/// The smallest block edge of a packing grown in blocks, in largest particle sizes: two blocks
/// growing at once are a block apart (front/block_front.hpp) and each places centres up to
/// 2 r_max beyond its box, so 6 r_max keeps what they place out of each other's reach; 8 leaves
/// room for a bulk.
inline constexpr double kMinBlockEdge = 8.0;
/// The most blocks a packing grown in blocks may have (each is a unit of scheduling, with its
/// own bookkeeping): 10^9 spheres on 1,000 ranks want about 1.7 x 10^6 (experiments/scale).
inline constexpr double kMaxBlocks = 4194304.0;

/// Blocks along an axis of extent `size` for the requested block `edge`: the nearest whole
/// number, at least 1, and no more than blocks of kMinBlockEdge r_max fit.
inline double blocks_along(double size, double r_max, double edge) {
  const double fit = std::floor(size / (kMinBlockEdge * r_max));
  return std::clamp(std::round(size / edge), 1.0, std::max(1.0, fit));
}

/// The tetrahedral-mesh packer (fill/tet_mesh_fill.hpp, paper 000): its parameters besides the
/// radius range (the scene's law) and phi0 / N0 (`stop:`).
struct TetMeshOptions {
  double overlap = 0.0;  ///< epsilon: overlap allowed between spheres, times r_min
  int z_min = 3;         ///< contacts a sphere of the geometric procedure needs (walls count)
  bool loose = false;    ///< skip steps 5 and 6 (a loose packing)
  bool fallback_r_min = false;  ///< step 7b: DensifyOptions::fallback_r_min
  /// A surface container (STL/OFF/OBJ) is meshed into tetrahedra of about this edge; unset: the
  /// paper's 8 mean radii.
  std::optional<double> mesh_edge;
};

/// The graded large-first stacking (fill/graded_stacking.hpp, paper 003): tries per step.
struct StackingParameters {
  int random_tries = 4;        ///< (5) completely random positions per particle
  int near_tries = 2;          ///< (6) random positions near a nucleus
  int two_contact_tries = 4;   ///< (7) random positions touching a nucleus and a neighbour
  int nuclei = 1000000;        ///< (8) open nuclei tried per particle at most (default: every one; see fill/graded_stacking.hpp)
  int pairs_per_nucleus = 64;  ///< (8) pairs of bodies that can both touch, tried around a nucleus (256: as dense, 1.2-1.7x slower)
  int reshapes = 8;            ///< (11) reshape passes at most (0: none)
  bool contacts_first = false; ///< `order: contacts_first`: (8) first, then (7), (6), (5); `paper`: (5) .. (8)
  double random_share = 0.0;   ///< contacts_first: the first share of the list's solid in the paper's order
  /// (12) the particles left without a place go into the voids of the Delaunay triangulation of
  /// the centres (densify/void_filling.hpp, the list mode), largest first.
  bool voids = true;
};

struct PackerOptions {
  /// "front": the advancing front; "tet_mesh": paper 000's packing of a tetrahedral mesh (a .msh
  /// container), followed by its void filling (step 7b); "stacking": paper 003's graded
  /// large-first stacking of the list the target (or stop.particles) makes.
  std::string method = "front";
  TetMeshOptions tet_mesh;                   ///< method tet_mesh only
  StackingParameters stacking;               ///< method stacking only
  FrontPick front_pick = FrontPick::ClosestToSeed;
  CandidateChoice candidate = CandidateChoice::ClosestToSeed;
  PairOrder pair_order = PairOrder::NearestFirst;
  ContactBodies contact_bodies = ContactBodies::Front;  ///< pairs among front particles only: ~4x fewer solves
  /// With a pool: first check that the smallest pooled radius fits at s0 and drop s0 at once if
  /// not (one failed scan instead of one per radius). Sound when a radius that does not fit
  /// implies larger ones do not either, which fails for wide distributions (a large particle can
  /// bridge a gap a small one cannot). Unset = on when r_max / r_min <= kProbeRatioLimit.
  std::optional<bool> probe_smallest;
  bool walls_as_bodies = true;               ///< particles may touch container walls (closes the boundary gap)
  int radius_pool = 4;                       ///< radii drawn ahead; a radius that does not fit waits, others are tried (1 = paper)
  double contact_tolerance = 1e-9;           ///< relative: a contact is |gap| <= tol * min(ri, rj)
  double grid_cell_factor = 2.0;             ///< grid cell size = factor * r_max of its level
  double hierarchical_grid_ratio = 4.0;      ///< use the hierarchical grid when r_max / r_min exceeds this
  std::optional<std::vector<double>> seed_point;  ///< where growth starts (default: container interior point)
  MinimisationOptions minimisation;          ///< non-spherical particles only
  /// Non-spherical particles: orientations drawn from the template's law per placement, the
  /// position kept by the compactness rule over all of them (front/advancing_front.hpp).
  int orientation_trials = 1;
  /// Non-spherical particles, lab frame: orientation trials beyond the first turn a face of a
  /// polytope against one of s0's (isotropic laws; other shapes draw from their law).
  bool face_to_face = false;
  /// Non-spherical particles under the isotropic law: orientations drawn per placement in the
  /// pocket the scan found (its contact problem solved again at each), the one closest to the
  /// seed point kept (0: none). In the radial frame they turn the particle about the radius only.
  int pocket_trials = 32;
  /// Non-spherical particles under the isotropic law: the frame of the orientation's choice.
  OrientationFrame orientation_frame = OrientationFrame::Radial;
  /// Non-spherical particles: turns tried per placement by the roll, which turns the particle
  /// within its law while it touches the same bodies, towards the seed point (0: no roll).
  int roll_steps = 60;
  ContactSolverChoice contact_solver = ContactSolverChoice::Auto;  ///< non-spherical particles only
  /// Threads (0: every hardware thread). Above 1 the container is grown in blocks
  /// (front/block_front.hpp), whose output does not depend on the thread count.
  int threads = 1;
  /// The blocks' edge (the automatic one when unset); setting it grows in blocks even on one thread.
  std::optional<double> block_edge;
  bool in_blocks() const { return threads != 1 || block_edge.has_value(); }
};

struct StopCriteria {
  std::optional<std::uint64_t> max_particles;     ///< stop after N particles
  std::optional<double> target_volume_fraction;   ///< stop when sum of particle volumes / container volume >= phi0
  std::optional<double> time_limit_seconds;       ///< stop after this wall time
  /// With max_particles: the size law is scaled (its shape kept) so that N particles fill the
  /// container, the scale solved for by trial packings (cli/scaled_sizes.hpp).
  bool scale_sizes = false;
  // The front running empty always stops the run.
};

/// How a sphere filling a void gets its radius (densify/void_filling.hpp).
enum class VoidRadii {
  /// Drawn from the scene's distribution, `radius_pool` ahead: the largest pooled radius that
  /// fits a void goes in, so at most the pool is left unplaced (the bias the radii test sees).
  Distribution,
  /// The void's own (paper 000, Sect. 2.1): the sphere touching its D + 1 bodies, kept when in the
  /// distribution's [r_min, r_max] (r_max when larger, reduced to cancel an overlap in last
  /// resort). Only the range is then asked of the radii; their law drifts small.
  Fit
};

/// Void filling after the packer (`densify:`): spheres added into the voids of the Delaunay
/// triangulation of the centres (paper 000, step 7b), largest void first, round after round.
struct DensifyOptions {
  VoidRadii radii = VoidRadii::Distribution;
  int radius_pool = 0;    ///< Distribution: radii drawn ahead; 0: half the square root of the packing's count, at least 4
  double overlap = 0.0;   ///< epsilon: overlap allowed between spheres, times the distribution's r_min (paper 000: delta_max = epsilon r_min)
  int z_min = 0;          ///< contacts (walls count) a new sphere needs; 0: the dimension
  int rounds = 0;         ///< triangulations at most; 0: until one adds nothing
  /// Fit: a void whose own sphere does not go in (overlapping, or reduced below r_min) takes a
  /// sphere of r_min touching D of its bodies: denser, with many more spheres of r_min.
  bool fallback_r_min = false;
  /// Distribution: split the law at this radius r_s: the packer packs its part above r_s, the
  /// voids take its part at or below r_s, up to the count that keeps the law's proportions
  /// (N_packed / (1 - F(r_s)) in all), so the whole stays a sample of the law.
  std::optional<double> split;
  std::optional<double> target_volume_fraction;  ///< phi0: stop once the packing reaches it (checked after every sphere)
  std::optional<std::uint64_t> max_particles;    ///< N0: stop once the packing holds this many
  /// Distribution, set by code (not a scene key): these radii and no others, largest first into
  /// the voids, none drawn (the graded stacking's particles left without a place); stops when
  /// every one is placed or no void takes one.
  std::vector<double> list;
};

/// What least-squares densification may change besides the centres (densify/least_squares.hpp).
enum class LeastSquaresRadii {
  Fixed,  ///< the centres alone: contacts gained, the solid fraction kept
  Range   ///< the paper's: each radius too, within the law's [r_min, r_max] (denser; the law drifts)
};

/// Least-squares densification (`least_squares:`, paper 001): after the packer and the void
/// filling, the centres (and radii) minimise Eq. 4 over the edges of the Delaunay triangulation
/// of the centres, then every overlap is removed without losing a particle.
struct LeastSquaresOptions {
  LeastSquaresRadii radii = LeastSquaresRadii::Range;
  int evaluations = 100;       ///< of Eq. 4 and its gradient, at most (L-BFGS)
  int relax_evaluations = 50;  ///< of the penalised Eq. 4, per round of the overlap removal
  bool boundary = true;      ///< Eqs. 3-4: particles near a wall drawn to touch it
  /// Edges of the triangulation whose gap is above this times r_i + r_j are left out; 0: every
  /// edge (the paper's: the edges of its finite element mesh). Measured (experiments/
  /// labra-densification): every edge draws the hull's long edges and those across voids, and
  /// the solid fraction of a front packing fell from 0.56 to 0.35; a smaller bound densifies
  /// more and makes fewer contacts (0.2: 0.594, z 3.6; 0.3: 0.585, z 3.9; 0.5: 0.551, z 4.3).
  double edge_gap = 0.3;
  int relax_rounds = 8;      ///< overlap removal: rounds of Eq. 4 under a growing penalty on overlaps, at most
  /// The stage's overlap allowance and contact tolerance, relative to the smaller radius (a
  /// minimiser brings pairs into contact to about this, not to the packer's rounding); the
  /// packing's tolerance is the larger of it and packer.contact_tolerance.
  double tolerance = 1e-6;
};

/// A physical volume of a tetrahedral mesh with laws of its own (`regions:`, paper 000: "by
/// defining different regions with different solid fractions it is thus possible to obtain a
/// gradient of density").
struct RegionSpec {
  std::string name;                               ///< the physical volume's name (or its tag) in the mesh file
  int tag = 0;                                    ///< its physical tag
  RadiusDistributionPtr radii;                    ///< its radius law; null: the scene's
  std::optional<double> target_volume_fraction;   ///< its phi0; unset: the scene's stop
};

/// Where a value was written in the scene file, so that errors found later (shape families are
/// resolved in shapes/, above core/) still name the file, line and key (SceneError).
struct SourceSpot {
  std::string file;
  int line = 0;    ///< 1-based; 0 = unknown
  int column = 0;
  std::string key; ///< dotted path, e.g. "particles[0].aspect_ratio"
  /// "file:line:column: key 'k'" as in SceneError messages.
  std::string describe() const {
    std::string s = file;
    if (line > 0) s += ":" + std::to_string(line) + ":" + std::to_string(column);
    return key.empty() ? s : s + ": key '" + key + "'";
  }
};

struct OutputSpec {
  std::string format;  ///< vtu | yade | lammps | csv | json
  std::string path;    ///< relative paths are relative to the working directory
  SurfaceDetail surfaces = SurfaceDetail::Fine;  ///< vtu of shapes: its surfaces side file
  SourceSpot spot;     ///< where `path` was written (empty file for -o)
};

/// A shape family's parameters as written in the scene (everything but the common template keys),
/// resolved into a shape by shapes/shape_registry.hpp.
struct ShapeParameters {
  std::map<std::string, double> numbers;                              ///< aspect_ratio: 0.5
  std::map<std::string, std::vector<double>> lists;                     ///< radii: [1, 0.5]
  std::map<std::string, std::vector<std::vector<double>>> point_lists;  ///< vertices: [[0,0,0], ...]
  std::map<std::string, std::string> strings;                           ///< preset: cube
  std::map<std::string, SourceSpot> spots;                              ///< per key above: where it was written
  SourceSpot spot;                                                      ///< the template itself
};


/// What a template's `fraction` is a share of: the particles' number, or their volume (mass:
/// one material for every template, so the same shares).
enum class FractionBasis { Number, Volume };

/// One particle template: a shape family, its parameters, a size distribution on a named
/// dimension and an orientation distribution. `fraction` weights templates, by number or by
/// volume (shapes/template_fractions.hpp converts it to shares by number).
struct ParticleTemplateSpec {
  std::string family;                                  ///< "sphere", "spherocylinder", "polyhedron", ...
  ShapeParameters parameters;
  std::string size_on = "circumscribed_radius";         ///< which dimension `size` is drawn on
  RadiusDistributionPtr size;                           ///< the size distribution (on that dimension)
  OrientationSpec orientation;
  double fraction = 1.0;                                ///< share among the templates, on fraction_basis
  FractionBasis fraction_basis = FractionBasis::Number; ///< `fraction: 0.3` by number; `{volume: 0.3}`, `{mass: 0.3}`
};

struct Scene {
  std::string source_path;   ///< file the scene was read from ("" if built in code)
  std::string source_text;   ///< its exact text, carried into the run record
  std::vector<std::string> overrides;  ///< "KEY=VALUE" changes applied to that text (--set, a study's run), in order
  int dimension = 3;
  std::uint64_t seed = 1;
  ContainerPtr<2> container2;  ///< set when dimension == 2
  ContainerPtr<3> container3;  ///< set when dimension == 3
  /// A container read from a Gmsh .msh file: its tetrahedra, in the container's local frame.
  std::shared_ptr<const TetMesh> tet_mesh;
  /// The container of dimension D (null if the scene has the other dimension).
  template <int D>
  const Container<D>* container() const {
    if constexpr (D == 2) return container2.get();
    else return container3.get();
  }
  RadiusDistributionPtr radii;  ///< spheres/disks: the radius distribution (null for a shape scene)
  /// Non-spherical particles (`particles: [{shape: ..., size: ..., ...}, ...]`); empty for a
  /// sphere/disk scene, which keeps the sphere fast path (no FCL, no NLopt).
  std::vector<ParticleTemplateSpec> particle_templates;
  PackerOptions packer;
  StopCriteria stop;
  std::optional<DensifyOptions> densify;  ///< void filling after the packer (spheres only)
  std::optional<LeastSquaresOptions> least_squares;  ///< after the void filling (spheres only)
  /// `target:` the solid fraction the whole container is to have (given as solid_fraction,
  /// porosity n = 1 - phi or void ratio e = 1 / phi - 1): the packer packs to its own density,
  /// then particles spread over the whole container are removed down to it (densify/thinning.hpp);
  /// a fill with a phi0 of its own (tet_mesh, the void filling) stops at it.
  std::optional<double> target_solid_fraction;
  std::vector<RegionSpec> regions;        ///< method tet_mesh: physical volumes with laws of their own
  /// `material: {density}`: the particles' material density, mass per unit volume of the scene's
  /// length unit (2D too: LAMMPS takes a disk's mass as a sphere's); written into the LAMMPS data
  /// files and the record. Default: quartz sand in SI units (kg/m^3).
  double density = 2650.0;
  std::vector<OutputSpec> outputs;
  /// Every file the scene was read from (itself, a mesh): no output may replace them.
  std::vector<std::string> read_files;
  /// Where the keys checked after parsing were written (core/io/scene_limits.hpp), by dotted key:
  /// "container", "particles", "stop", "stop.particles", "stop.volume_fraction", "packer.radius_pool";
  /// a key the file does not have is absent.
  std::map<std::string, SourceSpot> spots;
  /// The spot of `key`, or the file alone when the scene does not write it.
  SourceSpot spot(const std::string& key) const {
    const auto it = spots.find(key);
    return it != spots.end() ? it->second : SourceSpot{source_path, 0, 0, key};
  }
};

}  // namespace fp
