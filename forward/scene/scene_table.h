// Numbers in a parsed scene addressed by a dotted path, for command-line overrides
// (vshell run --set tool.punch.friction=0.2) and for calibration parameters.
//
// Address grammar (every segment is a scene key; tools are addressed by their name):
//   blank.thickness_mm
//   material.r_value
//   material.hardening.K_MPa
//   material.rate.m
//   tool.<name>.friction        e.g. tool.punch.friction, tool.die.friction
//   process.punch_travel_mm
//   numerics.tolerance
// Only keys declared in the scene reference are addressable; anything else is an InputError
// naming the address. Setting a key that is absent from the file inserts it (the scene's default
// is then overridden). Integers (blank.elements, ...) accept whole numbers only.
#pragma once

#include <toml++/toml.h>

#include <string>

#include "scene/scene_keys.h"

namespace vs {

// Parses a scene file into a table without validating it (syntax errors -> InputError
// with file:line:column).
toml::table read_scene_table(const std::string& path);

// The declared key `address` resolves to (throws InputError for an unknown address).
const KeySpec& scene_address_key(const toml::table& table, const std::string& address);

// The numeric value at `address`, or the declared default when the file does not set it.
double get_scene_number(const toml::table& table, const std::string& address);

// Sets the numeric value at `address` (+infinity allowed for friction = sticking).
void set_scene_number(toml::table& table, const std::string& address, double value);

// Sets any value from its text form as typed on a command line: numbers, true/false, "inf",
// strings; the value is checked later by scene_from_table.
void set_scene_value_from_text(toml::table& table, const std::string& address,
                               const std::string& text);

}  // namespace vs
