#pragma once
// A change to a scene before it is read: `frontpack pack SCENE --set KEY=VALUE`, or a study's
// parameter (cli/study_*). The value, YAML text, replaces the one at the dotted key or adds it;
// a problem with it is reported where it was given (the --set argument, the study file's line).
#include <string>
#include <vector>

#include "core/io/scene.hpp"

namespace fp {

struct SceneOverride {
  std::string key;    ///< dotted, with list indices: "packer.front", "particles[0].aspect_ratio"
  std::string value;  ///< YAML: 0.5, ellipse, [1, 2], {type: box, min: [0, 0], max: [1, 1]}
  SourceSpot origin;  ///< where it was given; file "--set KEY=VALUE" on the command line
};

/// What a dotted key looks like, for messages about one that does not.
inline constexpr const char* kSceneKeyForm =
    "dotted names with list indices, e.g. container.max or particles[0].aspect_ratio";

/// Whether `key` has that form (whether the scene has it is known only when it is read).
bool is_scene_key(const std::string& key);

/// "KEY=VALUE" of `--set`. Throws std::invalid_argument naming the argument (no '=', an empty or
/// malformed key; the value is checked when the scene is read).
SceneOverride scene_override_argument(const std::string& key_equals_value);

/// "KEY=VALUE, KEY=VALUE" for messages and the run record.
std::string describe_overrides(const std::vector<SceneOverride>& overrides);

/// Whether the value at dotted key `key` was set by the override of `override_key` (the key
/// itself, or inside it: "container" covers "container.max" and "container.max[0]").
bool override_covers(const std::string& override_key, const std::string& key);

}  // namespace fp
