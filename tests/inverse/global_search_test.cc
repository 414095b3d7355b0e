#include "global_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "calibrate.h"
#include "calibration_config.h"
#include "core/error.h"
#include "inverse_test_support.h"
#include "scene/load_scene.h"
#include "synthetic.h"

namespace vs {
namespace {

using namespace vs::testing;

CalibrationConfig poor_start_config(const fs::path& dir) {
  const fs::path scene_file = write_scene(dir);
  Scene scene = load_scene(scene_file.string());
  scene.tools[0].friction = 0.15;
  scene.material.hardening.n = 0.25;
  scene.process.output_travels_mm = {20.0};
  const RunResult run = StretchingFake{}(scene);
  std::vector<double> travels, radii;
  for (int i = 1; i <= 20; ++i) travels.push_back(i);
  for (int i = 0; i <= 24; ++i) radii.push_back(2.0 * i);
  const auto measured = make_synthetic_measurements(
      scene, run,
      {{MeasurementKind::kLoadTravel, "load", 0.0, travels, 0.0, 0.0},
       {MeasurementKind::kThicknessStrain, "thick", 20.0, radii, 0.0, 0.0}},
      1);
  CalibrationConfig config;
  config.scenes = {{"scene", scene_file.string(), "test"}};
  // A start far from the truth: the thinning peak model is far from the data.
  config.parameters = {param("tool.punch.friction", 0.45, 0.0, 0.5, 0.1),
                       param("material.hardening.n", 0.5, 0.05, 0.6, 0.2)};
  config.data = {data_set(measured[0], 100.0), data_set(measured[1], 0.002)};
  config.optimizer.method = OptimizerMethod::kGlobalThenLocal;
  config.optimizer.global.seed = 11;
  config.optimizer.global.max_evaluations = 120;
  return config;
}

TEST(GlobalSearch, IsDeterministicForAFixedSeedAndRespectsTheLimit) {
  const fs::path dir = scratch_dir();
  const auto config = poor_start_config(dir);
  CalibrationOptions options;
  options.write_report = false;
  const auto first = calibrate(config, options, StretchingFake{});
  const auto second = calibrate(config, options, StretchingFake{});
  EXPECT_LE(first.global.evaluations, 120);
  EXPECT_EQ(first.global.evaluations, second.global.evaluations);
  EXPECT_EQ(first.global.x, second.global.x);
  EXPECT_EQ(first.global.cost, second.global.cost);
  EXPECT_EQ(first.free_values(), second.free_values());
  ASSERT_EQ(first.evaluations.size(), second.evaluations.size());
  // ... and the Ceres polish then finds the truth.
  EXPECT_NEAR(first.free_values()[0], 0.15, 1e-6);
  EXPECT_NEAR(first.free_values()[1], 0.25, 1e-6);
}

TEST(GlobalSearch, EveryAlgorithmRunsWithinItsBudget) {
  const fs::path dir = scratch_dir();
  auto config = poor_start_config(dir);
  for (const char* algorithm : {"mlsl_lds", "crs2", "direct", "bobyqa"}) {
    config.optimizer.global.algorithm = algorithm;
    config.optimizer.global.max_evaluations = 40;
    CalibrationOptions options;
    options.write_report = false;
    const auto result = calibrate(config, options, StretchingFake{});
    EXPECT_LE(result.global.evaluations, 40) << algorithm;
    EXPECT_GT(result.global.evaluations, 0) << algorithm;
    EXPECT_LT(result.global.cost, result.initial_cost) << algorithm;
  }
}

// StretchingFake whose punch force carries a deterministic jitter that is not smooth in the
// parameters (a stand-in for a 3D cup's contact events): 0.2 % of the force, changing sign and
// size from one parameter value to the next at the 1e-4 level.
struct JitteryStretchingFake {
  RunResult operator()(const Scene& scene) const {
    RunResult run = StretchingFake{}(scene);
    const double phase = 1e5 * punch_friction(scene) + 3e5 * scene.material.hardening.n;
    for (auto& s : run.steps) s.punch_force_N *= 1.0 + 2e-3 * std::sin(phase + 0.37 * s.step);
    return run;
  }
};

CalibrationConfig surface_config(const fs::path& dir) {
  CalibrationConfig config = poor_start_config(dir);
  // The start off the truth (0.15, 0.25) by 0.02 / 0.005; the grid spans +- half a scale around
  // it (friction 0.12-0.22, n 0.245-0.265: the force is far more sensitive to n).
  config.parameters = {param("tool.punch.friction", 0.17, 0.0, 0.5, 0.1),
                       param("material.hardening.n", 0.255, 0.05, 0.6, 0.02)};
  config.data.resize(1);  // the load curve only: a cost close to quadratic over the grid
  config.optimizer.global.algorithm = "surface";
  config.optimizer.global.grid_half_width = 0.5;
  config.optimizer.global.max_evaluations = 26;
  return config;
}

TEST(GlobalSearch, SurfaceFindsTheMinimumOfTheQuadraticThroughTheGrid) {
  const fs::path dir = scratch_dir();
  const auto config = surface_config(dir);
  CalibrationOptions options;
  options.write_report = false;
  const auto smooth = calibrate(config, options, StretchingFake{});
  EXPECT_EQ(smooth.global.result, "SURFACE_MINIMUM");
  EXPECT_EQ(smooth.global.evaluations, 26);  // 5 x 5 grid + the quadratic's minimum
  // A fifth of the grid's half width from the truth (the cost is not exactly quadratic) ...
  EXPECT_NEAR(smooth.global.x[0], 0.15, 0.01);
  EXPECT_NEAR(smooth.global.x[1], 0.25, 0.002);
  // ... and the polish takes it to the truth.
  EXPECT_NEAR(smooth.free_values()[0], 0.15, 1e-6);
  EXPECT_NEAR(smooth.free_values()[1], 0.25, 1e-6);
  // With the jitter the quadratic still lands there (it averages the noise over the grid), and
  // the scatter about it says the cost is rough.
  const auto jittery = calibrate(config, options, JitteryStretchingFake{});
  EXPECT_EQ(jittery.global.result, "SURFACE_MINIMUM");
  EXPECT_NEAR(jittery.global.x[0], 0.15, 0.01);
  EXPECT_NEAR(jittery.global.x[1], 0.25, 0.002);
  EXPECT_GT(jittery.global.surface_rms, smooth.global.surface_rms);
  // Same input, same bits (the grid runs in parallel batches).
  const auto again = calibrate(config, options, JitteryStretchingFake{});
  EXPECT_EQ(again.global.x, jittery.global.x);
  EXPECT_EQ(again.global.cost, jittery.global.cost);
}

// A grid too wide for the cost's curvature: the quadratic through it misses the minimum of the
// (non-quadratic) cost. A second round, centred there at half the width, comes closer; with the
// jitter it still averages the noise (the grid spans far more than the jitter's scale).
// Measured distances from the truth in parameter scales, smooth / jittery: 1 round 0.24 / 0.23,
// 2 rounds 0.033 / 0.077, 3 rounds 0.0076 / 0.054.
TEST(GlobalSearch, SurfaceRoundsZoomOntoTheMinimum) {
  const fs::path dir = scratch_dir();
  auto config = surface_config(dir);
  config.optimizer.global.grid_half_width = 3.0;
  CalibrationOptions options;
  options.write_report = false;
  auto distance = [](const Eigen::VectorXd& x) {
    return std::hypot((x[0] - 0.15) / 0.1, (x[1] - 0.25) / 0.02);  // in parameter scales
  };
  double one_round = 0.0, two_rounds = 0.0;
  for (int rounds : {1, 2, 3}) {
    config.optimizer.global.surface_rounds = rounds;
    config.optimizer.global.max_evaluations = 26 * rounds;
    for (bool jitter : {false, true}) {
      SCOPED_TRACE(::testing::Message() << rounds << " rounds, jitter " << jitter);
      const auto r = jitter ? calibrate(config, options, JitteryStretchingFake{})
                            : calibrate(config, options, StretchingFake{});
      EXPECT_EQ(r.global.evaluations, 26 * rounds);
      EXPECT_EQ(r.global.result.rfind("SURFACE_MINIMUM", 0), 0u) << r.global.result;
      const double d = distance(r.global.x);
      if (rounds == 1 && !jitter) {
        one_round = d;
        EXPECT_GT(d, 0.1) << "the wide grid must miss for the test to mean anything";
      }
      if (rounds > 1) {
        EXPECT_LT(d, 0.5 * one_round);
      }
      if (rounds == 2 && !jitter) two_rounds = d;
      if (rounds == 3 && !jitter) {
        EXPECT_LT(d, 0.5 * two_rounds);
      }
    }
  }
  std::string why;
  config.optimizer.global.surface_rounds = 0;
  EXPECT_FALSE(config.optimizer.global.IsValid(&why));
  EXPECT_NE(why.find("surface_rounds"), std::string::npos);
}

TEST(GlobalSearch, SurfaceGridMustFitIntoTheEvaluations) {
  const fs::path dir = scratch_dir();
  const fs::path file = dir / "surface.toml";
  {
    std::ofstream f(file);
    f << "scene = \"" << write_scene(dir).string() << "\"\n"
      << "[[parameter]]\naddress = \"tool.punch.friction\"\ninitial = 0.2\nlower = 0.0\n"
      << "upper = 0.5\n"
      << "[[parameter]]\naddress = \"material.hardening.n\"\ninitial = 0.3\nlower = 0.05\n"
      << "upper = 0.6\n"
      << "[[data]]\nname = \"load\"\nkind = \"load_travel\"\nfile = \"load.csv\"\n"
      << "[optimizer]\nmethod = \"global_then_local\"\nglobal_algorithm = \"surface\"\n"
      << "grid_points = 7\nmax_evaluations = 49\n";
  }
  {
    std::ofstream f(dir / "load.csv");
    f << "# source: test\n# units: mm, N\npunch_travel_mm,punch_force_N\n";
    for (int i = 1; i <= 10; ++i) f << i << "," << 100 * i << "\n";
  }
  try {
    load_calibration_config(file.string());
    ADD_FAILURE() << "a 7 x 7 grid with 49 evaluations was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs grid_points^2 + 1 = 50 evaluations"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace vs
