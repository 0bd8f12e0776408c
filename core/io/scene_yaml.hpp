#pragma once
// Reads a scene file (YAML) into a Scene: containers and radius distributions constructed,
// packer options, stop criteria and outputs checked. Every problem is a SceneError naming
// the file, line, column and dotted key (scene_error.hpp). Nothing is silently ignored: an
// unknown key, or a key the chosen container/distribution does not use, is an error.
// yaml-cpp is included only in fp_io, behind core/io/yaml_document.hpp.
//
// Schema ("*" = required):
//   dimension*: 2 | 3
//   seed: unsigned 64-bit integer (default 1)
//   container*:
//     type*: box | sphere | cylinder | mesh (3D);  rectangle | disk | polygon (2D)
//     box/rectangle:  min*, max*   ([x, y(, z)], min < max on every axis)
//     sphere/disk:    center*, radius*
//     cylinder:       base* (centre of the bottom cap), axis (default [0, 0, 1]), radius*, height*
//     polygon:        vertices* ([[x, y], ...], at least 3)
//     mesh:           file* (STL/OFF/OBJ, relative to the scene file's folder), scale (default 1)
//   particles*: spheres/disks (the sphere fast path, Scene::radii):
//     radius*:
//       distribution*: constant | uniform | normal | lognormal | discrete | histogram | gradation
//       constant:  value*
//       uniform:   min*, max*
//       normal:    mean*, std*, min*, max*          (truncated to [min, max])
//       lognormal: median* or mu* (= ln median), sigma* (of ln r), min*, max*
//       discrete:  values* ([[radius, count weight], ...])
//       histogram: edges* (radius bin edges), weights* (count weight per bin)
//       gradation: curve* ([[sieve DIAMETER, % passing], ...]), basis (mass | count, default mass)
//   particles*: or particle templates (Scene::particle_templates): a list of templates, or one
//               template mapping (told from the sphere form by its `shape` key):
//     - shape*: family name (sphere, spherocylinder, cluster, polygon, polyhedron, ellipse,
//               ellipsoid, ...; resolved and checked by shapes/shape_registry.hpp, not here)
//       size*: a distribution as under `radius` above, drawn on `size_on`
//       size_on: the dimension `size` is drawn on (default circumscribed_radius; checked by shapes/)
//       orientation: random (default) | {fixed: angle in degrees} (2D) | {fixed: [w, x, y, z]} (3D,
//                    a unit quaternion; normalised when its norm is within 1e-6 of 1, else an error)
//       fraction: share by number among the templates, > 0 (default 1)
//       <any other key>: a family parameter: a number (aspect_ratio: 0.5), a list of numbers
//                    (radii: [1, 0.5]) or a list of points (vertices: [[0, 0], [1, 0], [0, 1]]),
//                    (ShapeParameters::numbers/lists/point_lists)
//     Every key written in a template, common ones included, has its file/line/column/dotted key
//     in ShapeParameters::spots (e.g. "particles[0].aspect_ratio"); ShapeParameters::spot is the
//     template itself ("particles[0]", or "particles" for the single-mapping form).
//   packer:
//     method: front;  front: closest | random | fifo;  candidate: closest | first;
//     pair_order: nearest | index;  contact_bodies: front | all;  probe_smallest: auto | bool;  walls: bool;  radius_pool: integer 1..1024;
//     contact_tolerance: in (0, 1e-3);  grid_cell_factor: >= 1;  hierarchical_grid_ratio: > 1;
//     seed_point: [x, y(, z)] inside the container
//     contact_solver (particle templates only): auto | minimisation
//     minimisation (particle templates only; MinimisationOptions):
//       algorithm: newton | slsqp | lbfgs | nelder-mead | cobyla | sbplx;  gap_tolerance: in (0, 0.1);
//       max_evaluations: integer >= 10;  polish: bool
//   stop:
//     particles: integer > 0 (1e6 accepted);  volume_fraction: in (0, 1);  time: seconds > 0
//   material: {density: mass per unit volume, > 0 (default 2650: quartz, SI)}  (the LAMMPS data files)
//   output: list of {format: vtu | yade | lammps | csv | json (default: from the path's
//           extension), path*: relative to the working directory}
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/io/scene.hpp"
#include "core/io/scene_error.hpp"
#include "core/io/scene_override.hpp"

namespace fp {

/// Largest scene file read (yaml-cpp needs about 0.7 s and 160 MB per MiB; geometry that big
/// belongs in a mesh file).
inline constexpr std::size_t kMaxSceneBytes = 16u << 20;  // a polygon of 3 x 10^5 vertices

/// Largest radius_pool: each placement sorts the pool (measured in experiments/extremes: 64 costs
/// 2.4x the time of 4, 1024 costs 29x).
inline constexpr std::uint64_t kMaxRadiusPool = 1024;

/// Most threads a scene may ask for (each holds a block's front and neighbour grid).
inline constexpr std::uint64_t kMaxThreads = 4096;

/// Every length of a scene (the container's extent, particle sizes) lies in [kMinLength,
/// kMaxLength], so that volumes are ordinary doubles.
inline constexpr double kMinLength = 1e-100;
inline constexpr double kMaxLength = 1e100;

/// Reads and parses `path`, changed by `overrides` (in order; Scene::overrides). Throws
/// SceneError (also when the file cannot be read, is not a regular file, or is larger than
/// kMaxSceneBytes); a problem with an override's key or value names where it was given.
Scene load_scene(const std::string& path, const std::vector<SceneOverride>& overrides = {});

/// Parses scene text; `source_name` is used in messages, stored as Scene::source_path, and
/// its folder resolves relative mesh file names.
Scene parse_scene(const std::string& text, const std::string& source_name, const std::vector<SceneOverride>& overrides = {});

}  // namespace fp
