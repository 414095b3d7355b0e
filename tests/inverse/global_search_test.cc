#include "global_search.h"

#include <gtest/gtest.h>

#include "calibrate.h"
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

}  // namespace
}  // namespace vs
