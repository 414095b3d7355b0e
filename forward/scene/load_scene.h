// Scene files (TOML) -> Scene. Every key is declared once (scene_keys.cc) with default, unit,
// range and documentation; unknown keys, wrong types and out-of-range values raise InputError
// naming file, line and key.
#pragma once

#include <toml++/toml.h>

#include <string>

#include "scene/scene.h"

namespace vs {

// Reads and validates a scene file. Relative paths inside the scene (table files) are resolved
// against the scene file's folder.
Scene load_scene(const std::string& path);

// Validates an already parsed TOML table (used by the calibration toolkit, which edits a copy of
// the table in memory and rebuilds the Scene without touching the disk). `source` names the
// origin in error messages; `base_dir` resolves relative file references.
Scene scene_from_table(const toml::table& table, const std::string& source,
                       const std::string& base_dir);

// Annotated TOML with every key, its default, unit, range and documentation.
std::string scene_defaults_toml();

// Markdown reference of every key (docs/scene-reference.md is generated from this).
std::string scene_reference_markdown();

}  // namespace vs
