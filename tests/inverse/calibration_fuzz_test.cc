// Generated malformed calibration inputs (configs and measurement files): loading and the checks
// before the fit either pass or throw InputError with one line; never another exception, never
// a signal, and no forward run before every input error is found. Bounded in time.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <random>
#include <string>

#include "calibrate.h"
#include "calibration_config.h"
#include "core/error.h"
#include "inverse_test_support.h"
#include "scene/fuzz_mutate.h"
#include "scene/toml_guard.h"

namespace vs {
namespace {

using namespace vs::testing;

constexpr const char* kLoadCsv =
    "# source: test\n# units: mm, N\npunch_travel_mm,punch_force_N\n1,100\n2,200\n3,300\n";
constexpr const char* kThickCsv =
    "# source: test\n# units: mm, 1\nr0_mm,eps_thickness\n0,-0.1\n10,-0.2\n20,-0.1\n";

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

  fs::path dir_;
};

TEST_F(CalibrationFuzz, TheUnmodifiedConfigRuns) { EXPECT_EQ(outcome(kConfig), "ok"); }

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

TEST_F(CalibrationFuzz, MutatedConfigsLoadOrGiveOneLine) {
  std::mt19937 rng(17);
  const auto start = std::chrono::steady_clock::now();
  int cases = 0, errors = 0;
  while (cases < 2000 &&
         std::chrono::steady_clock::now() - start < std::chrono::milliseconds(1500)) {
    const std::string text = mutate_toml(kConfig, rng);
    ++cases;
    const std::string message = outcome(text);
    if (message == "ok") continue;
    ++errors;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "case " << cases << ": " << message;
    EXPECT_LT(message.size(), 600u) << "case " << cases << ": " << message;
  }
  EXPECT_GT(cases, 50);
  EXPECT_GT(errors, cases / 4);
}

}  // namespace
}  // namespace vs
