#pragma once
// Writers of a packing of general shapes (shapes/particle.hpp) in the formats DEM users load:
// write_packing for a ShapePacking, the overload of core/io/packing_writers.hpp's for spheres
// (whose fast path needs no shape), so `pack` writes either kind with one call.
//
// Conventions shared by every format (the same as core/io/packing_writers.hpp):
// * Numbers are printed in the shortest decimal form that reads back to the same double
//   (std::to_chars); VTU stores the raw doubles. Non-finite numbers: "nan"/"inf" in text
//   formats, null in JSON.
// * "id" = 0-based particle index, "shape_id" = the particle's template_id (the index into
//   ShapePacking::template_names). LAMMPS atom ids are 1-based (LAMMPS requires it).
// * Quaternions are (w, x, y, z), unit, w >= 0 (shapes/pose.hpp quaternion_of); a 2D
//   rotation by theta is the quaternion (cos theta/2, 0, 0, sin theta/2).
// * 2D packings are written with z = 0 (CSV drops the z column instead).
// * Every file is written atomically (core/io/atomic_file.hpp). Formats with a companion file
//   (vtu, lammps) write both to temporaries and rename them only when both are complete; if
//   the second rename fails the first is removed again, so a failed write never leaves a
//   half-written file nor a companion that does not match its main file. Missing folders are
//   an error, never created.
//
// Layouts:
// * vtu: "<path>": one VTK_VERTEX per particle centre; point data id, shape_id (Int64), size,
//   bounding_radius, measure (Float64), quaternion (4 components w x y z), axis_x, axis_y,
//   axis_z (3 components each: the body axes in the world, rotation * e_k; handy for glyphs).
//   Companion "<stem>.surfaces.vtu" (surfaces_path()): every particle's surface(kShapeSurfaceResolution,
//   half of it with SurfaceDetail::Coarse; no companion with None) in the world frame: 3D one VTK_TRIANGLE per facet; 2D one VTK_POLYGON per closed loop of the
//   outline (the outline's segments are chained, points that coincide up to 1e-9 of the
//   bounding radius welded: one polygon per particle for a convex shape or a connected
//   cluster, one per separate piece otherwise; a chain that does not close becomes a
//   VTK_POLY_LINE), z = 0; cell data id, shape_id.
// * json: {"frontpack": <the run record, core/io/run_record.hpp>, "dimension": D,
//   "shapes": [{"shape_id", "name", "kind", "count", "representative_id",
//   "representative_size", "definition"}...], "particles": [{"id", "shape_id",
//   "position": [x, y, z], "quaternion": [w, x, y, z], "size"}...]}. "definition" is the
//   representative particle's Shape::definition_json() (at that particle's size; the other
//   particles of the template are the same shape scaled, each with its own "size"; its numbers
//   are reprinted in the shortest round-trip form); a template without particles has null
//   kind/representative/definition. 2D: position z = 0.
// * csv: if every particle is a spherocylinder: "id,shape_id,ax,ay,az,bx,by,bz,r" (3D) or
//   "id,shape_id,ax,ay,bx,by,r" (2D): the world end points of the axis segment
//   (pose.to_world(end_a()), pose.to_world(end_b())) and the radius. Otherwise (and for an
//   empty packing): "id,shape_id,kind,x,y,z,qw,qx,qy,qz,size,bounding_radius" (2D: no z).
// * yade (spheres and clusters only): YADE's ymport.textClumps layout, "#format
//   x_y_z_r_clumpId", a '#' line explaining the columns, then one line "x y z r clump_id" per
//   member ball (world centre; clump_id = particle id; a sphere is a clump of one).
// * lammps (spheres and clusters only): a LAMMPS data file, atom_style hybrid sphere bond, one
//   atom per member ball ("id type x y z diameter density molecule", type = shape_id + 1,
//   density = record.density, molecule = clump id + 1: `fix rigid/small molecule` runs the
//   clumps as written), atoms in clump order; box as core/io/packing_writers.hpp. Companion
//   "<stem>.multisphere.txt" (multisphere_path()): per clump a line
//   "clump_id member_count shape_id x y z qw qx qy qz" (clump reference point in the world and
//   its rotation), then member_count lines "x y z r" (member centre in the clump's body frame:
//   world = position + rotation(q) * body). Clump k's members are the atoms that follow clump
//   k-1's, in the same order. Both files explain this in their '#' header comments.
//
// Member balls of a sphere or cluster are its Shape::hull_balls() (for these two families the
// hull balls are exactly the balls the shape is made of).
#include <string>
#include <vector>

#include "core/io/output_format.hpp"
#include "core/io/run_record.hpp"
#include "shapes/particle.hpp"

namespace fp {

/// Segments per full turn of curved parts in the surfaces VTU: 24 for 2D outlines, 12 in 3D
/// (a 3D capsule at 24 took 35 KB of VTU; 7,000 capsules of the paper's case then made 250 MB).
template <int D>
inline constexpr int kShapeSurfaceResolution = D == 2 ? 24 : 12;

/// The segments per turn of a surfaces side file of that detail: kShapeSurfaceResolution, or
/// half of it for Coarse.
template <int D>
constexpr int surface_resolution(SurfaceDetail detail) {
  return detail == SurfaceDetail::Coarse ? kShapeSurfaceResolution<D> / 2 : kShapeSurfaceResolution<D>;
}

/// Writes `packing` to `path` (and its companion, see above; `surfaces`: how finely a vtu's) in `format`. `record` supplies the
/// run record of the JSON, the LAMMPS box (record.bounds, else the member balls' bounding box)
/// and density, and the version named in headers.
/// Throws std::invalid_argument (naming the path, nothing written) if `format` cannot represent
/// these particles, and std::runtime_error naming the path on any other failure.
template <int D>
void write_packing(OutputFormat format, const std::string& path, const ShapePacking<D>& packing,
                         const RunRecord& record, SurfaceDetail surfaces = SurfaceDetail::Fine);

/// Throws std::invalid_argument with a clear message if `format` cannot represent particles of
/// the shape `families` (family / kind names such as "sphere", "cluster", "spherocylinder"):
/// yade and lammps write spheres and clusters only ("sphere", "disk", "cluster"); vtu, csv and
/// json write every shape. Meant
/// to be called before packing, so that nothing is lost.
template <int D>
void check_shape_format(OutputFormat format, const std::vector<std::string>& families);

/// Every file besides `path` that an output of `format` (and surface detail) writes (its companion, if any): the
/// commands check them like the outputs themselves, before packing.
std::vector<std::string> companion_paths(OutputFormat format, const std::string& path,
                                         SurfaceDetail surfaces = SurfaceDetail::Fine);

/// The surfaces companion of a vtu output: "out/capsules.vtu" -> "out/capsules.surfaces.vtu".
std::string surfaces_path(const std::string& path);

/// The clump companion of a lammps output: "out/clumps.data" -> "out/clumps.multisphere.txt".
std::string multisphere_path(const std::string& path);

}  // namespace fp
