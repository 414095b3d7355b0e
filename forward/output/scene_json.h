// The scene as run (scene/scene_echo.h: every key that applies to it, defaults included) as JSON
// for run.json, so a run folder says exactly what was simulated: nested by section
// ("material": {"hardening": {...}}), the tools as an array of objects, key names as in a scene
// file (they carry their units: radius_mm, K_MPa), enums as their scene-file words, an infinite
// friction coefficient as "sticking".
#pragma once

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace vs {

nlohmann::ordered_json scene_to_json(const Scene& scene);

}  // namespace vs
