// The resolved Scene (every field, defaults included) as JSON for run.json, so a run folder says
// exactly what was simulated. Keys are the Scene field names, which carry their units
// (radius_mm, K_MPa...); enums are written as lower_snake_case words; an infinite friction
// coefficient is written as the string "sticking" (JSON has no infinity).
#pragma once

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace vs {

nlohmann::ordered_json scene_to_json(const Scene& scene);

}  // namespace vs
