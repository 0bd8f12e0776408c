#pragma once
// Reads a scene file (YAML) into a Scene: containers and radius distributions constructed,
// packer options, stop criteria and outputs checked. Every problem is a SceneError naming
// the file, line, column and dotted key (scene_error.hpp). Nothing is silently ignored: an
// unknown key, or a key the chosen container/distribution does not use, is an error.
// Only scene_yaml.cpp includes yaml-cpp.
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
//   particles*:
//     radius*:
//       distribution*: constant | uniform | normal | lognormal | discrete | histogram | gradation
//       constant:  value*
//       uniform:   min*, max*
//       normal:    mean*, std*, min*, max*          (truncated to [min, max])
//       lognormal: median* or mu* (= ln median), sigma* (of ln r), min*, max*
//       discrete:  values* ([[radius, count weight], ...])
//       histogram: edges* (radius bin edges), weights* (count weight per bin)
//       gradation: curve* ([[sieve DIAMETER, % passing], ...]), basis (mass | count, default mass)
//   packer:
//     method: front;  front: closest | random | fifo;  candidate: closest | first;
//     pair_order: nearest | index;  contact_bodies: front | all;  probe_smallest: auto | bool;  walls: bool;  radius_pool: integer >= 1;
//     contact_tolerance: in (0, 1e-3);  grid_cell_factor: >= 1;  hierarchical_grid_ratio: > 1;
//     seed_point: [x, y(, z)] inside the container
//   stop:
//     particles: integer > 0 (1e6 accepted);  volume_fraction: in (0, 1);  time: seconds > 0
//   output: list of {format: vtu | yade | lammps | csv | json (default: from the path's
//           extension), path*: relative to the working directory}
#include <string>

#include "core/io/scene.hpp"
#include "core/io/scene_error.hpp"

namespace fp {

/// Reads and parses `path`. Throws SceneError (also when the file cannot be read).
Scene load_scene(const std::string& path);

/// Parses scene text; `source_name` is used in messages, stored as Scene::source_path, and
/// its folder resolves relative mesh file names.
Scene parse_scene(const std::string& text, const std::string& source_name);

}  // namespace fp
