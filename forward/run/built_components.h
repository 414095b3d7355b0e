// What a run built for its scene, in words, for RunResult::built and run.json: the contact terms
// each tool brings (none, regularised Coulomb, sticking; the blank holder's load), shared by
// both geometries' drivers, which add their model and solver lines.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace vs {

// One line per tool, e.g. "tool 'punch' (hemispherical_punch): contact, regularised Coulomb
// friction 0.1" or "tool 'holder' (blank_holder): fixed gap 1.04 mm, frictionless".
std::vector<std::string> tool_components(const Scene& scene);

}  // namespace vs
