// Consistency rules that involve more than one key (tool set, clearances, output stages). Run on
// the finished Scene; messages point at the offending key through the SceneSourceMap.
#pragma once

#include <string_view>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_diagnostics.h"

namespace vs {

// Bounds on the size of a run (check_scene_consistency): steps of the travel grid, and steps x
// elements. Measured on a 2-core machine: ~10 us per axisymmetric element-step (plus 150 bytes
// of history each with output.history), 0.15-0.35 ms per shell3d element-step (2-core AMD EPYC,
// 27 Nov 2026; ~2 ms with the explicit update of the first sessions).
inline constexpr double kMaxRunSteps = 1e6;
inline constexpr double kMaxElementStepsAxisym = 1e8;
inline constexpr double kMaxElementSteps3d = 5e6;

// Throws InputError naming file, line and key for the first rule the scene breaks.
void check_scene_consistency(const Scene& scene, const SceneSourceMap& where);

// One sentence per rule, for the reference documentation.
const std::vector<std::string_view>& scene_consistency_rules();

}  // namespace vs
