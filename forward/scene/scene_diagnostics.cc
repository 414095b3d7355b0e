#include "scene/scene_diagnostics.h"

#include <fmt/format.h>

#include "core/error.h"

namespace vs {

std::string source_location(const std::string& source, const toml::source_region& region) {
  if (region.begin.line == 0) return source;
  return fmt::format("{}:{}:{}", source, region.begin.line, region.begin.column);
}

void fail_at(const std::string& source, const toml::source_region& region,
             const std::string& message) {
  throw InputError(fmt::format("{}: {}", source_location(source, region), message));
}

std::string toml_type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "string";
    case toml::node_type::integer:
      return "integer";
    case toml::node_type::floating_point:
      return "float";
    case toml::node_type::boolean:
      return "boolean";
    case toml::node_type::array:
      return "array";
    case toml::node_type::table:
      return "table";
    case toml::node_type::date:
      return "date";
    case toml::node_type::time:
      return "time";
    case toml::node_type::date_time:
      return "date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

void SceneSourceMap::add(const std::string& address, const toml::source_region& region) {
  regions_[address] = region;
}

void SceneSourceMap::fail(const std::string& address, const std::string& message) const {
  std::string a = address;
  while (!a.empty()) {
    const auto it = regions_.find(a);
    if (it != regions_.end() && it->second.begin.line != 0) fail_at(source_, it->second, message);
    const std::size_t cut = a.find_last_of(".[");
    a = cut == std::string::npos ? std::string() : a.substr(0, cut);
  }
  throw InputError(fmt::format("{}: {}", source_, message));
}

}  // namespace vs
