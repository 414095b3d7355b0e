// Dotted addresses into a parsed scene: get with defaults, set and rebuild, text overrides.
#include "scene/scene_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "scene_test_util.h"

namespace vs {
namespace {

using testing::kDie;
using testing::kMinimalScene;
using testing::write_scratch;

toml::table minimal_table() {
  return read_scene_table(write_scratch("scene.toml", kMinimalScene + kDie));
}

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SceneTable, GetReturnsFileValueOrDeclaredDefault) {
  const toml::table table = minimal_table();
  EXPECT_EQ(get_scene_number(table, "blank.thickness_mm"), 0.85);
  EXPECT_EQ(get_scene_number(table, "tool.die.profile_radius_mm"), 6.35);
  EXPECT_EQ(get_scene_number(table, "numerics.tolerance"), NumericsSpec{}.tolerance);
  EXPECT_EQ(get_scene_number(table, "blank.elements"), BlankSpec{}.elements);
  EXPECT_EQ(get_scene_number(table, "material.hardening.K_MPa"), HardeningSpec{}.K_MPa);
  EXPECT_EQ(get_scene_number(table, "tool.punch.friction"), ToolSpec{}.friction);
}

TEST(SceneTable, SetGetRoundTripAndRebuild) {
  toml::table table = minimal_table();
  set_scene_number(table, "tool.punch.friction", 0.2);
  set_scene_number(table, "material.hardening.K_MPa", 610.5);  // creates [material.hardening]
  set_scene_number(table, "blank.elements", 64);
  set_scene_number(table, "tool.die.friction", std::numeric_limits<double>::infinity());
  EXPECT_EQ(get_scene_number(table, "tool.punch.friction"), 0.2);
  EXPECT_EQ(get_scene_number(table, "material.hardening.K_MPa"), 610.5);
  EXPECT_EQ(get_scene_number(table, "blank.elements"), 64.0);
  const Scene scene = scene_from_table(table, "memory", "");
  EXPECT_EQ(scene.tools[0].friction, 0.2);
  EXPECT_TRUE(scene.tools[1].sticking());
  EXPECT_EQ(scene.material.hardening.K_MPa, 610.5);
  EXPECT_EQ(scene.blank.elements, 64);
}

TEST(SceneTable, ValuesSetInMemoryAreCheckedWithoutLineNumbers) {
  toml::table table = minimal_table();
  set_scene_number(table, "blank.thickness_mm", -1.0);
  EXPECT_EQ(error_of([&] { scene_from_table(table, "memory", ""); }),
            "memory: blank.thickness_mm = -1 is out of range (0, inf) mm");
}

TEST(SceneTable, SetFromText) {
  toml::table table = minimal_table();
  set_scene_value_from_text(table, "tool.punch.friction", "sticking");
  set_scene_value_from_text(table, "tool.die.friction", "0.5");
  set_scene_value_from_text(table, "output.plots", "false");
  set_scene_value_from_text(table, "title", "run 7");
  set_scene_value_from_text(table, "material.hardening.law", "voce");
  set_scene_value_from_text(table, "process.output_travels_mm", "[2, 4]");
  EXPECT_EQ(get_scene_number(table, "tool.punch.friction"),
            std::numeric_limits<double>::infinity());
  const Scene scene = scene_from_table(table, "memory", "");
  EXPECT_TRUE(scene.tools[0].sticking());
  EXPECT_EQ(scene.tools[1].friction, 0.5);
  EXPECT_FALSE(scene.output.plots);
  EXPECT_EQ(scene.title, "run 7");
  EXPECT_EQ(scene.material.hardening.law, HardeningLaw::kVoce);
  EXPECT_EQ(scene.process.output_travels_mm, (std::vector<double>{2.0, 4.0}));
}

TEST(SceneTable, BadAddressesAndValues) {
  toml::table table = minimal_table();
  EXPECT_EQ(error_of([&] { get_scene_number(table, "blank.thicknes_mm"); }),
            "unknown scene address 'blank.thicknes_mm' (did you mean 'blank.thickness_mm'?)");
  EXPECT_EQ(error_of([&] { get_scene_number(table, "tool.punch.fricton"); }),
            "unknown scene address 'tool.punch.fricton' (did you mean 'tool.punch.friction'?)");
  EXPECT_EQ(error_of([&] { set_scene_number(table, "tool.holder.friction", 0.1); }),
            "scene address 'tool.holder.friction': there is no [[tool]] named 'holder'");
  EXPECT_EQ(error_of([&] { set_scene_number(table, "solver.tolerance", 0.1); }),
            "unknown scene address 'solver.tolerance'");
  EXPECT_EQ(error_of([&] { set_scene_number(table, "blank.elements", 10.5); }),
            "scene address 'blank.elements' takes whole numbers only, got 10.5");
  EXPECT_EQ(error_of([&] { get_scene_number(table, "blank.edge"); }),
            "scene address 'blank.edge' is not a number");
  set_scene_value_from_text(table, "blank.grading", "steep");
  EXPECT_EQ(error_of([&] { get_scene_number(table, "blank.grading"); }),
            "scene address 'blank.grading': expected a number, got string");
  EXPECT_EQ(error_of([&] { scene_from_table(table, "memory", ""); }),
            "memory: blank.grading: expected a number, got string");
}

TEST(SceneTable, ReadSceneTableReportsSyntaxErrors) {
  const std::string path = write_scratch("bad.toml", "[blank]\nradius_mm = \n");
  const std::string message = error_of([&] { read_scene_table(path); });
  EXPECT_EQ(message.rfind(path + ":2:", 0), 0u) << message;
}

}  // namespace
}  // namespace vs
