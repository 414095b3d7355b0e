// The calibration toolkit on the real axisymmetric solver (issue 4): twin experiments on the
// hemispherical stretching scene (data/scenes/ex1_hemispherical_stretching.toml) with a coarse
// mesh (24 elements) and 20 mm of travel.
//
// These tests hold because the forward map is smooth in the parameters. It was not while the
// travel step was 0.25 mm: the explicit (Heun) geometry update was then beyond its stability
// limit, the deformation mechanism of the nearly rigid outer free region switched from step to
// step, and a friction change of 2e-4 moved the punch force by up to 1 % and the thickness strain
// by 1e-3, non-monotonically; the four-parameter fit landed 1-10 % off. With the travel step
// capped at 0.025 element lengths (numerics.max_travel_increment_per_length, the default) the
// same sweep moves smoothly (experiments/06_step_stability), and the fits below land within
// 0.7 %. relative_step = 0.05 is kept (numerics.md section 5.3).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "calibrate.h"
#include "default_forward_model.h"
#include "inverse/inverse_test_support.h"
#include "measurement.h"
#include "scene/load_scene.h"
#include "scene/scene_table.h"
#include "synthetic.h"

namespace vs {
namespace {

const std::string kScene =
    std::string(VS_SOURCE_DIR) + "/data/scenes/ex1_hemispherical_stretching.toml";

struct Truth {
  double friction = 0.1;
  double K_MPa = 589.0;
  double n = 0.216;
  double r_value = 1.5;
};

// The scene edits of every run here; the calibration applies the same ones (ForwardSettings),
// so synthetic data and fits come from one model.
ForwardSettings coarse() {
  ForwardSettings f;
  f.tolerance = 1e-8;
  f.overrides = {{"blank.elements", "24"}, {"process.punch_travel_mm", "20"}};
  return f;
}

Scene truth_scene(const Truth& t) {
  toml::table table = read_scene_table(kScene);
  for (const auto& [address, text] : coarse().overrides) {
    set_scene_value_from_text(table, address, text);
  }
  set_scene_number(table, "numerics.tolerance", coarse().tolerance);
  set_scene_number(table, "tool.punch.friction", t.friction);
  set_scene_number(table, "material.hardening.K_MPa", t.K_MPa);
  set_scene_number(table, "material.hardening.n", t.n);
  set_scene_number(table, "material.r_value", t.r_value);
  set_scene_value_from_text(table, "process.output_travels_mm", "[10, 20]");
  set_scene_value_from_text(table, "output.history", "false");
  return scene_from_table(table, kScene, "");
}

// Load at 1..20 mm, thickness strain at 10 and 20 mm travel (r0 = 0..55 mm every 2.5 mm).
std::vector<Measurement> synthetic(const Truth& t, double noise_relative, unsigned long long seed) {
  const Scene scene = truth_scene(t);
  const RunResult run = make_default_forward_model()(scene);
  EXPECT_TRUE(run.completed()) << run.message;
  std::vector<double> travels, radii;
  for (int i = 1; i <= 20; ++i) travels.push_back(i);
  for (int i = 0; i <= 22; ++i) radii.push_back(2.5 * i);
  return make_synthetic_measurements(
      scene, run,
      {{MeasurementKind::kLoadTravel, "load", 0.0, travels, noise_relative, 0.0},
       {MeasurementKind::kThicknessStrain, "thick_10mm", 10.0, radii, noise_relative, 0.0},
       {MeasurementKind::kThicknessStrain, "thick_20mm", 20.0, radii, noise_relative, 0.0}},
      seed);
}

// The bundled sets of data/calibration/: name prefix, noise (relative to each curve's maximum)
// and seed.
struct BundledSet {
  std::string prefix;
  double noise;
  unsigned long long seed;
};
const std::vector<BundledSet> kBundledSets = {{"synthetic_ex1_clean", 0.0, 1},
                                              {"synthetic_ex1_noise1pct_seed17", 0.01, 17}};

std::filesystem::path bundled_dir() {
  return std::filesystem::path(VS_SOURCE_DIR) / "data" / "calibration";
}

// Regenerates the synthetic data sets in data/calibration/ (see its README.md): the same runs as
// synthetic() above, noise-free and with 1 % Gaussian noise (seed 17). Disabled because it writes
// into the source tree; run it with the one command data/calibration/regenerate.sh (which builds
// vs_system_tests and runs this test). VS_CALIBRATION_DATA_DIR redirects the output (default:
// <source>/data/calibration).
TEST(CalibrationSystem, DISABLED_WriteSyntheticDataSets) {
  const char* dir_env = std::getenv("VS_CALIBRATION_DATA_DIR");
  const std::filesystem::path dir = dir_env ? std::filesystem::path(dir_env) : bundled_dir();
  std::filesystem::create_directories(dir);
  const Truth truth;
  const std::string settings =
      "blank.elements=24 process.punch_travel_mm=20 numerics.tolerance=1e-8 "
      "process.output_travels_mm=[10, 20], the scene file otherwise unchanged";
  const std::string generator =
      "data/calibration/regenerate.sh (tests/system/calibration_system_test.cc "
      "CalibrationSystem.DISABLED_WriteSyntheticDataSets)";
  for (const BundledSet& set : kBundledSets) {
    for (Measurement m : synthetic(truth, set.noise, set.seed)) {
      // Replace the absolute scene path in the source line by the repository-relative one.
      for (auto& [key, value] : m.provenance) {
        if (key == "source") {
          value =
              "SYNTHETIC data, not a measurement: forward solver run of "
              "data/scenes/ex1_hemispherical_stretching.toml (vs::make_synthetic_measurements)";
        }
      }
      m.provenance.emplace_back("forward settings", settings);
      m.provenance.emplace_back("generator", generator);
      const auto path = dir / fmt::format("{}_{}.csv", set.prefix, m.name);
      write_measurement_csv(m, path.string());
      fmt::print("wrote {}\n", path.string());
      // What was written reads back as the same data.
      const Measurement back = read_measurement_csv(path.string(), m.kind);
      EXPECT_EQ(back.y, m.y) << path;
    }
  }
}

// The bundled files must be what the current solver computes at the truth: data made by an
// older solver version fit to other parameters (issue 16: n +0.7 %, R +0.9 %, friction 0.1049
// instead of 0.1, with intervals excluding the truth). The forward map is smooth to ~1e-8 of each
// curve at the calibration tolerance (experiments/06_step_stability); 1e-6 of the curve's
// largest value (1e-4 of the 1 % sigma the configs state) is far below anything a fit can see
// and far above the solver's convergence noise. The noisy sets are the clean curve plus a seeded,
// platform-independent noise stream, so they are checked the same way.
TEST(CalibrationSystem, BundledSyntheticDataMatchTheCurrentSolver) {
  const Truth truth;
  for (const BundledSet& set : kBundledSets) {
    for (const Measurement& now : synthetic(truth, set.noise, set.seed)) {
      const auto path = bundled_dir() / fmt::format("{}_{}.csv", set.prefix, now.name);
      const Measurement bundled = read_measurement_csv(path.string(), now.kind);
      ASSERT_EQ(bundled.x, now.x) << path;
      double largest = 0.0, worst = 0.0;
      for (std::size_t i = 0; i < now.y.size(); ++i) {
        largest = std::max(largest, std::abs(now.y[i]));
        worst = std::max(worst, std::abs(bundled.y[i] - now.y[i]));
      }
      EXPECT_LE(worst, 1e-6 * largest)
          << path.string() << " differs from the current solver at the truth by " << worst
          << " (largest value " << largest
          << "): the forward solver changed; regenerate the bundled data with "
             "data/calibration/regenerate.sh and update the figures in data/calibration/README.md";
    }
  }
}

using testing::param;

// The four parameters of the issue; `free` picks which are identified (others fixed at truth).
CalibrationConfig config_for(const std::vector<Measurement>& data, const Truth& t, double start,
                             const std::vector<bool>& free = {true, true, true, true}) {
  CalibrationConfig c;
  c.scenes = {{"scene", kScene, "system test"}};
  c.forward = coarse();
  auto initial = [&](double truth, int i) { return free[i] ? truth * start : truth; };
  c.parameters = {
      param("tool.punch.friction", initial(t.friction, 0), 0.0, 0.5, 0.1, !free[0]),
      param("material.hardening.K_MPa", initial(t.K_MPa, 1), 100.0, 2000.0, 500.0, !free[1]),
      param("material.hardening.n", initial(t.n, 2), 0.05, 0.6, 0.2, !free[2]),
      param("material.r_value", initial(t.r_value, 3), 0.3, 5.0, 1.0, !free[3])};
  // Noise-free data still need a scale per data set: about 1 % of each curve.
  const double sigma[] = {200.0, 0.002, 0.002};
  for (std::size_t k = 0; k < data.size(); ++k) {
    DataSpec d;
    d.measurement = data[k];
    d.sigma = data[k].point_sigma.empty() ? sigma[k % 3] : 0.0;
    d.where = "system test";
    c.data.push_back(d);
  }
  c.optimizer.threads = 2;
  c.optimizer.fd.relative_step = 0.05;  // see the file comment
  return c;
}

CalibrationOptions options() {
  CalibrationOptions o;
  o.write_report = false;
  o.progress = [](const std::string& line) { fmt::print("    {}\n", line); };
  return o;
}

// The bundled friction-only example, started AT the truth, stays there: the one-line check a
// user would run on the shipped files (0.104874 with the data of an older solver).
TEST(CalibrationSystem, BundledFrictionOnlyExampleStaysAtTheTruth) {
  CalibrationConfig config =
      load_calibration_config((bundled_dir() / "calibrate_friction_only.toml").string());
  ASSERT_EQ(config.parameters.size(), 1u);
  config.parameters[0].initial = Truth{}.friction;
  const auto result = calibrate(config, options(), make_default_forward_model());
  fmt::print("{}", result.brief_report());
  EXPECT_NEAR(result.parameters[0].value, Truth{}.friction, 1e-4 * Truth{}.friction);
}

double truth_of(const Truth& t, const std::string& address) {
  if (address == "tool.punch.friction") return t.friction;
  if (address == "material.hardening.K_MPa") return t.K_MPa;
  if (address == "material.hardening.n") return t.n;
  return t.r_value;
}

void expect_recovered(const CalibrationResult& r, const Truth& t, double tolerance) {
  for (const auto& p : r.parameters) {
    if (p.spec.fixed) continue;
    EXPECT_NEAR(p.value / truth_of(t, p.spec.address), 1.0, tolerance) << p.spec.address;
  }
}

void recover_four_from_two_starts(double tolerance) {
  const Truth truth;
  const auto data = synthetic(truth, 0.0, 1);
  for (double start : {0.7, 1.3}) {
    const auto result =
        calibrate(config_for(data, truth, start), options(), make_default_forward_model());
    // The benchmark figures of the issue: forward runs and wall time of the 4-parameter fit.
    fmt::print("start x{}: {} forward runs, {:.2f} s wall\n{}", start, result.forward_runs,
               result.wall_time_s, result.brief_report());
    EXPECT_NE(result.termination, CalibrationTermination::kFailed) << result.message;
    expect_recovered(result, truth, tolerance);
  }
}

// Measured: x0.7 start -> friction +0.27 %, K +0.17 %, n +0.13 %, R -0.30 % (118 forward runs,
// 25 s); x1.3 -> +0.63 %, +0.21 %, +0.16 %, -0.40 % (84 runs, 18 s).
TEST(CalibrationSystem, FourParametersFromTwoStartsWithin1Percent) {
  recover_four_from_two_starts(0.01);
}

// Seed 17: the truth lies inside every 95 % interval (friction 0.108 [0.089, 0.127], K 618
// [569, 667], n 0.224 [0.211, 0.237], R 1.40 [1.21, 1.59]).
TEST(CalibrationSystem, NoisyDataTruthInsideIntervals) {
  const Truth truth;
  const auto data = synthetic(truth, 0.01, 17);  // 1 % of each curve's maximum, seed 17
  const auto result =
      calibrate(config_for(data, truth, 0.8), options(), make_default_forward_model());
  fmt::print("{}", result.brief_report());
  ASSERT_TRUE(result.uncertainty_available) << result.uncertainty_message;
  for (const auto& u : result.uncertainty.parameters) {
    const double t = truth_of(truth, u.name);
    EXPECT_LE(u.interval_lower, t) << u.name;
    EXPECT_GE(u.interval_upper, t) << u.name;
  }
}

TEST(CalibrationSystem, FrictionAloneFromThicknessProfiles) {
  const Truth truth;
  auto data = synthetic(truth, 0.0, 1);
  data.erase(data.begin());  // profiles only
  const auto result = calibrate(config_for(data, truth, 0.7, {true, false, false, false}),
                                options(), make_default_forward_model());
  fmt::print("{}", result.brief_report());
  expect_recovered(result, truth, 0.01);  // measured: 0.10034
}

TEST(CalibrationSystem, HardeningAloneFromTheLoadCurve) {
  const Truth truth;
  auto data = synthetic(truth, 0.0, 1);
  data.resize(1);  // load curve only
  const auto result = calibrate(config_for(data, truth, 0.8, {false, true, true, false}), options(),
                                make_default_forward_model());
  fmt::print("{}", result.brief_report());
  expect_recovered(result, truth, 0.01);  // measured: K 589.75, n 0.21649
}

TEST(CalibrationSystem, FrictionFromTheLoadCurveAloneIsPoorlyDetermined) {
  const Truth truth;
  auto data = synthetic(truth, 0.01, 5);
  data.resize(1);  // load curve only: it hardly depends on friction (seed paper §5.1)
  const auto result = calibrate(config_for(data, truth, 0.7, {true, true, true, false}), options(),
                                make_default_forward_model());
  fmt::print("{}", result.brief_report());
  ASSERT_TRUE(result.uncertainty_available) << result.uncertainty_message;
  EXPECT_FALSE(result.uncertainty.parameters.at(0).determined);
  EXPECT_FALSE(result.uncertainty.well_determined());
}

}  // namespace
}  // namespace vs
