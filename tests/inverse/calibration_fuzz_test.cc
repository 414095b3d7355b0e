// Generated malformed calibration inputs (configs and measurement files): loading and the checks
// before the fit either pass or throw InputError with one line; never another exception, never
// a signal, and no forward run before every input error is found. Bounded in time.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "calibrate.h"
#include "calibration_config.h"
#include "core/error.h"
#include "inverse_test_support.h"
#include "scene/fuzz_mutate.h"
#include "scene/load_scene.h"
#include "scene/toml_guard.h"

namespace vs {
namespace {

using namespace vs::testing;

constexpr const char* kConfig = R"(scene = "scene.toml"
[[parameter]]
address = "tool.punch.friction"
initial = 0.05
lower = 0.0
upper = 0.5
[[parameter]]
address = "material.hardening.K_MPa"
lower = 100.0
upper = 1000.0
[[data]]
kind = "load_travel"
file = "load.csv"
sigma = 50.0
[[data]]
kind = "thickness_strain"
file = "thick.csv"
travel_mm = 20
sigma = 0.01
[optimizer]
max_iterations = 3
[forward.set]
"blank.elements" = 24
)";

class CalibrationFuzz : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_dir();
    write_scene(dir_);
    write_file(dir_ / "load.csv", kLoadCsv);
    write_file(dir_ / "thick.csv", kThickCsv);
  }

  // "ok" if the config loads and the fit runs, else the InputError message; any other
  // exception fails the test. Input errors must come before the first forward run.
  std::string outcome(const std::string& config_text) {
    write_file(dir_ / "calibrate.toml", config_text);
    std::atomic<int> calls{0};
    try {
      const CalibrationConfig config = load_calibration_config((dir_ / "calibrate.toml").string());
      CalibrationOptions options;
      options.write_report = false;
      StretchingFake fake;
      fake.calls = &calls;
      calibrate(config, options, fake);
    } catch (const InputError& e) {
      EXPECT_EQ(calls, 0) << e.what();
      return e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << typeid(e).name() << ": " << e.what() << "\n--- config ---\n" << config_text;
      return "exception";
    }
    return "ok";
  }

  // Mutations of `config` (seeded, at most max_cases or 1.5 s): each loads and runs or gives one
  // line; at least min_cases ran and a quarter of them were errors.
  void expect_mutations_give_one_line(const std::string& config, unsigned seed, int max_cases,
                                      int min_cases) {
    std::mt19937 rng(seed);
    const auto start = std::chrono::steady_clock::now();
    int cases = 0, errors = 0;
    while (cases < max_cases &&
           std::chrono::steady_clock::now() - start < std::chrono::milliseconds(1500)) {
      const std::string text = mutate_toml(config, rng);
      ++cases;
      const std::string message = outcome(text);
      if (message == "ok") continue;
      ++errors;
      EXPECT_EQ(message.find('\n'), std::string::npos) << "case " << cases << ": " << message;
      EXPECT_LT(message.size(), 600u) << "case " << cases << ": " << message;
    }
    EXPECT_GT(cases, min_cases);
    EXPECT_GT(errors, cases / 4);
  }

  fs::path dir_;
};

TEST_F(CalibrationFuzz, TheUnmodifiedConfigRuns) { EXPECT_EQ(outcome(kConfig), "ok"); }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST_F(CalibrationFuzz, ParameterValuesThatWouldBeSilentlyReplacedAreErrors) {
  const std::string c = kConfig;
  EXPECT_NE(outcome(replaced(c, "initial = 0.05", "initial = nan"))
                .find("calibrate.toml:4: key 'parameter.initial': must be a number, got nan"),
            std::string::npos);
  EXPECT_NE(outcome(replaced(c, "initial = 0.05", "initial = inf"))
                .find("must be a finite number, got inf (omit it to start from the scene's value)"),
            std::string::npos);
  EXPECT_NE(outcome(replaced(c, "lower = 0.0", "lower = nan")).find("key 'parameter.lower'"),
            std::string::npos);
  EXPECT_NE(outcome(replaced(c, "initial = 0.05", "initial = 0.05\nscale = 0"))
                .find("key 'parameter.scale': 0 is out of range (0, inf)"),
            std::string::npos);
}

TEST_F(CalibrationFuzz, IntegerKeysCannotBeCalibrated) {
  const std::string message = outcome(replaced(
      kConfig, "address = \"tool.punch.friction\"\ninitial = 0.05\nlower = 0.0\nupper = 0.5",
      "address = \"blank.elements\"\nlower = 10\nupper = 40"));
  EXPECT_NE(message.find("calibrate.toml:2: parameter 'blank.elements' is an integer key: integer "
                         "keys cannot be calibrated"),
            std::string::npos)
      << message;
}

TEST_F(CalibrationFuzz, TheSameFileUnderTwoNamesIsAnError) {
  const std::string message = outcome(std::string(kConfig) +
                                      "[[data]]\nkind = \"load_travel\"\nfile = \"./load.csv\"\n"
                                      "sigma = 50.0\nname = \"load_again\"\n");
  EXPECT_NE(message.find("data set 'load_again' reads"), std::string::npos) << message;
  EXPECT_NE(message.find("which data set 'load' (" + (dir_ / "calibrate.toml").string() +
                         ":11) reads already: its points would count twice"),
            std::string::npos)
      << message;
}

