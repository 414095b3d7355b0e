// docs/calibration-reference.md must be the current output of calibration_reference_markdown(),
// and the declaration must be the reader's: every declared key is read, nothing else is.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "calibration_config.h"
#include "calibration_keys.h"
#include "core/error.h"
#include "inverse_test_support.h"

namespace vs {
namespace {

using namespace vs::testing;

const std::string kReferencePath = std::string(VS_SOURCE_DIR) + "/docs/calibration-reference.md";

TEST(CalibrationReference, DocsFileIsUpToDate) {
  std::ifstream in(kReferencePath);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_TRUE(text.str() == calibration_reference_markdown())
      << kReferencePath << " is stale; regenerate with: build/tests/vs_inverse_tests "
      << "--gtest_also_run_disabled_tests --gtest_filter='*RegenerateCalibrationReference*'";
}

TEST(CalibrationReference, EveryKeyIsDocumented) {
  const std::string markdown = calibration_reference_markdown();
  for (const KeySpec& key : calibration_keys()) {
    EXPECT_FALSE(key.doc.empty()) << key.address_in_section();
    EXPECT_NE(markdown.find("| `" + std::string(key.name) + "` |"), std::string::npos)
        << key.address_in_section();
  }
}

// A config that sets every declared key loads: the reader takes each one (an undeclared read
// would throw std::logic_error, an unread declared key would be an unknown key).
TEST(CalibrationReference, EveryDeclaredKeyIsRead) {
  const fs::path dir = scratch_dir();
  write_scene(dir);
  write_file(dir / "load.csv",
             "# source: t\n# units: mm, N\npunch_travel_mm,punch_force_N\n1,100\n2,200\n");
  write_file(dir / "thick.csv", "# source: t\n# units: mm, 1\nR,eps\n0,-0.1\n10,-0.2\n20,-0.1\n");
  write_file(dir / "cup.txt", "0, 34\n45, 33\n90, 35\n");
  write_file(dir / "calibrate.toml", R"([[scene]]
name = "a"
file = "scene.toml"
[[parameter]]
address = "tool.punch.friction"
initial = 0.05
lower = 0.0
upper = 0.5
scale = 0.1
fixed = false
[[data]]
kind = "load_travel"
file = "load.csv"
sigma = 10.0
name = "load"
scene = "a"
[[data]]
kind = "thickness_strain"
file = "thick.csv"
weight = 10.0
relative_sigma = 0.02
travel_mm = 20
scene = "a"
columns = { r0_mm = "R", eps_thickness = "eps" }
[[data]]
kind = "cup_height_profile"
file = "cup.txt"
source = "t"
shape_only = true
sigma = 0.1
scene = "a"
[optimizer]
method = "global_then_local"
max_iterations = 5
function_tolerance = 1e-9
gradient_tolerance = 1e-12
parameter_tolerance = 1e-9
fd = "ridders"
relative_step = 0.01
ridders_levels = 3
threads = 1
global_algorithm = "crs2"
seed = 3
max_evaluations = 10
grid_points = 4
grid_half_width = 0.5
surface_rounds = 2
noise_floor_factor = 10
active_set = false
[uncertainty]
confidence = 0.9
scale_by_residual_variance = false
rank_tolerance = 1e-9
correlation_threshold = 0.9
relative_error_threshold = 0.2
lack_of_fit_significance = 0.05
lack_of_fit_min_rms = 1
lack_of_fit_min_resolutions = 20
[[model_form]]
name = "fine mesh"
set = { "blank.elements" = 40 }
drop_data = ["thick"]
discrepancy = ["continuum"]
[[discrepancy]]
name = "continuum"
set = { "tool.punch.friction" = 0.1 }
files = { load = "load.csv" }
[forward]
tolerance = 1e-8
[forward.set]
"blank.elements" = 24
[output]
directory = "out"
plots = false
)");
  std::string text;
  {
    std::ifstream in(dir / "calibrate.toml");
    std::stringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  for (const KeySpec& key : calibration_keys()) {
    const std::string name(key.name);
    EXPECT_TRUE(text.find("\n" + name + " =") != std::string::npos ||
                text.find("." + name + "]") != std::string::npos)
        << key.address_in_section() << " is not in the test config";
  }
  const CalibrationConfig c = load_calibration_config((dir / "calibrate.toml").string());
  EXPECT_EQ(c.data[1].measurement.x.size(), 3u);
  EXPECT_TRUE(c.data[2].shape_only);
  EXPECT_EQ(c.data[2].measurement.provenance.front().second, "t");
  EXPECT_EQ(c.optimizer.global.algorithm, "crs2");
  EXPECT_EQ(c.optimizer.global.grid_points, 4);
  EXPECT_EQ(c.optimizer.global.surface_rounds, 2);
  EXPECT_EQ(c.optimizer.global.grid_half_width, 0.5);
  EXPECT_EQ(c.model_forms.size(), 1u);
  EXPECT_EQ(c.model_forms[0].discrepancy, std::vector<std::string>{"continuum"});
  ASSERT_EQ(c.discrepancies.size(), 1u);
  EXPECT_EQ(c.discrepancies[0].references.size(), 1u);
}

TEST(CalibrationReference, DefaultsInTheDocsAreTheReadersDefaults) {
  const fs::path dir = scratch_dir();
  write_scene(dir);
  write_file(dir / "load.csv",
             "# source: t\n# units: mm, N\npunch_travel_mm,punch_force_N\n1,100\n2,200\n");
  write_file(dir / "calibrate.toml",
             "scene = \"scene.toml\"\n[[parameter]]\naddress = \"tool.punch.friction\"\n"
             "[[data]]\nkind = \"load_travel\"\nfile = \"load.csv\"\n");
  const CalibrationConfig c = load_calibration_config((dir / "calibrate.toml").string());
  EXPECT_EQ(default_toml_text(*find_calibration_key("optimizer", "relative_step")),
            float_toml_text(c.optimizer.fd.relative_step));
  EXPECT_EQ(default_toml_text(*find_calibration_key("optimizer", "max_iterations")),
            std::to_string(c.optimizer.least_squares.max_iterations));
  EXPECT_EQ(default_toml_text(*find_calibration_key("data", "relative_sigma")),
            float_toml_text(c.data[0].relative_sigma));
  EXPECT_EQ(default_toml_text(*find_calibration_key("optimizer", "noise_floor_factor")),
            float_toml_text(c.optimizer.noise_floor_factor));
  EXPECT_EQ(default_toml_text(*find_calibration_key("uncertainty", "lack_of_fit_min_rms")),
            float_toml_text(c.uncertainty.lack_of_fit.min_rms));
  EXPECT_EQ(default_toml_text(*find_calibration_key("uncertainty", "lack_of_fit_min_resolutions")),
            float_toml_text(c.uncertainty.lack_of_fit.min_resolutions));
  EXPECT_EQ(default_toml_text(*find_calibration_key("forward", "tolerance")),
            float_toml_text(c.forward.tolerance));
  EXPECT_EQ(default_toml_text(*find_calibration_key("output", "directory")),
            "\"" + c.output_directory + "\"");
}

// Run explicitly to rewrite the docs file after changing the declaration.
TEST(CalibrationReference, DISABLED_RegenerateCalibrationReference) {
  std::ofstream(kReferencePath) << calibration_reference_markdown();
}

}  // namespace
}  // namespace vs
