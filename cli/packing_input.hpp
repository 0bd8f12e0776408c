#pragma once
// What `validate` and `analyze` read: a packing file and, optionally, the scene it fills.
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/packing.hpp"
#include "core/io/output_paths.hpp"
#include "core/io/scene.hpp"
#include "core/io/scene_override.hpp"
#include "shapes/particle.hpp"

namespace fp {

struct PackingInput {
  std::optional<Scene> scene;  ///< when a scene path was given
  int dimension = 3;           ///< of the packing (and of the scene)
  Packing<2> packing2;         ///< set when dimension == 2 (spheres, disks)
  Packing<3> packing3;         ///< set when dimension == 3
  bool shapes = false;         ///< a scene of shapes: the packing is in shapes2 / shapes3
  ShapePacking<2> shapes2;
  ShapePacking<3> shapes3;
};

/// Loads the scene (if scene_path is not empty) and the packing (format: explicit, else from the
/// extension), and checks that their dimensions agree. With a scene of shapes and `shapes_too`,
/// the packing is read from its json output (the format that carries the shapes); without
/// `shapes_too` a scene of shapes is refused. Throws std::runtime_error naming the file (and
/// line, key) on any bad input: the commands report it with exit code 2. `overrides` change the
/// scene as it is read (--set).
PackingInput read_packing_input(const std::string& packing_path, const std::string& format, const std::string& scene_path,
                                bool shapes_too = false, const std::vector<SceneOverride>& overrides = {});

/// The files `scene` was read from (itself, a mesh), for check_output_paths: no output may
/// replace them. `named_by` says how the scene was given ("argument SCENE", "option --scene").
std::vector<NamedPath> scene_reads(const Scene& scene, const std::string& named_by);

}  // namespace fp
