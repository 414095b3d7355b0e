// Scene file -> Scene: parse (scene_table.cc), walk the sections against the key registry
// (scene_reader.cc), then check the rules that span sections (scene_checks.cc).
#include "scene/load_scene.h"

#include <fmt/format.h>

#include <filesystem>
#include <string_view>

#include "scene/scene_checks.h"
#include "scene/scene_diagnostics.h"
#include "scene/scene_keys.h"
#include "scene/scene_reader.h"
#include "scene/scene_table.h"

namespace vs {

namespace {

// Keys that only one geometry uses (KeySpec::geometry); setting one in a scene of the other
// geometry is an error, like a key of another hardening law.
void check_geometry_keys(const toml::table& table, const Scene& scene, const std::string& source) {
  const KeySpec& geometry_key = *find_key("", "geometry");
  const std::string_view geometry =
      geometry_key.choices.at(static_cast<std::size_t>(scene.geometry));
  for (const KeySpec& k : scene_keys()) {
    if (k.geometry.empty() || k.geometry == geometry) continue;
    const toml::table* section = table.at_path(k.section).as_table();  // "material.anisotropy"
    if (section == nullptr) continue;
    for (auto&& [key, node] : *section) {
      if (key.str() != k.name) continue;
      fail_at(source, key.source(),
              fmt::format("key '{}' is only used by geometry = \"{}\"", k.address_in_section(),
                          k.geometry));
    }
  }
}

// Defaults that depend on the geometry or the update, for keys the scene file does not set. The
// implicit geometry update is the default of both geometries: stable at steps set by accuracy,
// 5-8x faster than heun at equal answers (experiments/06_step_stability,
// experiments/01_performance, experiments/05_shell3d). In 3D its step across the first contact
// events on a coarse grid was 2-4 points less accurate in force than heun's (experiments/06,
// "Implicit at 0.25 as the scene default"), so a shell3d scene refines the start of its step grid
// (start_refinement = 3: the first grid increments split into 8, 4 and 2 steps), and its steps
// do not end at contact events (contact_events = false: every node of a 3D mesh touches at its
// own instant, and with events its outputs jumped under 1e-5 changes of friction; experiments/06,
// "The implicit update as the 3D default"). The step cap relative to the element length follows the
// update: 0.25 implicit (accuracy), 0.025 heun / euler (the explicit update's stability). A
// shell3d scene's velocity solves per step follow the model's size (implicit_solves_for in
// stepping/step_driver.h: one from kOneSolveMinUnknowns unknowns).
void apply_geometry_defaults(const toml::table& table, Scene* scene) {
  NumericsSpec& nu = scene->numerics;
  if (!table.at_path("numerics.time_integration")) nu.time_integration = TimeIntegration::kImplicit;
  const bool implicit_3d =
      scene->geometry == Geometry::kShell3d && nu.time_integration == TimeIntegration::kImplicit;
  if (!table.at_path("numerics.start_refinement")) {
    nu.start_refinement = implicit_3d ? kShell3dImplicitStartRefinement : 0;
  }
  if (!table.at_path("numerics.contact_events")) nu.contact_events = !implicit_3d;
  if (!table.at_path("numerics.implicit_solves") && implicit_3d) {
    nu.implicit_solves = kImplicitSolvesBySize;
  }
  if (!table.at_path("numerics.max_travel_increment_per_length")) {
    nu.max_travel_increment_per_length = nu.time_integration == TimeIntegration::kImplicit
                                             ? kImplicitTravelIncrementPerLength
                                             : NumericsSpec{}.max_travel_increment_per_length;
  }
}

}  // namespace

Scene load_scene(const std::string& path) {
  const toml::table table = read_scene_table(path);
  return scene_from_table(table, path, std::filesystem::path(path).parent_path().string());
}

Scene scene_from_table(const toml::table& table, const std::string& source,
                       const std::string& base_dir) {
  SceneSourceMap where(source);
  Scene scene = read_scene_sections(table, base_dir, where);
  scene.source = source;
  check_geometry_keys(table, scene, source);
  apply_geometry_defaults(table, &scene);
  check_scene_consistency(scene, where);
  return scene;
}

}  // namespace vs
