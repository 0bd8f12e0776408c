#pragma once
// Packing a tetrahedral mesh: paper 000 (Jerier, Richefeu, Imbault, Donzé 2010), Sect. 2.2,
// steps 2 to 7a (Fig. 1); step 7b, the search for void spaces, is the void filling of
// densify/void_filling.hpp, which the command runs after it (any packer can be followed by it).
//   2, 3  spheres at the edge midpoints (r = l / 8) and at the nodes (r = the shortest adjacent
//         edge); a radius above r_max is drawn from the scene's law instead, one below r_min set
//         to r_min; then the overlapping ones reduced (edge spheres first, then nodes, each to
//         the spheres already kept: one pass, no overlap beyond epsilon r_min is left) and those
//         reduced below r_min removed;
//   4-6   the geometric procedure (Eqs. 1-9, contact/tangent_sphere.hpp) aimed at the faces'
//         barycentres (4), the tetrahedra's (5) and midway between a tetrahedron's barycentre
//         and its nodes (6): the sphere touching four of the spheres nearest the aim, tried in
//         4-sets of the nearest first, kept within [r_min, r_max] with z_min contacts, its radius
//         reduced in last resort (contact/sphere_placement.hpp); steps 5 and 6 may be skipped
//         for a loose packing, as the paper does;
//   7a    the spheres not inside the mesh's boundary removed. The paper marks the boundary with
//         virtual spheres tangent to the boundary faces; the container's exact distance does
//         the same without the spheres' approximation of a plane.
// The target solid fraction phi0 and count N0 are checked after every sphere of steps 4-6; with
// regions (physical volumes of their own law and phi0), each region's.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/geometry/container.hpp"
#include "core/geometry/packing.hpp"
#include "core/geometry/tet_mesh.hpp"
#include "core/sampling/radius_distribution.hpp"

namespace fp {

/// A region of the mesh with laws of its own.
struct TetRegion {
  const RadiusDistribution* radii = nullptr;     ///< its law; null: the fill's
  std::optional<double> target_volume_fraction;  ///< its phi0 (solid of the spheres aimed in it / its volume)
};

struct TetFillOptions {
  double overlap = 0.0;  ///< epsilon: overlap allowed between spheres, times r_min
  int z_min = 3;         ///< contacts a sphere of steps 4-6 needs
  bool loose = false;    ///< skip steps 5 and 6 (the paper: phi about 0.45 instead of 0.55)
  std::optional<double> target_volume_fraction;  ///< phi0
  std::optional<std::uint64_t> max_particles;    ///< N0
  /// Regions: tetrahedron t is in regions[tet_region[t]]; a sphere takes the region of the
  /// tetrahedron it is aimed from (an edge, node or face: the first tetrahedron that has it).
  /// Empty: one region, the fill's law and phi0.
  std::vector<TetRegion> regions;
  std::vector<int> tet_region;
};

struct TetFillReport {
  std::uint64_t edges = 0, nodes = 0, faces = 0, tets = 0;  ///< of the mesh
  std::uint64_t edge_spheres = 0;      ///< step 2: kept after the reduction
  std::uint64_t node_spheres = 0;      ///< step 3: kept after the reduction
  std::uint64_t removed_reduced = 0;   ///< steps 2-3: reduced below r_min, removed
  std::uint64_t face_spheres = 0;      ///< step 4
  std::uint64_t tet_spheres = 0;       ///< step 5
  std::uint64_t midway_spheres = 0;    ///< step 6
  std::uint64_t removed_boundary = 0;  ///< step 7a
  std::uint64_t mesh_spheres_kept = 0; ///< spheres of steps 2-3 left after 7a: the packing's first ones
  std::uint64_t procedures = 0;        ///< geometric procedures run (4-sets)
  bool reached_target = false;         ///< phi0 or N0 stopped it
  double seconds = 0.0;
};

/// Fills `mesh` (nodes in `container`'s local frame; the container is the mesh's boundary) with
/// spheres of `dist`'s range (its law where a radius is drawn) into `out` (cleared first).
TetFillReport fill_tet_mesh(const TetMesh& mesh, const Container<3>& container, const RadiusDistribution& dist,
                            const TetFillOptions& options, std::uint64_t seed, double contact_tolerance, Packing<3>& out);

}  // namespace fp
