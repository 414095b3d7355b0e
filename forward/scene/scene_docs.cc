// The two human-readable views of the key registry: the annotated defaults file
// (vshell print-defaults) and the markdown reference (docs/scene-reference.md).
#include <fmt/format.h>

#include <string>

#include "scene/load_scene.h"
#include "scene/scene_checks.h"
#include "scene/scene_keys.h"

namespace vs {

namespace {

std::string type_text(const KeySpec& key) {
  switch (key.type) {
    case KeyType::kFloat:
      return "float";
    case KeyType::kInt:
      return "integer";
    case KeyType::kBool:
      return "boolean";
    case KeyType::kString:
      return "string";
    case KeyType::kEnum:
      return "string (choice)";
    case KeyType::kFloatArray:
      return "array of float";
    case KeyType::kPairArray:
      return "array of [float, float]";
    case KeyType::kStringArray:
      return "array of string";
    case KeyType::kTable:
      return "table";
  }
  return "";
}

// Allowed values: the range for numbers, the choices for enums.
std::string allowed_text(const KeySpec& key, bool markdown) {
  const std::string quote = markdown ? "`" : "";
  if (key.type == KeyType::kEnum || !key.choices.empty()) {
    std::string out;
    for (std::string_view c : key.choices) {
      if (!out.empty()) out += markdown ? ", " : " | ";
      out += key.type == KeyType::kEnum ? fmt::format("{}\"{}\"{}", quote, c, quote)
                                        : fmt::format("{}{}{}", quote, c, quote);
    }
    return out;
  }
  if (key.type == KeyType::kFloat || key.type == KeyType::kInt ||
      key.type == KeyType::kFloatArray) {
    std::string out = key.range.text();
    if (key.sticking_alias) out += markdown ? " or `\"sticking\"`" : " or \"sticking\"";
    if (key.max_items > 0) out += fmt::format(", at most {} values", key.max_items);
    return out;
  }
  if (key.identifier) return "[A-Za-z0-9_]+";
  return "";
}

std::string applies_text(const KeySpec& key) {
  const std::string geometry = key.geometry.empty() ? "" : fmt::format("geometry {}", key.geometry);
  if (key.applies_to.empty()) return geometry;
  std::string out;
  for (std::string_view v : key.applies_to) out += (out.empty() ? "" : ", ") + std::string(v);
  const VariantSelector* selector = find_selector(key.section);
  if (selector != nullptr) out = fmt::format("{} {}", selector->label, out);
  return geometry.empty() ? out : geometry + "; " + out;
}

// A default given in words ("(implicit for axisymmetric, ...)", "(the scene's value)"), not as
// TOML.
bool default_in_words(const std::string& text) { return !text.empty() && text.front() == '('; }

// Whether the key is used by the section's default variant (so its default line is active).
bool used_by_default_variant(const KeySpec& key) {
  if (!key.geometry.empty() &&
      default_toml_text(*find_key("", "geometry")) != fmt::format("\"{}\"", key.geometry)) {
    return false;  // used only by another geometry than the default one
  }
  const VariantSelector* selector = find_selector(key.section);
  if (selector == nullptr || key.applies_to.empty()) return true;
  const std::string text = default_toml_text(*find_key(key.section, selector->key));
  if (text.size() < 2) return false;
  return key_applies(key, std::string_view(text).substr(1, text.size() - 2));
}

std::string escape_cell(std::string_view text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

void append_defaults_key(std::string& out, const KeySpec& key, bool whole_section_commented) {
  std::string notes;
  auto note = [&notes](const std::string& s) {
    if (!s.empty()) notes += (notes.empty() ? "" : "; ") + s;
  };
  note(key.unit.empty() ? "" : fmt::format("unit {}", key.unit));
  const std::string allowed = allowed_text(key, false);
  note(allowed.empty() ? "" : fmt::format("allowed {}", allowed));
  const std::string applies = applies_text(key);
  note(applies.empty() ? "" : "only for " + applies);
  note(key.required ? "required" : "");
  out += fmt::format("# {}\n", key.doc);
  if (!notes.empty()) out += fmt::format("# ({})\n", notes);
  const std::string value = default_toml_text(key);
  // A default in words is not TOML: shown commented out.
  const bool active = !whole_section_commented && !value.empty() && !default_in_words(value) &&
                      used_by_default_variant(key);
  const std::string shown = !value.empty() ? value : key.required ? "<required>" : "<none>";
  out += fmt::format("{}{} = {}\n\n", active ? "" : "# ", key.name, shown);
}

void append_markdown_row(std::string& out, const KeySpec& key) {
  std::string default_text = default_toml_text(key);
  if (key.required) {
    default_text = "required";
  } else if (default_text.empty()) {
    default_text = "none";
  } else if (!default_in_words(default_text)) {
    default_text = fmt::format("`{}`", default_text);
  }
  out += fmt::format("| `{}` | {} | {} | {} | {} | {} | {} |\n", key.name, type_text(key),
                     escape_cell(default_text), key.unit.empty() ? "-" : std::string(key.unit),
                     escape_cell(allowed_text(key, true)),
                     applies_text(key).empty() ? "all" : escape_cell(applies_text(key)),
                     escape_cell(key.doc));
}

}  // namespace

std::string key_table_markdown(const std::vector<KeySpec>& keys, std::string_view section) {
  std::string out =
      "| key | type | default | unit | allowed | applies to | description |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const KeySpec& key : keys) {
    if (key.section == section) append_markdown_row(out, key);
  }
  return out;
}

std::string scene_defaults_toml() {
  std::string out =
      "# Viscous shell scene file: every key with its default, unit, allowed values and\n"
      "# documentation (generated from the key registry, forward/scene/scene_keys.cc).\n"
      "# Units: mm, N, s, MPa. Keys used only by another variant (hardening law, rate law,\n"
      "# tool kind) are commented out; setting a key the chosen variant does not use is an "
      "error.\n"
      "# There are no tools by default: add one [[tool]] table per tool (exactly one punch).\n\n";
  for (const SectionSpec& section : scene_sections()) {
    const bool is_tool = section.name == "tool";
    if (!section.name.empty()) {
      out += fmt::format("# {}\n{}{}\n\n", section.doc, is_tool ? "# " : "", section.header);
    }
    for (const KeySpec& key : scene_keys()) {
      if (key.section == section.name) append_defaults_key(out, key, is_tool);
    }
  }
  return out;
}

std::string scene_reference_markdown() {
  std::string out =
      "<!-- Generated by scene_reference_markdown() (forward/scene/scene_docs.cc) from the key\n"
      "     registry forward/scene/scene_keys.cc. Do not edit by hand; regenerate with\n"
      "     build-scene/tests/vs_scene_tests --gtest_also_run_disabled_tests "
      "--gtest_filter='*RegenerateReference*' -->\n\n"
      "# Scene file reference\n\n"
      "A scene is a TOML file describing one forming simulation, axisymmetric (`geometry = "
      "\"axisymmetric\"`, the default) or 3D (`geometry = \"shell3d\"`). Every key below "
      "has a type, a default (or is required), a unit and an allowed range. Unknown keys, wrong "
      "types, out-of-range values, keys that the chosen variant does not use (for example "
      "`K_MPa` with hardening law `voce`) and keys of the other geometry are errors reported as "
      "one line `FILE:LINE:COL: message`. Integers are accepted where floats are expected; "
      "floats are not accepted for integers. `vshell print-defaults` prints an annotated file "
      "with every default.\n\n"
      "## Units\n\n"
      "One consistent system everywhere: length in mm, force in N, time in s, stress in MPa "
      "(= N/mm^2). Strains are true (logarithmic) strains, dimensionless. Key names carry their "
      "unit (`radius_mm`, `force_N`, `gamma_per_s`); keys without a suffix are dimensionless.\n\n"
      "## Coordinates and tools\n\n"
      "- z is the punch axis and points up; the sheet mid-surface starts flat at z = 0. "
      "Axisymmetric scenes model a meridian: the model is axisymmetric about the z axis, r is "
      "the radius, and the sheet spans 0 <= r <= blank `radius_mm`. 3D scenes: see \"3D scenes\" "
      "below.\n"
      "- Every tool is a rigid surface of revolution about the z axis, in both geometries (in 3D "
      "the profiles below are revolved about z).\n"
      "- The punch is below the sheet and moves in +z by `process.punch_travel_mm`. A "
      "`hemispherical_punch` is a sphere of radius `radius_mm` on the axis; a `flat_punch` has "
      "outer radius `radius_mm`, its flat face ending where the nose arc of radius "
      "`profile_radius_mm` (centred at r = radius_mm - profile_radius_mm) begins.\n"
      "- The `die` is fixed above the sheet. `radius_mm` is the opening radius (innermost "
      "radius of the die); the shoulder arc of radius `profile_radius_mm` is centred at "
      "r = radius_mm + profile_radius_mm, where the flat die face begins.\n"
      "- The `blank_holder` sits below the flange and presses it up against the die face with "
      "the total force `force_N` on the whole blank (360 degrees; in a 3D quarter model the "
      "quarter carries a quarter of it).\n"
      "- `friction` is a Coulomb coefficient between that tool and the sheet; `inf` or "
      "`\"sticking\"` means no slip.\n"
      "- Forces reported (punch force in `load_travel.csv`, the summary and `run.json`) are "
      "those on the whole blank, in both geometries and for quarter and full 3D blanks alike.\n\n"
      "## 3D scenes (geometry = \"shell3d\")\n\n"
      "### Coordinates\n\n"
      "- x and y span the initial sheet plane z = 0, z points up along the punch axis, which "
      "passes through the blank centre x = y = 0 (right-handed; lengths in mm). The punch moves "
      "in +z by `process.punch_travel_mm` and stretches the sheet up, towards the die; r = "
      "sqrt(x^2 + y^2) is the distance from the punch axis (the `r0_mm`, `r_mm` columns of the "
      "outputs).\n"
      "- `blank.shape = \"circle\"`: the disc x^2 + y^2 <= radius_mm^2. `\"square\"`: "
      "|x| <= radius_mm and |y| <= radius_mm (half side `radius_mm`, sides parallel to the x and "
      "y axes, corners on the diagonals).\n"
      "- The blank is meshed with 9-node shells (`blank.divisions`, `numerics.element_rule`); "
      "`blank.elements` and `blank.grading` are axisymmetric keys and errors here.\n\n"
      "### Quarter model and symmetry planes\n\n"
      "`blank.symmetry = \"quarter\"` (the default) meshes the part x >= 0, y >= 0. The planes "
      "x = 0 and y = 0 are symmetry planes: a node on one of them has no velocity normal to the "
      "plane, and its director does not rotate out of the plane; the centre node (on both "
      "planes) moves only along z and its director stays vertical. This is exact because every "
      "tool is a surface of revolution and both blank outlines are mirror-symmetric about x = 0 "
      "and y = 0. Forces are reported for the whole blank (four times the quarter's), and a "
      "blank holder's `force_N` is the whole blank's (the quarter carries a quarter of it). "
      "Strain profiles are written along the lines `x` (y = 0), `y` (x = 0) and `diagonal` "
      "(x = y), from the centre outwards.\n\n"
      "### Full blank\n\n"
      "`blank.symmetry = \"full\"` meshes the whole blank without symmetry planes: the quarter "
      "mesh mirrored onto the four quadrants (four times the elements), so a full and a quarter "
      "run of one scene discretise the same sheet. A pinned or clamped edge holds the sheet in "
      "place; with a free edge, nothing but contact and friction would fix the in-plane "
      "translation and the rotation about z, so the centre node keeps zero in-plane velocity and "
      "the outermost node on the positive x axis zero circumferential velocity (exact for "
      "axisymmetric tools and mirror-symmetric outlines). Forces are for the whole blank, as in "
      "the quarter model. Profiles: `x`, `y`, `diagonal` are the halves with x, y >= 0 (read "
      "like the quarter's), `x_neg`, `y_neg`, `diagonal_neg` the other halves.\n\n"
      "### Edge conditions (blank.edge)\n\n"
      "The edge is the blank's outline: the rim node of the axisymmetric meridian; in 3D every "
      "node of the circle's rim or of the square's sides (x = radius_mm or y = radius_mm in a "
      "quarter model, also x = -radius_mm and y = -radius_mm in a full one). Nodes on a symmetry "
      "plane keep their symmetry conditions as well.\n\n"
      "| `edge` | axisymmetric (rim node) | 3D (every edge node) |\n"
      "|---|---|---|\n"
      "| `\"pinned\"` | no radial and no axial velocity; the rotation is free (a hinge) | "
      "velocity zero in all three directions, so a square edge cannot slide along itself either "
      "(and a circular rim has no circumferential velocity, which the axisymmetric model has by "
      "symmetry); both director rotation rates free (a hinge); the edge nodes take no part in "
      "contact |\n"
      "| `\"clamped\"` | as pinned, and no rotation | as pinned, and both director rotation rates "
      "zero: the director keeps its initial vertical direction |\n"
      "| `\"free\"` | nothing prescribed: the rim draws in; needs a die | nothing prescribed: the "
      "edge draws in and its nodes touch tools like any other; needs a die; a full blank fixes "
      "its rigid-body modes as above |\n\n"
      "## Keys\n\n";
  for (const SectionSpec& section : scene_sections()) {
    out += fmt::format("### {}\n\n{}\n\n", section.header, section.doc);
    if (const VariantSelector* selector = find_selector(section.name)) {
      out += fmt::format(
          "The `{}` key selects the {}; a key whose `applies to` column does not list it is an "
          "error.\n\n",
          selector->key, selector->label);
    }
    out += key_table_markdown(scene_keys(), section.name) + "\n";
  }
  out +=
      "## Hardening table files\n\n"
      "`material.hardening.table_file` names a CSV file, relative to the scene file. Lines "
      "starting with `#` and blank lines are ignored; the first other line is the header "
      "`plastic_strain,stress_MPa`; each further line is one `strain,stress` point. Strains "
      "start at 0 and increase strictly, stresses are > 0, at least 2 points. A malformed line "
      "is reported as `FILE:LINE: message`.\n\n"
      "## Elasticity\n\n"
      "The solver is rigid-(visco)plastic. `[material.elastic]` with `law = \"isotropic\"` adds "
      "elasticity as a first-order correction in both geometries "
      "(`forward/material/elastic_start.h`; measured against continuum references in "
      "experiments/08_continuum_reference): `start` makes the flow stress at accumulated strain "
      "e the secant elastic-plastic curve sigma = min(E e, sigma_y(e - sigma / E)) (monotonic, "
      "proportional loading; a point that unloads keeps its flow stress, there is no elastic "
      "unloading); `strains` adds the elastic part of the thickness strain to the strain "
      "profiles from the current in-plane stress by Hooke's law (plane stress): -nu (sigma_1 + "
      "sigma_2) / E when the shell's strains are plastic (`start = false`), the elastic volume "
      "change (1 - 2 nu) (sigma_1 + sigma_2) / E when they are total (`start = true`). The "
      "default `law = \"none\"` leaves every output unchanged.\n\n"
      "## Forming-limit curve\n\n"
      "`[forming_limit]` sets the curve drawn on the forming-limit diagram (`fld.svg`) and the "
      "margin of every element to it (`fld_points.csv`: `flc_eps_major`, `flc_margin`, "
      "`flc_zone`; 3D stages: `flc_margin`, `flc_zone`; the smallest margin in `run.json` and the "
      "printed summary). The solver never reads it. All strains are true (logarithmic) strains, "
      "as in the diagram.\n\n"
      "- `keeler-brazier` (the default): FLC0 = (23.3 + 14.13 t) n / 0.21, in % engineering major "
      "strain at plane strain (t = `blank.thickness_mm`, fitted for t <= 3 mm: a thicker blank "
      "gets a warning), after Keeler and Brazier as given by the AHSS Application Guidelines "
      "(\"Forming Limit Curves\"): a left branch of constant thinning in true strains and a right "
      "branch rising 0.6 x the engineering minor strain. With e0 = FLC0 / 100: major = ln(1 + e0) "
      "- minor for minor <= 0, major = ln(1 + e0 + 0.6 (exp(minor) - 1)) for minor >= 0. n is "
      "`material.hardening.n` (swift, hollomon) or, for voce and table flow curves, "
      "ln(sigma(0.2) / sigma(0.1)) / ln 2.\n"
      "- `table`: `points = [[minor, major], ...]`, linear between the points and constant beyond "
      "the first and last (conservative: both branches rise away from plane strain).\n"
      "- `none`: no curve, no margins.\n\n"
      "The margin of an element is the FLC's major strain at the element's minor strain minus "
      "its major strain: `failed` below 0, `marginal` from 0 to `safety_margin`, `safe` "
      "above.\n\n"
      "## Consistency rules\n\n";
  for (std::string_view rule : scene_consistency_rules()) out += fmt::format("- {}\n", rule);
  out +=
      "\n## Addresses\n\n"
      "Command-line overrides (`vshell run --set ADDRESS=VALUE`) and calibration parameters "
      "name a key by its dotted address: `section.key` (`blank.thickness_mm`, "
      "`material.hardening.K_MPa`, `numerics.tolerance`) or `tool.NAME.key` for tools "
      "(`tool.punch.friction`).\n";
  return out;
}

}  // namespace vs
