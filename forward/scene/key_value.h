// One scene value: checks a TOML node against its KeySpec (type, range, allowed values) and
// stores it in the Scene. Messages name the key by its address and point at the value.
#pragma once

#include <toml++/toml.h>

#include <string>

#include "scene/scene.h"
#include "scene/scene_diagnostics.h"
#include "scene/scene_keys.h"

namespace vs {

// Checks `node` as the value of `key` and stores it in `scene` (or in `tool` for [[tool]] keys).
// `address` names the key in messages ("blank.thickness_mm", "tool.punch.friction"). Array
// elements are recorded in `where` as "address[i]". Keys without a field are not stored.
void store_key_value(const KeySpec& key, const toml::node& node, const std::string& address,
                     SceneSourceMap& where, Scene& scene, ToolSpec& tool);

// The checked string of an enum key (used to learn a section's variant before its other keys).
std::string read_choice(const KeySpec& key, const toml::node& node, const std::string& address,
                        const std::string& source);

// The checked string of a string key.
std::string read_string(const KeySpec& key, const toml::node& node, const std::string& address,
                        const std::string& source);

// A number for a float key: integers are converted, ranges are not checked.
double read_number(const toml::node& node, const std::string& address, const std::string& source);

}  // namespace vs
