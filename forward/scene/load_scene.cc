// Scene file -> Scene: parse (scene_table.cc), walk the sections against the key registry
// (scene_reader.cc), then check the rules that span sections (scene_checks.cc).
#include "scene/load_scene.h"

#include <filesystem>

#include "scene/scene_checks.h"
#include "scene/scene_diagnostics.h"
#include "scene/scene_reader.h"
#include "scene/scene_table.h"

namespace vs {

Scene load_scene(const std::string& path) {
  const toml::table table = read_scene_table(path);
  return scene_from_table(table, path, std::filesystem::path(path).parent_path().string());
}

Scene scene_from_table(const toml::table& table, const std::string& source,
                       const std::string& base_dir) {
  SceneSourceMap where(source);
  Scene scene = read_scene_sections(table, base_dir, where);
  scene.source = source;
  check_scene_consistency(scene, where);
  return scene;
}

}  // namespace vs
