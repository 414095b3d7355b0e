#include "output/scene_json.h"

#include <string>
#include <string_view>
#include <variant>

#include "scene/scene_echo.h"

namespace vs {

namespace {

using Json = nlohmann::ordered_json;

Json json_value(const KeyValue& value) {
  struct ToJson {
    Json operator()(double x) const { return x; }
    Json operator()(int x) const { return x; }
    Json operator()(bool x) const { return x; }
    Json operator()(const std::string& x) const { return x; }
    Json operator()(const std::vector<double>& x) const { return x; }
    Json operator()(const KeyPairs& x) const {
      Json a = Json::array();
      for (const auto& p : x) a.push_back({p[0], p[1]});
      return a;
    }
  };
  return std::visit(ToJson{}, value);
}

// The object of a dotted section ("material.hardening") inside j, created on first use.
Json& section_object(Json& j, std::string_view section) {
  Json* node = &j;
  while (!section.empty()) {
    const std::size_t dot = section.find('.');
    const std::string part(section.substr(0, dot));
    node = &(*node)[part];
    section = dot == std::string_view::npos ? std::string_view{} : section.substr(dot + 1);
  }
  return *node;
}

}  // namespace

nlohmann::ordered_json scene_to_json(const Scene& scene) {
  Json j;
  j["source"] = scene.source;
  Json tools = Json::array();
  for (const EchoEntry& e : echo_scene(scene)) {
    const KeySpec& key = *e.key;
    if (key.section == "tool") {
      while (static_cast<int>(tools.size()) <= e.tool) tools.push_back(Json::object());
      tools[static_cast<std::size_t>(e.tool)][std::string(key.name)] = json_value(e.value);
    } else {
      section_object(j, key.section)[std::string(key.name)] = json_value(e.value);
    }
  }
  j["tools"] = tools;
  return j;
}

}  // namespace vs
