// The registry of every scene key: section, name, type, unit, range, documentation, the variants
// it applies to, and where its value lives in Scene. Validation (load_scene.cc), the annotated
// defaults file and the markdown reference (scene_docs.cc) and dotted addresses (scene_table.cc)
// all read this one list, so a key is declared exactly once. Defaults are not repeated here: they
// are read from a default-constructed Scene / ToolSpec (the in-class defaults of scene.h).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "scene/scene.h"

namespace vs {

// Largest finite Coulomb coefficient a scene accepts (larger: use "sticking"). Sheet forming sees
// 0-0.3 with lubricant and up to ~0.6-0.8 dry; continuum codes stand in for a no-slip contact
// with mu = 3-10 (the CalculiX references of experiments/08 and 11), and the shell must run the
// same problem to be compared with them (ex4b, 8 divisions, mu = 10: 11 Newton iterations a step,
// no cut-back). 1e6 collapses the steps (key_value.cc); 10 is the largest value measured to run.
inline constexpr double kMaxCoulombCoefficient = 10.0;

enum class KeyType {
  kFloat,  // TOML float or integer (converted)
  kInt,    // TOML integer only
  kBool,
  kString,
  kEnum,         // string from KeySpec::choices
  kFloatArray,   // [x, ...]; KeySpec::range applies to each element
  kPairArray,    // [[x, y], ...] (the inline hardening table)
  kStringArray,  // ["a", ...] (calibration: model_form.drop_data)
  kTable,        // a table of keys the owner reads itself (calibration: [forward.set], columns)
};

// Interval of allowed values; an infinite bound is written inf and is only reachable if closed.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_closed = false;
  bool hi_closed = false;

  bool contains(double x) const;
  std::string text() const;  // "(0, inf)", "[1e-12, 0.1]"
};

Range open_above(double lo);              // (lo, inf)
Range at_least(double lo);                // [lo, inf)
Range closed(double lo, double hi);       // [lo, hi]
Range open_closed(double lo, double hi);  // (lo, hi]
Range open(double lo, double hi);         // (lo, hi)

// Accessors into the Scene under construction. The ToolSpec argument is the tool being read for
// [[tool]] keys and is ignored elsewhere. Exactly one accessor matching the key's type is set,
// except for keys the loader handles itself (material.hardening.table / table_file).
struct KeyField {
  double& (*number)(Scene&, ToolSpec&) = nullptr;
  int& (*integer)(Scene&, ToolSpec&) = nullptr;
  bool& (*flag)(Scene&, ToolSpec&) = nullptr;
  std::string& (*text)(Scene&, ToolSpec&) = nullptr;
  std::vector<double>& (*numbers)(Scene&, ToolSpec&) = nullptr;
  int (*get_choice)(Scene&, ToolSpec&) = nullptr;  // index into KeySpec::choices
  void (*set_choice)(Scene&, ToolSpec&, int) = nullptr;
};

struct KeySpec {
  std::string_view section;  // "" (top level), "blank", "material.hardening", "tool", ...
  std::string_view name;
  KeyType type = KeyType::kFloat;
  std::string_view unit;      // "" for dimensionless
  Range range;                // kFloat, kInt, kFloatArray
  std::size_t max_items = 0;  // kFloatArray: most values allowed; 0 = no limit
  // Why the range stops where it does, when that is a resource bound rather than physics;
  // appended to out-of-range messages ("... is out of range [4, 2000]: <bound_reason>").
  std::string_view bound_reason;
  bool bound_reason_below = false;        // the reason is for the lower bound (else the upper one)
  std::vector<std::string_view> choices;  // kEnum: allowed strings; kInt: allowed values if set
  // Variants of the section's selector (hardening law, rate law, tool kind) this key is used by;
  // empty = every variant.
  std::vector<std::string_view> applies_to;
  bool required = false;        // no default: must be given (where it applies)
  bool sticking_alias = false;  // also accepts the string "sticking" (= +inf); finite values
                                // at most kMaxCoulombCoefficient
  bool identifier = false;      // string restricted to [A-Za-z0-9_]+
  // The only model geometry ("axisymmetric", "shell3d") that uses the key; empty = every one.
  // Setting the key in a scene of another geometry is an error (load_scene.cc).
  std::string_view geometry;
  std::string_view doc;
  KeyField field;
  // Registries not backed by Scene (the calibration config, inverse/calibration_keys.cc): the
  // default as TOML text, computed from the owner's default-constructed options ("" = none).
  std::string (*default_text)() = nullptr;

  std::string address_in_section() const;  // "blank.radius_mm", "tool.friction", "title"
};

// A section whose keys depend on one of its own enum keys (the selector).
struct VariantSelector {
  std::string_view section;  // "material.hardening"
  std::string_view key;      // "law"
  std::string_view label;    // "hardening law", used in "key 'K_MPa' is not used by ..."
};

// Every key, in documentation order (sections in file order, keys in section order).
const std::vector<KeySpec>& scene_keys();

// Sections in documentation order, with a one-line description each.
struct SectionSpec {
  std::string_view name;    // "" for the top level
  std::string_view header;  // "[blank]", "[[tool]]", "(top level)"
  std::string_view doc;
};
const std::vector<SectionSpec>& scene_sections();

// The key `name` of `section`, or nullptr.
const KeySpec* find_key(std::string_view section, std::string_view name);

// Selector of `section`, or nullptr if the section has no variants.
const VariantSelector* find_selector(std::string_view section);

// Whether `key` is used when its section's selector has the value `variant`.
bool key_applies(const KeySpec& key, std::string_view variant);

// The value of a key in a scene: double (kFloat), int (kInt), bool, std::string (kString,
// kEnum), a float array, a pair array.
using KeyPairs = std::vector<std::array<double, 2>>;
using KeyValue = std::variant<double, int, bool, std::string, std::vector<double>, KeyPairs>;

// `key`'s value in `scene` (in `tool` for [[tool]] keys) read through its accessor; false if it
// has none (the keys the loader reads itself: tables, table files).
bool read_key_value(const KeySpec& key, Scene& scene, ToolSpec& tool, KeyValue* value);

// A value as TOML text: floats in shortest round-trip form ("500.0", "1e-06", "inf"), strings
// quoted and escaped, arrays in brackets.
std::string key_value_toml(const KeyValue& value);

// The default value as TOML text ("0.85", "\"pinned\"", "[]"), or "" if the key is required or
// has no value by default (table, table_file).
std::string default_toml_text(const KeySpec& key);

// Numeric default of a kFloat / kInt key (from a default-constructed Scene / ToolSpec).
double default_number(const KeySpec& key);

// TOML text of a double: always shows it is a float ("500.0", "1e-06", "inf").
std::string float_toml_text(double x);

// The Markdown table (key, type, default, unit, allowed, applies to, description) of the keys of
// `section` in `keys`, as in docs/scene-reference.md; also used for the calibration reference.
std::string key_table_markdown(const std::vector<KeySpec>& keys, std::string_view section);

}  // namespace vs
