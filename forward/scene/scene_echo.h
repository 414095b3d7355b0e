// The scene as run, read back key by key through the registry (scene_keys.h): every key that
// applies to the scene (its geometry, the variant of each law, the kind of each tool) with the
// value the solver used, defaults and geometry defaults included. A key the registry gains is
// echoed without a change here (a test checks that none is left out). Written as TOML
// (scene_toml: scene.toml in a run folder, which `vshell run` runs again to the same bits) and,
// by output/scene_json.h, as run.json's scene record.
//
// A number outside its key's range (which no scene file can give) means "not given" and is left
// out: a holder's force_N when it has a gap, blank.radial_divisions 0 (as many as divisions).
// Values that a scene file gives in another form are echoed resolved: a hardening table_file as
// the inline table it was read into, a measured cup profile as an absolute path, an infinite
// friction coefficient as "sticking".
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_keys.h"

namespace vs {

struct EchoEntry {
  const KeySpec* key = nullptr;
  int tool = -1;   // [[tool]] keys: index into Scene::tools
  KeyValue value;  // (an infinite friction as the string "sticking")
};

// Every key that applies to `scene`, in registry order (the tool keys tool by tool).
std::vector<EchoEntry> echo_scene(const Scene& scene);

// Registry keys that echo_scene never writes, because the scene holds them in another form
// (hardening.table_file: the table it was read into is echoed as hardening.table).
bool echo_skips(const KeySpec& key);

// echo_scene as a scene file.
std::string scene_toml(const Scene& scene);

}  // namespace vs
