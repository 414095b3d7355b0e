// Every class of scene error gives one line "FILE:LINE:COL: message" pointing at the culprit.
#include <gtest/gtest.h>

#include <string>

#include "scene_test_util.h"

namespace vs {
namespace {

using testing::kDie;
using testing::kMinimalScene;
using testing::scene_error;

// kMinimalScene is 9 lines and kDie 5, so text appended after both starts on line 15.

TEST(SceneErrors, MissingFileAndSyntaxError) {
  try {
    load_scene("/nonexistent/x.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "cannot open scene file '/nonexistent/x.toml'");
  }
  const std::string message = scene_error("[blank]\nradius_mm = = 5\n");
  EXPECT_EQ(message.rfind("scene.toml:2:", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(SceneErrors, UnknownKeysSuggestTheNearestKey) {
  EXPECT_EQ(scene_error(kMinimalScene + kDie + "  fricton = 0.1\n"),
            "scene.toml:15:3: unknown key 'fricton' in [[tool]] 'die' (did you mean 'friction'?)");
  EXPECT_EQ(scene_error("[blnk]\n"),
            "scene.toml:1:2: unknown key 'blnk' at top level "
            "(did you mean 'blank'?)");
  EXPECT_EQ(scene_error(kMinimalScene + "[process]\npunch_travel = 5\n"),
            "scene.toml:11:1: unknown key 'punch_travel' in [process] "
            "(did you mean 'punch_travel_mm'?)");
  EXPECT_EQ(scene_error(kMinimalScene + "[material.hardening]\nk_mpa = 5\n"),
            "scene.toml:11:1: unknown key 'k_mpa' in [material.hardening] "
            "(did you mean 'K_MPa'?)");
  EXPECT_EQ(scene_error("[blank]\nr_value = 1\n"),
            "scene.toml:2:1: unknown key 'r_value' in [blank] (it belongs in [material])");
  EXPECT_EQ(scene_error("[blank]\nzzzzzzzz = 1\n"),
            "scene.toml:2:1: unknown key 'zzzzzzzz' in [blank]");
}

TEST(SceneErrors, OutOfRangeValuesNameKeyRangeAndUnit) {
  EXPECT_EQ(scene_error("[blank]\nradius_mm = 59.18\nthickness_mm = -1\n"),
            "scene.toml:3:16: blank.thickness_mm = -1 is out of range (0, inf) mm");
  EXPECT_EQ(scene_error("[blank]\nelements = 0\n"),
            "scene.toml:2:12: blank.elements = 0 is out of range [4, 2000]");
  EXPECT_EQ(scene_error("[blank]\nelements = 1000000000\n"),
            "scene.toml:2:12: blank.elements = 1000000000 is out of range [4, 2000]: run time and "
            "per-step history grow with the square of the element count (2000 elements: minutes "
            "and GBs)");
  EXPECT_EQ(scene_error("[numerics]\ntransverse_shear_scale = 0\n"),
            "scene.toml:2:26: numerics.transverse_shear_scale = 0 is out of range [0.01, 100]");
  EXPECT_EQ(
      scene_error("[numerics]\nstep_fraction = 1e-4\n"),
      "scene.toml:2:17: numerics.step_fraction = 0.0001 is out of range [0.05, 1]: a fraction "
      "f takes about ln(1/f)/f steps per contact event (92 000 at 1e-4)");
  EXPECT_EQ(
      scene_error("[numerics]\nmax_iterations = 100000000\n"),
      "scene.toml:2:18: numerics.max_iterations = 100000000 is out of range [1, 1000]: a step "
      "that has not converged in 1000 iterations will not; it is cut back");
  EXPECT_EQ(scene_error("[material]\nr_value = 25\n"),
            "scene.toml:2:11: material.r_value = 25 is out of range [0.05, 20]");
  EXPECT_EQ(scene_error("[numerics]\ntolerance = 0.5\n"),
            "scene.toml:2:13: numerics.tolerance = 0.5 is out of range [1e-12, 0.1]");
  EXPECT_EQ(scene_error("[numerics]\nmax_cutbacks = 31\n"),
            "scene.toml:2:16: numerics.max_cutbacks = 31 is out of range [0, 30]");
  EXPECT_EQ(scene_error("[numerics]\nthickness_points = 4\n"),
            "scene.toml:2:20: numerics.thickness_points = 4 is not allowed; expected one of 3, "
            "5, 7, 9");
  EXPECT_EQ(scene_error(kMinimalScene + "friction = -0.1\n"),
            "scene.toml:10:12: tool.punch.friction = -0.1 is out of range [0, inf]");
  // A continuum code's no-slip surrogate (mu = 3 or 10) is a scene the shell must run to be
  // compared with it (experiments/11, section 5); above 10 it is "sticking".
  EXPECT_EQ(scene_error(kMinimalScene + "friction = 3\n"), "loaded");
  EXPECT_EQ(scene_error(kMinimalScene + "friction = 10\n"), "loaded");
  EXPECT_EQ(scene_error(kMinimalScene + "friction = 10.5\n"),
            "scene.toml:10:12: tool.punch.friction = 10.5 is above 10: no sliding contact has "
            "such a coefficient; use \"sticking\" (no slip, treated exactly) instead");
  EXPECT_EQ(scene_error("[blank]\ngrading = nan\n"),
            "scene.toml:2:11: blank.grading = nan is out of range (0, inf)");
  EXPECT_EQ(scene_error("[process]\noutput_travels_mm = [1, -2]\n"),
            "scene.toml:2:25: process.output_travels_mm[1] = -2 is out of range (0, inf) mm");
}

TEST(SceneErrors, WrongTypes) {
  EXPECT_EQ(scene_error("[material.hardening]\nn = \"0.2\"\n"),
            "scene.toml:2:5: material.hardening.n: expected a number, got string");
  EXPECT_EQ(scene_error("[blank]\nelements = 50.0\n"),
            "scene.toml:2:12: blank.elements: expected an integer, got float");
  EXPECT_EQ(scene_error("[output]\nplots = 1\n"),
            "scene.toml:2:9: output.plots: expected true or false, got integer");
  EXPECT_EQ(scene_error("blank = 3\n"), "scene.toml:1:9: blank: expected a table, got integer");
  EXPECT_EQ(scene_error("[tool]\nname = \"p\"\n"),
            "scene.toml:1:1: tool: expected an array of tables ([[tool]]), got table");
  EXPECT_EQ(scene_error(kMinimalScene + "friction = \"slippery\"\n"),
            "scene.toml:10:12: tool.punch.friction = \"slippery\": expected a number, inf or "
            "\"sticking\"");
}

TEST(SceneErrors, EnumValues) {
  EXPECT_EQ(scene_error("geometry = \"plane_strain\"\n"),
            "scene.toml:1:12: geometry = \"plane_strain\" is not supported; expected one of "
            "\"axisymmetric\", \"shell3d\"");
  EXPECT_EQ(scene_error("[blank]\nedge = \"pined\"\n"),
            "scene.toml:2:8: blank.edge = \"pined\" is not supported; expected one of "
            "\"pinned\", \"clamped\", \"free\" (did you mean \"pinned\"?)");
}

TEST(SceneErrors, KeysOfAnotherVariantAreRejected) {
  EXPECT_EQ(scene_error("[material.hardening]\nlaw = \"voce\"\nK_MPa = 500\n"),
            "scene.toml:3:1: key 'K_MPa' is not used by hardening law 'voce'");
  EXPECT_EQ(scene_error("[material.hardening]\nsigma0_MPa = 200\n"),
            "scene.toml:2:1: key 'sigma0_MPa' is not used by hardening law 'swift'");
  EXPECT_EQ(scene_error("[material.hardening]\nlaw = \"hollomon\"\neps0 = 0.1\n"),
            "scene.toml:3:1: key 'eps0' is not used by hardening law 'hollomon'");
  EXPECT_EQ(scene_error("[material.hardening]\nlaw = \"swift\"\ntable_scale = 1.1\n"),
            "scene.toml:3:1: key 'table_scale' is not used by hardening law 'swift'");
  EXPECT_EQ(scene_error("[material.rate]\nlaw = \"perzyna\"\nm = 0.1\n"),
            "scene.toml:3:1: key 'm' is not used by rate law 'perzyna'");
  EXPECT_EQ(scene_error("[material.rate]\ngamma_per_s = 2\n"),
            "scene.toml:2:1: key 'gamma_per_s' is not used by rate law 'none'");
  EXPECT_EQ(scene_error(kMinimalScene + "profile_radius_mm = 3\n"),
            "scene.toml:10:1: key 'profile_radius_mm' is not used by tool kind "
            "'hemispherical_punch' in [[tool]] 'punch'");
  EXPECT_EQ(scene_error(kMinimalScene + kDie + "force_N = 100\n"),
            "scene.toml:15:1: key 'force_N' is not used by tool kind 'die' in [[tool]] 'die'");
}

TEST(SceneErrors, ToolTablesNeedNameKindAndTheirRequiredKeys) {
  EXPECT_EQ(scene_error(kMinimalScene + "[[tool]]\nkind = \"die\"\n"),
            "scene.toml:10:1: missing required key 'name' in [[tool]] #2");
  EXPECT_EQ(scene_error(kMinimalScene + "[[tool]]\nname = \"d\"\n"),
            "scene.toml:10:1: missing required key 'kind' in [[tool]] 'd'");
  EXPECT_EQ(scene_error(kMinimalScene + "[[tool]]\nname = \"d\"\nkind = \"die\"\n"),
            "scene.toml:10:1: missing required key 'radius_mm' in [[tool]] 'd'");
  EXPECT_EQ(scene_error(kMinimalScene + kDie + "[[tool]]\nname = \"h\"\nkind = \"blank_holder\"\n"),
            "scene.toml:17:8: blank holder 'h' needs exactly one of force_N (prescribed force) "
            "and gap_mm (fixed gap)");
  EXPECT_EQ(scene_error(kMinimalScene + kDie +
                        "[[tool]]\nname = \"h\"\nkind = \"blank_holder\"\nforce_N = 10\n"
                        "gap_mm = 2\n"),
            "scene.toml:17:8: blank holder 'h' needs exactly one of force_N (prescribed force) "
            "and gap_mm (fixed gap)");
  EXPECT_EQ(scene_error(kMinimalScene + kDie +
                        "[[tool]]\nname = \"h\"\nkind = \"blank_holder\"\ngap_mm = 0.5\n"),
            "scene.toml:18:10: tool.h.gap_mm = 0.5 must be >= blank.thickness_mm = 0.85 mm (the "
            "holder may not crush the blank at the start)");
  EXPECT_EQ(scene_error(kMinimalScene + "[[tool]]\nname = \"punch\"\n"),
            "scene.toml:11:8: duplicate tool name 'punch' (first used at scene.toml:6:8)");
  EXPECT_EQ(scene_error(kMinimalScene + "[[tool]]\nname = \"my die\"\n"),
            "scene.toml:11:8: tool #2 name = \"my die\" is not a valid name: use letters, "
            "digits and _");
}

TEST(SceneErrors, ToolSetRules) {
  EXPECT_EQ(scene_error("[blank]\nradius_mm = 59\n"),
            "scene.toml: the scene has no punch: add a [[tool]] with kind = "
            "\"hemispherical_punch\" or \"flat_punch\"");
  EXPECT_EQ(scene_error(kMinimalScene +
                        "[[tool]]\nname = \"p2\"\nkind = \"flat_punch\"\nradius_mm = 30\n"),
            "scene.toml:12:8: tool 'p2' is a second punch (tool 'punch' is one already); at "
            "most one punch is allowed");
  EXPECT_EQ(scene_error(kMinimalScene + kDie +
                        "[[tool]]\nname = \"d2\"\nkind = \"die\"\nradius_mm = 55\n"),
            "scene.toml:17:8: tool 'd2' is a second die (tool 'die' is one already); at most "
            "one die is allowed");
  EXPECT_EQ(scene_error(kMinimalScene +
                        "[[tool]]\nname = \"h\"\nkind = \"blank_holder\"\nforce_N = 1000\n"),
            "scene.toml:12:8: blank holder 'h' needs a die to press the flange against");
}

TEST(SceneErrors, GeometryRules) {
  EXPECT_EQ(scene_error("[blank]\nradius_mm = 59\n[[tool]]\nname = \"p\"\nkind = "
                        "\"flat_punch\"\nradius_mm = 30\nprofile_radius_mm = 30\n"),
            "scene.toml:7:21: tool.p.profile_radius_mm = 30 must be < tool.p.radius_mm = 30 mm "
            "(flat punch nose radius)");
  EXPECT_EQ(scene_error("[blank]\nradius_mm = 50\n[[tool]]\nname = \"p\"\nkind = "
                        "\"hemispherical_punch\"\nradius_mm = 50.8\n"),
            "scene.toml:2:13: blank.radius_mm = 50 must be > punch radius tool.p.radius_mm = "
            "50.8 mm");
  EXPECT_EQ(
      scene_error(kMinimalScene + "[[tool]]\nname = \"die\"\nkind = \"die\"\nradius_mm = 51.5\n"),
      "scene.toml:13:13: tool.die.radius_mm = 51.5 leaves no clearance: it must be > "
      "punch radius 50.8 + blank thickness 0.85 = 51.65 mm");
  EXPECT_EQ(
      scene_error(kMinimalScene + "[[tool]]\nname = \"die\"\nkind = \"die\"\nradius_mm = 60\n"),
      "scene.toml:2:13: blank.radius_mm = 59.18 must be > die opening tool.die.radius_mm "
      "= 60 mm (the blank must reach the die)");
  EXPECT_EQ(scene_error("[blank]\nradius_mm = 59.18\nedge = \"free\"\n[[tool]]\nname = \"p\"\n"
                        "kind = \"hemispherical_punch\"\nradius_mm = 50.8\n"),
            "scene.toml:3:8: blank.edge = \"free\" needs a die: without one nothing holds the "
            "sheet");
  EXPECT_EQ(scene_error("[blank]\nradius_mm = 59.18\nthickness_mm = 12\n[[tool]]\nname = \"p\"\n"
                        "kind = \"hemispherical_punch\"\nradius_mm = 50.8\n"),
            "scene.toml:3:16: blank.thickness_mm = 12 must be < blank.radius_mm / 5 = 11.836 mm "
            "(thin shell)");
}

TEST(SceneErrors, OutputTravels) {
  EXPECT_EQ(scene_error(kMinimalScene + "[process]\npunch_travel_mm = 30\n"
                                        "output_travels_mm = [10, 10, 20]\n"),
            "scene.toml:12:26: process.output_travels_mm[1] = 10 must be > the previous output "
            "travel 10 mm (strictly increasing)");
  EXPECT_EQ(scene_error(kMinimalScene + "[process]\npunch_travel_mm = 30\n"
                                        "output_travels_mm = [10, 20, 31]\n"),
            "scene.toml:12:30: process.output_travels_mm[2] = 31 exceeds "
            "process.punch_travel_mm = 30 mm");
  // Travel left at its default (10 mm): the error still points at the output stage.
  EXPECT_EQ(scene_error(kMinimalScene + "[process]\noutput_travels_mm = [20]\n"),
            "scene.toml:11:22: process.output_travels_mm[0] = 20 exceeds "
            "process.punch_travel_mm = 10 mm");
}

TEST(SceneErrors, MessagesAreOneLine) {
  for (const std::string text : {"[blank]\nradius_mm = = 5\n", "x = [\n", "[a]\n[a]\n"}) {
    const std::string message = scene_error(text);
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("scene.toml:", 0), 0u) << message;
  }
}

}  // namespace
}  // namespace vs
