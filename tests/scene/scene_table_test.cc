// Dotted addresses into a parsed scene: get with defaults, set and rebuild, text overrides.
#include "scene/scene_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

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

// Two numerics defaults depend on the geometry (load_scene.cc): the implicit update at 0.25
// element lengths for axisymmetric scenes, heun at 0.025 for shell3d; the cap follows the update
// unless the scene sets it.
TEST(SceneTable, NumericsDefaultsFollowTheGeometryAndTheUpdate) {
  const auto scene_with = [](const std::vector<std::pair<std::string, std::string>>& sets) {
    toml::table table = minimal_table();
    for (const auto& [address, value] : sets) set_scene_value_from_text(table, address, value);
    return scene_from_table(table, "memory", "");
  };
  const Scene axi = scene_with({});
  EXPECT_EQ(axi.numerics.time_integration, TimeIntegration::kImplicit);
  EXPECT_EQ(axi.numerics.max_travel_increment_per_length, 0.25);
  const Scene axi_heun = scene_with({{"numerics.time_integration", "heun"}});
  EXPECT_EQ(axi_heun.numerics.time_integration, TimeIntegration::kHeun);
  EXPECT_EQ(axi_heun.numerics.max_travel_increment_per_length, 0.025);
  const Scene axi_set = scene_with({{"numerics.max_travel_increment_per_length", "0.1"}});
  EXPECT_EQ(axi_set.numerics.time_integration, TimeIntegration::kImplicit);
  EXPECT_EQ(axi_set.numerics.max_travel_increment_per_length, 0.1);
  const std::string ex4a =
      std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml";
  toml::table table3d = read_scene_table(ex4a);
  const Scene shell = scene_from_table(table3d, ex4a, "");
  EXPECT_EQ(shell.numerics.time_integration, TimeIntegration::kImplicit);
  EXPECT_EQ(shell.numerics.max_travel_increment_per_length, 0.25);
  EXPECT_EQ(shell.numerics.start_refinement, 3);
  EXPECT_FALSE(shell.numerics.contact_events);
  EXPECT_EQ(axi.numerics.start_refinement, 0);
  EXPECT_TRUE(axi.numerics.contact_events);
  EXPECT_EQ(shell.numerics.implicit_solves, kImplicitSolvesBySize);
  EXPECT_EQ(axi.numerics.implicit_solves, 2);
  set_scene_value_from_text(table3d, "numerics.time_integration", "heun");
  const Scene shell_heun = scene_from_table(table3d, ex4a, "");
  EXPECT_EQ(shell_heun.numerics.max_travel_increment_per_length, 0.025);
  EXPECT_EQ(shell_heun.numerics.start_refinement, 0);
  EXPECT_TRUE(shell_heun.numerics.contact_events);
  EXPECT_EQ(shell_heun.numerics.implicit_solves, 2);
  set_scene_value_from_text(table3d, "numerics.start_refinement", "2");
  EXPECT_EQ(scene_from_table(table3d, ex4a, "").numerics.start_refinement, 2);
  set_scene_value_from_text(table3d, "numerics.time_integration", "implicit");
  set_scene_value_from_text(table3d, "numerics.implicit_solves", "2");
  EXPECT_EQ(scene_from_table(table3d, ex4a, "").numerics.implicit_solves, 2);
  // A number read from the table (the calibration's start values) cannot name such a default.
  EXPECT_NE(error_of([] {
              get_scene_number(minimal_table(), "numerics.max_travel_increment_per_length");
            }).find("depends on the scene"),
            std::string::npos);
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