TEST_F(CalibrationFuzz, DataWithoutSigmaGetTheRelativeDefaultAndTheReportSaysSo) {
  write_file(dir_ / "calibrate.toml", replaced(kConfig, "sigma = 50.0\n", ""));
  const CalibrationConfig config = load_calibration_config((dir_ / "calibrate.toml").string());
  const DataSigma sigma = data_set_sigma(config.data[0]);
  EXPECT_DOUBLE_EQ(sigma.sigma, 0.01 * (300.0 - 100.0));  // 1 % of the measured range
  CalibrationOptions options;
  options.output_directory = (dir_ / "out").string();
  const CalibrationResult result = calibrate(config, options, StretchingFake{});
  ASSERT_EQ(result.data_weighting.size(), 2u);
  EXPECT_TRUE(result.data_weighting[0].relative_default);
  EXPECT_FALSE(result.data_weighting[1].relative_default);
  EXPECT_NE(result.brief_report().find("data load: sigma = 2 N (default: 1 % of the measured "
                                       "range 200 N; set sigma to state it)"),
            std::string::npos)
      << result.brief_report();
  std::ifstream in(dir_ / "out" / "calibration.json");
  std::stringstream json;
  json << in.rdbuf();
  EXPECT_NE(json.str().find("\"relative_default\": true"), std::string::npos);
}

// identified_<scene>.toml: the scene with the identified values written in, as the fit ran it
// (its [forward.set] edits included); it loads as a scene and holds every identified value.
TEST_F(CalibrationFuzz, TheIdentifiedSceneLoadsWithTheIdentifiedValues) {
  write_file(dir_ / "calibrate.toml", kConfig);
  const CalibrationConfig config = load_calibration_config((dir_ / "calibrate.toml").string());
  CalibrationOptions options;
  options.output_directory = (dir_ / "out").string();
  const CalibrationResult result = calibrate(config, options, StretchingFake{});
  ASSERT_NE(result.termination, CalibrationTermination::kFailed) << result.message;
  ASSERT_EQ(result.identified_scenes.size(), 1u);
  const Scene scene = load_scene((dir_ / "out" / "identified_scene.toml").string());
  ASSERT_EQ(result.parameters.size(), 2u);
  EXPECT_EQ(scene.tools.at(0).friction, result.parameters[0].value);
  EXPECT_EQ(scene.material.hardening.K_MPa, result.parameters[1].value);
  EXPECT_EQ(scene.blank.elements, 24);                            // [forward.set]
  EXPECT_EQ(scene.numerics.tolerance, config.forward.tolerance);  // the fit's forward setting
  // Its run folder lies beside the report, not on the base scene's.
  EXPECT_EQ(scene.output.directory, (dir_ / "out" / "run_identified_scene").string());
  std::ifstream in(dir_ / "out" / "identified_scene.toml");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("#   tool.punch.friction = "), std::string::npos) << text.str();
}

// Files written for a failed calibration: no NaN, no null, the reason stated.
void expect_clean_failed_report(const fs::path& out, const std::string& reason) {
  std::ifstream json_in(out / "calibration.json");
  std::stringstream json;
  json << json_in.rdbuf();
  EXPECT_EQ(json.str().find(": null"), std::string::npos) << json.str();
  EXPECT_EQ(json.str().find("nan"), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"termination\": \"failed\""), std::string::npos);
  EXPECT_NE(json.str().find("\"failure\": \""), std::string::npos);
  EXPECT_NE(json.str().find(reason), std::string::npos) << json.str();
  std::ifstream csv_in(out / "evaluations.csv");
  std::stringstream csv;
  csv << csv_in.rdbuf();
  EXPECT_EQ(csv.str().find("nan"), std::string::npos) << csv.str();
  EXPECT_NE(csv.str().find(",failed,,"), std::string::npos) << csv.str();
}

TEST_F(CalibrationFuzz, AFitWhoseForwardRunsAllFailStopsWithTheRunsReason) {
  const CalibrationConfig config = [&] {
    write_file(dir_ / "calibrate.toml", kConfig);
    return load_calibration_config((dir_ / "calibrate.toml").string());
  }();
  CalibrationOptions options;
  options.output_directory = (dir_ / "out").string();
  StretchingFake fake;
  fake.fail_above_friction = -1.0;  // every run fails
  const CalibrationResult result = calibrate(config, options, fake);
  EXPECT_EQ(result.termination, CalibrationTermination::kFailed);
  EXPECT_EQ(result.evaluations.size(), 1u);  // stopped before the fit
  EXPECT_EQ(result.message,
            "the forward run at the initial parameters fails: " + (dir_ / "scene.toml").string() +
                ": fake: no convergence at high friction");
  EXPECT_EQ(result.brief_report().find("nan"), std::string::npos) << result.brief_report();
  expect_clean_failed_report(dir_ / "out", "fake: no convergence at high friction");
}

