// The one declaration of every calibration-config key (type, unit, range, default, doc), with the
// scene-key mechanism (scene/scene_keys.h): the config reader (calibration_config.cc) checks
// types, ranges and choices against it and rejects undeclared keys with a did-you-mean, and
// docs/calibration-reference.md is generated from it (calibration_reference_markdown()).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_keys.h"

namespace vs {

// Every key, sections in file order: "" (top level), "scene", "parameter", "data",
// "optimizer", "uncertainty", "model_form", "forward", "output".
const std::vector<KeySpec>& calibration_keys();

// Sections in documentation order ("[[parameter]]", ...), with a one-line description each.
const std::vector<SectionSpec>& calibration_sections();

// The key `name` of `section`, or nullptr.
const KeySpec* find_calibration_key(std::string_view section, std::string_view name);

// Markdown reference of the calibration config (docs/calibration-reference.md).
std::string calibration_reference_markdown();

}  // namespace vs
