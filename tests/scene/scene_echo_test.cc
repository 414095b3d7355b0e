// The scene as run (scene_echo.h): complete by construction (every registry key that applies to a
// scene is echoed), and a scene file that loads back to the same scene, for every bundled scene
// and for the values a scene file gives in another form (table files, sticking, odd titles).
#include "scene/scene_echo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "scene/load_scene.h"
#include "scene/scene_keys.h"
#include "scene/scene_table.h"
#include "scene/text_checks.h"
#include "scene_test_util.h"

namespace vs {
namespace {

using testing::write_scratch;

// The echo without its leading comment lines (which name the file it was read from).
std::string body(const std::string& toml) {
  std::size_t at = 0;
  while (at < toml.size() && toml[at] == '#') at = toml.find('\n', at) + 1;
  return toml.substr(at);
}

// Loads `path`, echoes it, loads the echo and echoes that: the two echoes agree.
void expect_round_trip(const std::string& path) {
  const Scene first = load_scene(path);
  const std::string echo = scene_toml(first);
  const std::string again = write_scratch("echo.toml", echo);
  Scene second;
  ASSERT_NO_THROW(second = load_scene(again)) << path << ":\n" << echo;
  EXPECT_EQ(body(scene_toml(second)), body(echo)) << path;
}

TEST(SceneEcho, EveryBundledSceneLoadsBackToTheSameScene) {
  const std::filesystem::path root = VS_SOURCE_DIR;
  int scenes = 0;
  for (const char* folder :
       {"data/scenes", "experiments/10_earing/scenes", "experiments/05_shell3d"}) {
    for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
      if (entry.path().extension() != ".toml") continue;
      SCOPED_TRACE(entry.path().string());
      expect_round_trip(entry.path().string());
      ++scenes;
    }
  }
  EXPECT_GE(scenes, 14);
}

// A scene with what a file gives in another form than the Scene holds it: a hardening table from
// a CSV file (relative to the scene), a sticking tool, a tabulated forming-limit curve, a title
// with quotes, a backslash, a tab and a DEL.
TEST(SceneEcho, ResolvedFormsLoadBack) {
  write_scratch("curve.csv", "plastic_strain,stress_MPa\n0,200\n0.1,300\n0.5,420\n");
  // (The title goes first: after a table header it would belong to that table.)
  const std::string text = "title = \"cup \\\"A\\\" \\\\ 1\\t2\\u007f\"\n" +
                           testing::kMinimalScene +
                           "friction = \"sticking\"\n\n"
                           "[material.hardening]\nlaw = \"table\"\ntable_file = \"curve.csv\"\n\n"
                           "[forming_limit]\nmodel = \"table\"\npoints = [[-0.2, 0.4], [0.0, "
                           "0.25], [0.3, 0.45]]\n";
  const Scene scene = load_scene(write_scratch("scene.toml", text));
  const std::string echo = scene_toml(scene);
  EXPECT_NE(echo.find("friction = \"sticking\""), std::string::npos) << echo;
  EXPECT_NE(echo.find("table = [[0.0, 200.0], [0.1, 300.0], [0.5, 420.0]]"), std::string::npos)
      << echo;
  EXPECT_EQ(echo.find("table_file"), std::string::npos) << echo;
  EXPECT_NE(echo.find("points = [[-0.2, 0.4], [0.0, 0.25], [0.3, 0.45]]"), std::string::npos)
      << echo;
  // Loaded from another folder: nothing in it depends on where the echo lies.
  const std::filesystem::path elsewhere = testing::scratch_dir() / "elsewhere";
  std::filesystem::create_directories(elsewhere);
  const std::string moved = (elsewhere / "scene.toml").string();
  std::ofstream(moved) << echo;
  const Scene back = load_scene(moved);
  EXPECT_EQ(back.title, scene.title);
  EXPECT_EQ(back.tools.at(0).friction, std::numeric_limits<double>::infinity());
  EXPECT_EQ(back.material.hardening.table_stress_MPa, scene.material.hardening.table_stress_MPa);
  EXPECT_EQ(back.forming_limit.table_major, scene.forming_limit.table_major);
  EXPECT_EQ(body(scene_toml(back)), body(echo));
}

// A scene in which `key` applies: its geometry, its section's variant, a tool of its kind.
Scene scene_for(const KeySpec& key) {
  Scene s;
  ToolSpec tool;
  if (key.geometry == "shell3d") s.geometry = Geometry::kShell3d;
  const VariantSelector* selector = find_selector(key.section);
  if (selector != nullptr && !key.applies_to.empty()) {
    const KeySpec& choice = *find_key(key.section, selector->key);
    const auto at = std::find(choice.choices.begin(), choice.choices.end(), key.applies_to[0]);
    choice.field.set_choice(s, tool, static_cast<int>(at - choice.choices.begin()));
  }
  // A number outside the key's range means "not given" (a holder's force_N when it has a gap):
  // give the key a value it accepts.
  const double lo = std::isfinite(key.range.lo) ? key.range.lo : 0.0;
  const double valid = key.range.contains(lo) ? lo : lo + 1.0;
  if (key.field.number && !key.range.contains(key.field.number(s, tool)) && !key.sticking_alias)
    key.field.number(s, tool) = valid;
  if (key.field.integer && !key.range.contains(key.field.integer(s, tool)))
    key.field.integer(s, tool) = static_cast<int>(valid);
  if (key.section == "tool") s.tools.push_back(tool);
  return s;
}

// Every key of the registry is echoed where it applies, except the one the scene holds in
// another form: a new key cannot be left out of scene.toml and run.json.
TEST(SceneEcho, EveryKeyIsEchoedWhereItApplies) {
  int checked = 0;
  for (const KeySpec& key : scene_keys()) {
    if (echo_skips(key)) continue;
    const Scene s = scene_for(key);
    const std::vector<EchoEntry> echo = echo_scene(s);
    const bool found =
        std::any_of(echo.begin(), echo.end(), [&](const EchoEntry& e) { return e.key == &key; });
    EXPECT_TRUE(found) << key.address_in_section();
    ++checked;
  }
  EXPECT_GT(checked, 70);
}

// Text that is not UTF-8 cannot be written in TOML: --set refuses it with a one-line error, and a
// scene built in code with such a string echoes U+FFFD in its place (the echo still loads).
TEST(SceneEcho, InvalidUtf8IsRefusedAtSetAndReplacedInTheEcho) {
  EXPECT_TRUE(valid_utf8("plain, caf\xC3\xA9, \xE2\x82\xAC, \xF0\x9F\x98\x80"));
  for (const char* bad :
       {"caf\xE9", "\xC3", "\xC0\xAF", "\xED\xA0\x80", "\xF4\x90\x80\x80", "\x80"}) {
    EXPECT_FALSE(valid_utf8(bad)) << bad;
  }
  toml::table table = toml::parse(testing::kMinimalScene);
  try {
    set_scene_value_from_text(table, "title", "caf\xE9");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--set title: the value is not valid UTF-8 text");
  }
  Scene scene = load_scene(write_scratch("scene.toml", testing::kMinimalScene));
  scene.title = "caf\xE9";
  const Scene back = load_scene(write_scratch("echo.toml", scene_toml(scene)));
  EXPECT_EQ(back.title, "caf\xEF\xBF\xBD");
}

// A key of another geometry or variant is not echoed (the loader would refuse it).
TEST(SceneEcho, KeysThatDoNotApplyAreLeftOut) {
  const Scene axisymmetric;  // swift hardening, no tools
  for (const EchoEntry& e : echo_scene(axisymmetric)) {
    EXPECT_NE(e.key->geometry, "shell3d") << e.key->address_in_section();
    EXPECT_NE(e.key->address_in_section(), "material.hardening.Q_MPa");
    EXPECT_NE(e.key->section, "tool");
  }
}

}  // namespace
}  // namespace vs