// Runs succeed only at the start: every finite-difference run fails, Ceres cannot take a step.
struct OnlyTheStartRuns {
  double start = 0.05;
  RunResult operator()(const Scene& scene) const {
    StretchingFake fake;
    fake.fail_above_friction = punch_friction(scene) == start ? INFINITY : -1.0;
    return fake(scene);
  }
};

TEST_F(CalibrationFuzz, AFitWhoseDerivativesAllFailIsAFailureWithoutNaN) {
  write_file(dir_ / "calibrate.toml",
             replaced(kConfig,
                      "address = \"material.hardening.K_MPa\"\nlower = 100.0\nupper = "
                      "1000.0",
                      "address = \"material.hardening.K_MPa\"\nfixed = true"));
  const CalibrationConfig config = load_calibration_config((dir_ / "calibrate.toml").string());
  CalibrationOptions options;
  options.output_directory = (dir_ / "out").string();
  const CalibrationResult result = calibrate(config, options, OnlyTheStartRuns{});
  EXPECT_EQ(result.termination, CalibrationTermination::kFailed) << result.message;
  EXPECT_EQ(result.message.find('\n'), std::string::npos);
  EXPECT_EQ(result.brief_report().find("nan"), std::string::npos) << result.brief_report();
  expect_clean_failed_report(dir_ / "out", "fake: no convergence at high friction");
}

TEST_F(CalibrationFuzz, DeepNestingIsAnErrorNamingTheLine) {
  for (int depth : {kMaxTomlNesting + 1, 100000}) {
    const std::string dotted = "a" + repeat(".a", depth - 1);
    for (const std::string& tail :
         {dotted + " = 1\n", "[" + dotted + "]\n", "[[" + dotted + "]]\n",
          "[forward.set]\n\"x\" = " + repeat("[", depth) + repeat("]", depth) + "\n"}) {
      const std::string message = outcome(std::string(kConfig) + tail);
      EXPECT_NE(message.find("calibrate.toml:2"), std::string::npos) << message.substr(0, 200);
      EXPECT_NE(message.find("nested deeper than 64 levels"), std::string::npos)
          << message.substr(0, 200);
    }
  }
}

constexpr const char* kDiscrepancy = R"([[discrepancy]]
name = "continuum"
set = { "tool.punch.friction" = 0.0, "material.hardening.K_MPa" = 450.0, "blank.elements" = 30 }
files = { load = "ref_load.csv", thick = "ref_thick.csv" }
[[model_form]]
name = "uncorrected"
discrepancy = []
)";

void write_references(const fs::path& dir) {
  write_file(dir / "ref_load.csv",
             "# source: test\n# units: mm, N\npunch_travel_mm,punch_force_N\n0,0\n4,420\n");
  write_file(dir / "ref_thick.csv",
             "# source: test\n# units: mm, 1\nr0_mm,eps_thickness\n0,-0.12\n25,-0.2\n");
}

// A reference run that fails: the calibration stops before the fit, with the reason, and its
// report has no NaN or null.
TEST_F(CalibrationFuzz, AFailedReferenceRunStopsWithACleanReport) {
  write_references(dir_);
  write_file(dir_ / "calibrate.toml",
             replaced(std::string(kConfig) + kDiscrepancy, "\"tool.punch.friction\" = 0.0",
                      "\"tool.punch.friction\" = 0.4"));
  const CalibrationConfig config = load_calibration_config((dir_ / "calibrate.toml").string());
  CalibrationOptions options;
  options.output_directory = (dir_ / "out").string();
  StretchingFake fake;
  fake.fail_above_friction = 0.3;
  const CalibrationResult result = calibrate(config, options, fake);
  EXPECT_EQ(result.termination, CalibrationTermination::kFailed);
  EXPECT_TRUE(result.evaluations.empty());
  EXPECT_EQ(result.message,
            "discrepancy 'continuum': the forward run at its parameters gives no curve for load: "
            "fake: no convergence at high friction");
  EXPECT_EQ(result.brief_report().find("nan"), std::string::npos) << result.brief_report();
  std::ifstream json_in(dir_ / "out" / "calibration.json");
  std::stringstream json;
  json << json_in.rdbuf();
  EXPECT_EQ(json.str().find(": null"), std::string::npos) << json.str();
  EXPECT_EQ(json.str().find("nan"), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"termination\": \"failed\""), std::string::npos);
  EXPECT_NE(json.str().find("\"ok\": false"), std::string::npos) << json.str();
}

TEST_F(CalibrationFuzz, MutatedConfigsLoadOrGiveOneLine) {
  expect_mutations_give_one_line(kConfig, 17, 2000, 50);
}

TEST_F(CalibrationFuzz, MutatedDiscrepancyConfigsLoadOrGiveOneLine) {
  write_references(dir_);
  const std::string config = std::string(kConfig) + kDiscrepancy;
  ASSERT_EQ(outcome(config), "ok");
  expect_mutations_give_one_line(config, 23, 1000, 30);
}

}  // namespace
}  // namespace vs
