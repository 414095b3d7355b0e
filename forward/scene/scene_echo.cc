#include "scene/scene_echo.h"

#include <fmt/format.h>

#include <cstddef>
#include <filesystem>
#include <limits>
#include <string_view>
#include <variant>

namespace vs {

namespace {

// The variant of `section` in this scene (its selector's current choice), or "" if the section
// has none. `tool`: the tool being echoed, for [[tool]] keys.
std::string_view variant_of(std::string_view section, Scene& scene, ToolSpec& tool) {
  const VariantSelector* selector = find_selector(section);
  if (selector == nullptr) return {};
  const KeySpec* key = find_key(section, selector->key);
  const int index = key->field.get_choice(scene, tool);
  return key->choices.at(static_cast<std::size_t>(index));
}

KeyPairs pairs(const std::vector<double>& a, const std::vector<double>& b) {
  KeyPairs out;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) out.push_back({a[i], b[i]});
  return out;
}

// The value of `key` as the run used it; false if the key has no value to echo.
bool read_value(const KeySpec& key, Scene& scene, ToolSpec& tool, KeyValue* value) {
  const std::string address = key.address_in_section();
  // Held in another form than the key's accessor (the loader reads them itself).
  if (address == "material.hardening.table") {
    *value =
        pairs(scene.material.hardening.table_strain, scene.material.hardening.table_stress_MPa);
    return true;
  }
  if (address == "forming_limit.points") {
    *value = pairs(scene.forming_limit.table_minor, scene.forming_limit.table_major);
    return true;
  }
  // The normal-anisotropy R is refused beside a planar anisotropy model (scene_reader.cc).
  if (address == "material.r_value" && scene.material.anisotropy.planar()) return false;
  if (address == "output.measured_cup_profile") {
    const std::string& path = scene.output.measured_cup_profile;
    *value = path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
    return true;
  }
  if (!read_key_value(key, scene, tool, value)) return false;
  // A number a scene file cannot give stands for "not given" (a holder's force_N when it has a
  // gap, and the other way round; blank.radial_divisions 0); an infinite friction is "sticking".
  if (const double* x = std::get_if<double>(value)) {
    if (key.sticking_alias && *x == std::numeric_limits<double>::infinity()) {
      *value = std::string("sticking");
      return true;
    }
    return key.sticking_alias || key.range.contains(*x);
  }
  if (const int* n = std::get_if<int>(value)) return key.range.contains(*n);
  return true;
}

}  // namespace

bool echo_skips(const KeySpec& key) {
  return key.address_in_section() == "material.hardening.table_file";
}

std::vector<EchoEntry> echo_scene(const Scene& original) {
  Scene scene = original;  // the accessors take mutable references
  const std::string_view geometry =
      find_key("", "geometry")->choices.at(static_cast<std::size_t>(scene.geometry));
  std::vector<EchoEntry> out;
  auto add = [&](const KeySpec& key, ToolSpec& tool, int tool_index) {
    if (echo_skips(key)) return;
    if (!key.geometry.empty() && key.geometry != geometry) return;
    if (!key_applies(key, variant_of(key.section, scene, tool))) return;
    EchoEntry e{&key, tool_index, {}};
    if (read_value(key, scene, tool, &e.value)) out.push_back(std::move(e));
  };
  const std::vector<KeySpec>& keys = scene_keys();
  ToolSpec no_tool;
  for (std::size_t k = 0; k < keys.size();) {
    if (keys[k].section != "tool") {
      add(keys[k], no_tool, -1);
      ++k;
      continue;
    }
    // The [[tool]] keys (consecutive in the registry), tool by tool.
    std::size_t end = k;
    while (end < keys.size() && keys[end].section == "tool") ++end;
    for (std::size_t t = 0; t < scene.tools.size(); ++t) {
      for (std::size_t j = k; j < end; ++j) add(keys[j], scene.tools[t], static_cast<int>(t));
    }
    k = end;
  }
  return out;
}

std::string scene_toml(const Scene& scene) {
  std::string source = scene.source.empty() ? "(a scene built in code)" : scene.source;
  for (char& c : source) {
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';  // one comment line
  }
  std::string out = fmt::format(
      "# The scene as run: every key that applies to it, with the value used (defaults\n"
      "# included). Read from {}. Units: mm, N, s, MPa.\n"
      "# Run it again with `vshell run scene.toml -o FOLDER` (without -o the run replaces\n"
      "# output.directory).\n",
      source);
  std::string_view section = "";
  int tool = -1;
  for (const EchoEntry& e : echo_scene(scene)) {
    const KeySpec& key = *e.key;
    if (key.section == "tool" && e.tool != tool) {
      out += "\n[[tool]]\n";
      tool = e.tool;
      section = key.section;
    } else if (key.section != section) {
      out += fmt::format("\n[{}]\n", key.section);
      section = key.section;
    }
    out += fmt::format("{} = {}\n", key.name, key_value_toml(e.value));
  }
  return out;
}

}  // namespace vs
