// Dotted scene addresses (scene_table.h) over an unvalidated toml::table. The address is
// resolved against the key registry, so only declared keys are reachable and defaults come from
// the same place as everywhere else.
#include "scene/scene_table.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"
#include "scene/did_you_mean.h"
#include "scene/scene_diagnostics.h"
#include "scene/scene_keys.h"
#include "scene/text_checks.h"
#include "scene/toml_guard.h"

namespace vs {

namespace {

std::vector<std::string> split(const std::string& address) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = address.find('.', start);
    parts.push_back(address.substr(start, dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

// An address resolved to its key: the tables leading to it, or the tool that holds it.
struct Target {
  const KeySpec* key = nullptr;
  std::vector<std::string> tables;  // e.g. {"material", "hardening"}; empty for tool keys
  std::string tool;                 // tool name for tool.<name>.<key>
};

std::vector<std::string> known_addresses(const toml::table& root) {
  std::vector<std::string> tools;
  if (const toml::array* array = root["tool"].as_array()) {
    for (const toml::node& t : *array) {
      if (auto name = t.as_table() ? (*t.as_table())["name"].value<std::string>() : std::nullopt) {
        tools.push_back(*name);
      }
    }
  }
  std::vector<std::string> addresses;
  for (const KeySpec& k : scene_keys()) {
    if (k.section != "tool") {
      addresses.push_back(k.address_in_section());
      continue;
    }
    for (const std::string& t : tools) addresses.push_back(fmt::format("tool.{}.{}", t, k.name));
  }
  return addresses;
}

[[noreturn]] void unknown_address(const toml::table& root, const std::string& address) {
  const std::vector<std::string> addresses = known_addresses(root);
  const std::vector<std::string_view> candidates(addresses.begin(), addresses.end());
  const std::string guess = closest_match(address, candidates);
  throw InputError(fmt::format("unknown scene address '{}'{}", address,
                               guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
}

Target resolve(const toml::table& root, const std::string& address) {
  const std::vector<std::string> parts = split(address);
  Target target;
  if (parts.front() == "tool") {
    if (parts.size() != 3) unknown_address(root, address);
    target.key = find_key("tool", parts[2]);
    target.tool = parts[1];
  } else {
    std::string section;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      section += (i > 0 ? "." : "") + parts[i];
      target.tables.push_back(parts[i]);
    }
    target.key = find_key(section, parts.back());
  }
  if (target.key == nullptr) unknown_address(root, address);
  return target;
}

// The [[tool]] table named `name`; Table is toml::table or const toml::table.
template <class Table>
Table* find_tool(Table& root, const std::string& name, const std::string& address) {
  if (auto* tools = root["tool"].as_array()) {
    for (auto& node : *tools) {
      Table* tool = node.as_table();
      if (tool != nullptr && (*tool)["name"].template value<std::string>() == name) return tool;
    }
  }
  throw InputError(
      fmt::format("scene address '{}': there is no [[tool]] named '{}'", address, name));
}

[[noreturn]] void not_a_table(const std::string& address, const std::string& name) {
  throw InputError(fmt::format("scene address '{}': '{}' is not a table", address, name));
}

// The table that holds the target's key, or nullptr if a section table is missing.
const toml::table* find_holder(const toml::table& root, const Target& target,
                               const std::string& address) {
  if (!target.tool.empty()) return find_tool(root, target.tool, address);
  const toml::table* table = &root;
  for (const std::string& name : target.tables) {
    const toml::node* node = table->get(name);
    if (node == nullptr) return nullptr;
    if (!node->is_table()) not_a_table(address, name);
    table = node->as_table();
  }
  return table;
}

// The table that holds the target's key, creating missing section tables.
toml::table& make_holder(toml::table& root, const Target& target, const std::string& address) {
  if (!target.tool.empty()) return *find_tool(root, target.tool, address);
  toml::table* table = &root;
  for (const std::string& name : target.tables) {
    toml::node* node = table->get(name);
    if (node == nullptr) node = table->insert(name, toml::table{}).first->second.as_table();
    if (!node->is_table()) not_a_table(address, name);
    table = node->as_table();
  }
  return *table;
}

bool is_numeric(const KeySpec& key) {
  return key.type == KeyType::kFloat || key.type == KeyType::kInt;
}

}  // namespace

toml::table read_scene_table(const std::string& path) {
  return parse_toml_file(path, "scene file");
}

const KeySpec& scene_address_key(const toml::table& table, const std::string& address) {
  return *resolve(table, address).key;
}

double get_scene_number(const toml::table& table, const std::string& address) {
  const Target target = resolve(table, address);
  if (!is_numeric(*target.key)) {
    throw InputError(fmt::format("scene address '{}' is not a number", address));
  }
  const toml::table* owner = find_holder(table, target, address);
  const toml::node* node = owner != nullptr ? owner->get(target.key->name) : nullptr;
  if (node == nullptr) {
    if (target.key->required) {
      throw InputError(fmt::format("scene address '{}' is not set and has no default", address));
    }
    if (target.key->default_text != nullptr) {  // a default in words: it depends on the scene
      throw InputError(
          fmt::format("scene address '{}' is not set and its default depends on the "
                      "scene {}: set it",
                      address, target.key->default_text()));
    }
    return default_number(*target.key);
  }
  if (node->is_floating_point()) return node->as_floating_point()->get();
  if (node->is_integer()) return static_cast<double>(node->as_integer()->get());
  if (target.key->sticking_alias && node->value<std::string>() == "sticking") {
    return std::numeric_limits<double>::infinity();
  }
  throw InputError(
      fmt::format("scene address '{}': expected a number, got {}", address, toml_type_name(*node)));
}

void set_scene_number(toml::table& table, const std::string& address, double value) {
  const Target target = resolve(table, address);
  if (!is_numeric(*target.key)) {
    throw InputError(fmt::format("scene address '{}' is not a number", address));
  }
  toml::table& owner = make_holder(table, target, address);
  if (target.key->type == KeyType::kInt) {
    if (!std::isfinite(value) || value != std::round(value) || std::abs(value) > 1e15) {
      throw InputError(
          fmt::format("scene address '{}' takes whole numbers only, got {}", address, value));
    }
    owner.insert_or_assign(target.key->name, static_cast<std::int64_t>(value));
  } else {
    owner.insert_or_assign(target.key->name, value);
  }
}

void set_scene_value_from_text(toml::table& table, const std::string& address,
                               const std::string& text) {
  const Target target = resolve(table, address);
  toml::table& owner = make_holder(table, target, address);
  // Let the TOML parser type the text (numbers, inf, true/false, "quoted", arrays); anything it
  // does not accept is taken as a bare string (--set tool.punch.friction=sticking).
  try {
    const std::string statement = "value = " + text;
    check_toml_text(statement, "--set " + address);
    const toml::table parsed = toml::parse(statement);
    if (const toml::node* node = parsed.get("value"); node != nullptr && parsed.size() == 1) {
      owner.insert_or_assign(target.key->name, *node);
      return;
    }
  } catch (const toml::parse_error&) {
  }
  if (!valid_utf8(text)) {
    throw InputError(fmt::format("--set {}: the value is not valid UTF-8 text", address));
  }
  owner.insert_or_assign(target.key->name, text);
}

}  // namespace vs
