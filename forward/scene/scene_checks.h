// Consistency rules that involve more than one key (tool set, clearances, output stages). Run on
// the finished Scene; messages point at the offending key through the SceneSourceMap.
#pragma once

#include <string_view>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_diagnostics.h"

namespace vs {

// Throws InputError naming file, line and key for the first rule the scene breaks.
void check_scene_consistency(const Scene& scene, const SceneSourceMap& where);

// One sentence per rule, for the reference documentation.
const std::vector<std::string_view>& scene_consistency_rules();

}  // namespace vs
