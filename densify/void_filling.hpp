#pragma once
// Void filling for any packing of spheres (disks): paper 000 (Jerier et al. 2010), Sect. 2.2,
// step 7b, "in search of void spaces". The voids are the simplices of the Delaunay triangulation
// of the centres (CGAL), taken largest void first (Eq. 10: the simplex's volume minus the
// spheres' parts in its corners); each gets a sphere touching D of its bodies, or all D + 1 with
// the radius the void gives (Eqs. 1-9, contact/tangent_sphere.hpp). The triangulation then grows
// by the new spheres and the next round visits the voids they made (a void that was not filled
// stays unfillable: its bodies are the same and its surroundings only fuller; in distribution
// mode, where a later draw may be smaller, the open ones are visited again), round after round,
// until a round adds nothing, a round limit, a target solid fraction phi0 or a count N0 (both
// checked after every sphere, as the paper asks).
//
// Walls: the centres near the container's boundary are mirrored across it, so the triangulation
// also has the voids between the outer spheres and the walls; in such a void the wall itself
// (not the mirror) is the body a new sphere touches, through the analytic sphere solver
// (contact/sphere_contact_solver.hpp), and every position is checked against the container.
//
// Radii (DensifyOptions::radii): drawn from the scene's distribution with a pool, so at most the
// pool is left unplaced and the radii stay a sample of the law up to that bias; or the void's own
// (the paper's), within [r_min, r_max], reduced in last resort to cancel an overlap, and kept only
// with at least z_min contacts.
//
// Overlaps: at most epsilon r_min between spheres (paper 000's delta_max), and never beyond the
// contact tolerance with a wall; with epsilon = 0 every new sphere is tangent to its bodies to
// the solver's rounding and overlaps nothing beyond the contact tolerance.
#include <cstddef>
#include <cstdint>
#include <functional>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/io/scene.hpp"
#include "core/sampling/radius_distribution.hpp"

namespace fp {

enum class VoidFillingStop { NoVoidFits, Rounds, VolumeFraction, ParticleCount };
const char* to_string(VoidFillingStop stop);

struct VoidFillingReport {
  std::size_t before = 0;              ///< spheres of the packing given
  std::size_t added = 0;               ///< spheres added
  int rounds = 0;                      ///< triangulations made
  VoidFillingStop stop = VoidFillingStop::NoVoidFits;
  std::uint64_t voids = 0;             ///< simplices met, over every round
  std::uint64_t voids_open = 0;        ///< of them, with room for a sphere of r_min
  std::uint64_t mirrored = 0;          ///< mirror points of centres near the walls, over every round
  std::uint64_t positions_tried = 0;   ///< positions checked
  std::uint64_t rejected_overlap = 0;  ///< overlapping a sphere beyond the allowance
  std::uint64_t rejected_container = 0;  ///< not inside the container
  std::uint64_t rejected_contacts = 0;   ///< fewer than z_min contacts, or (fit) reduced below r_min
  std::uint64_t radii_drawn = 0;       ///< distribution: radii drawn
  std::uint64_t radii_unplaced = 0;    ///< distribution: drawn, never placed (the pool at the end)
  std::uint64_t radii_reduced = 0;     ///< fit: radii reduced to cancel an overlap (the paper's last resort)
  std::uint64_t radii_capped = 0;      ///< fit: voids with room for more than r_max, given r_max
  double solid_before = 0.0;           ///< sum of the sphere volumes (2D: areas) given
  double solid_after = 0.0;            ///< and after
  double max_overlap_over_r_min = 0.0; ///< largest overlap of a new sphere with any other, / r_min (<= epsilon)
  double seconds = 0.0;                ///< the whole stage
  double triangulation_seconds = 0.0;  ///< of which the triangulations

  /// Another run's (the next region's) added: counts and times summed, its stop, the deeper
  /// overlap; solid_after becomes its.
  VoidFillingReport& operator+=(const VoidFillingReport& o);
};

/// Void filling confined to a region (a physical volume of a tetrahedral mesh, paper 000's
/// "applied only to a given region"): only the voids whose room's centre it contains are
/// filled, and phi0 is the volume of the spheres centred in it over its measure.
template <int D>
struct VoidRegion {
  std::function<bool(const Vec<D>&)> contains;
  double measure = 0.0;
};

/// Adds spheres into the voids of `packing` (centres in `container`'s local frame), from `dist`
/// (its law in distribution mode; its range in fit mode) with the options; draws from a stream
/// of its own for `seed`. `contact_tolerance` (relative to the smaller radius) is what counts as
/// touching. The same inputs give the same spheres, byte for byte. With a `region`, solid_before /
/// solid_after are the region's.
template <int D>
VoidFillingReport fill_voids(Packing<D>& packing, const Container<D>& container, const RadiusDistribution& dist,
                             const DensifyOptions& options, std::uint64_t seed, double contact_tolerance,
                             const VoidRegion<D>* region = nullptr);

}  // namespace fp
