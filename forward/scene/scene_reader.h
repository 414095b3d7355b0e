// The section-by-section walk over a parsed scene: every key is looked up in the registry
// (scene_keys.h), checked for its section's variant, type and range, and stored in a Scene.
// Consistency between sections is checked afterwards (scene_checks.h).
#pragma once

#include <toml++/toml.h>

#include <string>

#include "scene/scene.h"
#include "scene/scene_diagnostics.h"

namespace vs {

// Reads `root` into a Scene (source left empty). Records where each key was written in
// `where`. Relative table files resolve against `base_dir`. Throws InputError.
Scene read_scene_sections(const toml::table& root, const std::string& base_dir,
                          SceneSourceMap& where);

}  // namespace vs
