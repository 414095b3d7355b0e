// Config parsing and the rule that every configuration or data error is raised before the first
// forward run (the fake counts its calls).
#include "calibration_config.h"

#include <gtest/gtest.h>

#include <atomic>

#include "calibrate.h"
#include "core/error.h"
#include "inverse_test_support.h"

namespace vs {
namespace {

using namespace vs::testing;

constexpr const char* kGoodConfig = R"(scene = "scene.toml"
[[parameter]]
address = "tool.punch.friction"
initial = 0.05
lower = 0.0
upper = 0.5
scale = 0.01
[[parameter]]
address = "material.hardening.K_MPa"
lower = 100.0
upper = 1000.0
[[parameter]]
address = "material.hardening.eps0"
fixed = true
[[data]]
kind = "load_travel"
file = "load.csv"
sigma = 50.0
[[data]]
kind = "thickness_strain"
file = "thick.csv"
travel_mm = 20
weight = 100.0
name = "thick_20mm"
[optimizer]
method = "global_then_local"
max_iterations = 20
function_tolerance = 1e-9
seed = 42
max_evaluations = 50
fd = "ridders"
relative_step = 1e-3
threads = 2
[forward]
tolerance = 1e-10
[forward.set]
"blank.elements" = 24
[output]
directory = "calib_out"
)";

class ConfigTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_dir();
    write_scene(dir_);
    write_file(dir_ / "load.csv", kLoadCsv);
    write_file(dir_ / "thick.csv", kThickCsv);
  }

  fs::path write_config(const std::string& text) {
    write_file(dir_ / "calibrate.toml", text);
    return dir_ / "calibrate.toml";
  }

  // Loads and calibrates with a counting fake; returns the InputError text ("" if none).
  std::string error_of(const std::string& config_text) {
    const fs::path path = write_config(config_text);
    try {
      CalibrationConfig config = load_calibration_config(path.string());
      CalibrationOptions options;
      options.write_report = false;
      StretchingFake fake;
      fake.calls = &calls_;
      calibrate(config, options, fake);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  std::string replace(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  }

  fs::path dir_;
  std::atomic<int> calls_{0};
};

TEST_F(ConfigTest, ReadsEveryKey) {
  const CalibrationConfig c = load_calibration_config(write_config(kGoodConfig).string());
  ASSERT_EQ(c.scenes.size(), 1u);
  EXPECT_EQ(c.scenes[0].path, (dir_ / "scene.toml").lexically_normal().string());
  ASSERT_EQ(c.parameters.size(), 3u);
  EXPECT_EQ(c.parameters[0].scale, 0.01);
  EXPECT_TRUE(std::isnan(c.parameters[1].initial));  // taken from the scene by calibrate()
  EXPECT_TRUE(c.parameters[2].fixed);
  ASSERT_EQ(c.data.size(), 2u);
  EXPECT_EQ(c.data[0].measurement.name, "load");
  EXPECT_EQ(c.data[1].measurement.name, "thick_20mm");
  EXPECT_EQ(c.data[1].measurement.travel_mm, 20.0);
  EXPECT_EQ(c.data[1].weight, 100.0);
  EXPECT_EQ(c.optimizer.method, OptimizerMethod::kGlobalThenLocal);
  EXPECT_EQ(c.optimizer.global.seed, 42u);
  EXPECT_EQ(c.optimizer.global.max_evaluations, 50);
  EXPECT_EQ(c.optimizer.fd.method, FdMethod::kRidders);
  EXPECT_EQ(c.optimizer.least_squares.max_iterations, 20);
  EXPECT_EQ(c.forward.tolerance, 1e-10);
  ASSERT_EQ(c.forward.overrides.size(), 1u);
  EXPECT_EQ(c.forward.overrides[0].first, "blank.elements");
  EXPECT_EQ(c.forward.overrides[0].second, "24");
  EXPECT_EQ(c.output_directory, "calib_out");
}

TEST_F(ConfigTest, GoodConfigRunsAndFillsDefaultsFromTheScene) {
  const CalibrationConfig c = load_calibration_config(write_config(kGoodConfig).string());
  CalibrationOptions options;
  options.write_report = false;
  const auto result = calibrate(c, options, StretchingFake{});
  EXPECT_EQ(result.parameters[1].spec.initial, 500.0);  // K_MPa from the scene
  EXPECT_EQ(result.parameters[1].spec.scale, 500.0);
  EXPECT_EQ(result.parameters[2].value, 0.01);  // eps0 fixed at the scene's value
  EXPECT_TRUE(result.global_search_used);
  EXPECT_LE(result.global.evaluations, 50);
}

TEST_F(ConfigTest, UnknownKeyNamesFileLineAndKey) {
  const std::string error = error_of(replace(kGoodConfig, "fixed = true", "fixd = true"));
  EXPECT_NE(error.find("calibrate.toml:14: unknown key 'parameter.fixd'"), std::string::npos)
      << error;
  EXPECT_EQ(calls_, 0);
}

TEST_F(ConfigTest, WrongTypeNamesTheKey) {
  const std::string error = error_of(replace(kGoodConfig, "sigma = 50.0", "sigma = \"50\""));
  EXPECT_NE(error.find("key 'data.sigma': must be a number"), std::string::npos) << error;
  EXPECT_EQ(calls_, 0);
}

TEST_F(ConfigTest, TomlSyntaxErrorHasLineAndColumn) {
  const std::string error = error_of("scene = \n");
  EXPECT_NE(error.find("calibrate.toml:1:"), std::string::npos) << error;
}

TEST_F(ConfigTest, BadConfigurationsFailBeforeAnyForwardRun) {
  struct Case {
    const char* name;
    std::string config;
    const char* expected;
  };
  const std::string good = kGoodConfig;
  write_file(dir_ / "empty.csv", "");
  write_file(dir_ / "header_only.csv",
             "# source: t\n# units: mm, N\npunch_travel_mm,punch_force_N\n");
  write_file(dir_ / "non_monotone.csv",
             "# source: t\n# units: mm, N\npunch_travel_mm,punch_force_N\n1,1\n3,2\n2,3\n");
  write_file(dir_ / "no_units.csv", "# source: t\npunch_travel_mm,punch_force_N\n1,1\n");
  write_file(dir_ / "flat.csv",
             "# source: t\n# units: mm, N\npunch_travel_mm,punch_force_N\n1,5\n2,5\n");
  write_file(dir_ / "too_far.csv",
             "# source: t\n# units: mm, N\npunch_travel_mm,punch_force_N\n1,1\n45,2\n");
  const Case cases[] = {
      {"unknown parameter", replace(good, "material.hardening.K_MPa", "material.hardening.KK"),
       "parameter 'material.hardening.KK' is not a number in the scene"},
      {"unknown tool", replace(good, "tool.punch.friction", "tool.ram.friction"),
       "tool.ram.friction"},
      {"bounds exclude start", replace(good, "initial = 0.05", "initial = 0.7"),
       "bounds [0, 0.5] exclude the initial value 0.7"},
      {"scene default outside bounds", replace(good, "lower = 100.0", "lower = 600.0"),
       "exclude the initial value 500"},
      {"negative scale", replace(good, "scale = 0.01", "scale = -1"),
       "key 'parameter.scale': -1 is out of range (0, inf)"},
      {"duplicate parameter", replace(good, "material.hardening.K_MPa", "tool.punch.friction"),
       "listed twice"},
      {"empty csv", replace(good, "file = \"load.csv\"", "file = \"empty.csv\""), "empty.csv"},
      {"header only", replace(good, "file = \"load.csv\"", "file = \"header_only.csv\""),
       "no data rows"},
      {"non-monotone csv", replace(good, "file = \"load.csv\"", "file = \"non_monotone.csv\""),
       "non_monotone.csv:6: punch_travel_mm = 2 does not increase"},
      {"units missing", replace(good, "file = \"load.csv\"", "file = \"no_units.csv\""),
       "# units:"},
      {"missing file", replace(good, "file = \"load.csv\"", "file = \"nope.csv\""), "cannot open"},
      {"no weight on a flat curve",
       replace(replace(good, "sigma = 50.0", ""), "file = \"load.csv\"", "file = \"flat.csv\""),
       "its measured values do not vary"},
      {"profile without travel", replace(good, "travel_mm = 20", ""), "needs travel_mm"},
      {"travel beyond the scene", replace(good, "travel_mm = 20", "travel_mm = 40"),
       "punch_travel_mm"},
      {"load beyond the scene", replace(good, "file = \"load.csv\"", "file = \"too_far.csv\""),
       "needs 45 mm of punch travel"},
      {"unknown kind", replace(good, "kind = \"load_travel\"", "kind = \"load\""),
       "key 'data.kind': 'load' is not one of load_travel, thickness_strain, "
       "circumferential_strain"},
      {"unknown method", replace(good, "global_then_local", "simplex"), "simplex"},
      {"global without bounds", replace(good, "upper = 1000.0", ""), "finite lower and upper"},
      {"bad scene override", replace(good, "\"blank.elements\" = 24", "\"blank.elementz\" = 24"),
       "blank.elementz"},
      {"missing scene", replace(good, "scene.toml", "nothing.toml"), "nothing.toml"},
  };
  for (const auto& c : cases) {
    const std::string error = error_of(c.config);
    EXPECT_NE(error, "") << c.name;
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.name << ": " << error;
    EXPECT_EQ(calls_, 0) << c.name;
  }
}

TEST_F(ConfigTest, BoundTheSceneRejectsFailsBeforeAnyRun) {
  CalibrationConfig c = load_calibration_config(write_config(kGoodConfig).string());
  c.parameters[0].lower = -0.1;  // friction must be >= 0 in the scene
  std::atomic<int> calls{0};
  StretchingFake fake;
  fake.calls = &calls;
  CalibrationOptions options;
  options.write_report = false;
  try {
    calibrate(c, options, fake);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tool.punch.friction = -0.1"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace vs
