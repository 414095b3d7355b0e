// The calibration toolkit on the 3D shell solver (issue 13): vs::simulate is the calibration's
// forward model for every geometry, so a shell3d scene calibrates like an axisymmetric one.
// Twin experiment on the quarter disc of paper example 4a (data/scenes/ex4a_quarter_disc_
// sticking.toml) at 4 divisions (48 MITC9 elements, 1 085 unknowns) with Coulomb friction 0.2 and
// Swift K = 589 MPa, 10 mm of travel: synthetic load curve and thickness-strain profiles along
// the x axis at 5 and 10 mm, friction and K recovered from starts 30 % off.
// The numerics are the 3D speed setting of experiments/05_shell3d (travel step 0.035 element
// sizes, strain-rate cut-off 1e-2) for CI time; data and fits share them (a twin experiment
// tests the calibration machinery on the 3D model, not the model against reality).
#include <fmt/format.h>
#include <gtest/gtest.h>

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
    std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml";
constexpr double kFriction = 0.2, kK_MPa = 589.0;

ForwardSettings settings() {
  ForwardSettings f;
  f.tolerance = 1e-8;
  f.overrides = {{"blank.divisions", "4"},
                 {"process.punch_travel_mm", "10"},
                 {"process.output_travels_mm", "[5, 10]"},
                 {"numerics.max_travel_increment_per_length", "0.035"},
                 {"numerics.strain_rate_cutoff", "1e-2"}};
  return f;
}

std::vector<Measurement> synthetic_data() {
  toml::table table = read_scene_table(kScene);
  for (const auto& [address, text] : settings().overrides) {
    set_scene_value_from_text(table, address, text);
  }
  set_scene_number(table, "numerics.tolerance", settings().tolerance);
  set_scene_number(table, "tool.punch.friction", kFriction);
  set_scene_number(table, "material.hardening.K_MPa", kK_MPa);
  const Scene scene = scene_from_table(table, kScene, "");
  const RunResult run = make_default_forward_model()(scene);
  EXPECT_TRUE(run.completed()) << run.message;
  EXPECT_EQ(run.geometry, Geometry::kShell3d);
  std::vector<double> travels, radii;
  for (int i = 1; i <= 10; ++i) travels.push_back(i);
  for (int i = 0; i <= 11; ++i) radii.push_back(5.0 * i);  // 0..55 mm along the x axis
  return make_synthetic_measurements(
      scene, run,
      {{MeasurementKind::kLoadTravel, "load", 0.0, travels, 0.0, 0.0},
       {MeasurementKind::kThicknessStrain, "thick_5mm", 5.0, radii, 0.0, 0.0},
       {MeasurementKind::kThicknessStrain, "thick_10mm", 10.0, radii, 0.0, 0.0}},
      1);
}

// Friction starts 30 % low, K 30 % high. Measured (Nov 2026, loaded 2-core machine): both
// recovered to 1e-9 with parameter_tolerance 1e-10 in 26 iterations / 78 forward runs (from x0.7
// for both); the cost reaches the forward solver's noise floor (~1e-15) after 8 iterations and
// the default tolerances then creep on, so the test stops at a parameter step of 1e-6. With the
// noise-floor stop (25 Nov 2026): 4 iterations, 25 forward runs, both within 1e-5, "stopped at
// the noise floor".
TEST(Calibration3d, FrictionAndKFromStarts30PercentOff) {
  const std::vector<Measurement> data = synthetic_data();
  ASSERT_EQ(data.size(), 3u);
  {
    CalibrationConfig c;
    c.scenes = {{"scene", kScene, "3D system test"}};
    c.forward = settings();
    c.parameters = {
        testing::param("tool.punch.friction", kFriction * 0.7, 0.0, 0.6, 0.2, false),
        testing::param("material.hardening.K_MPa", kK_MPa * 1.3, 100.0, 2000.0, 500.0, false)};
    // About 1 % of each curve as its scale (noise-free data).
    const double sigma[] = {100.0, 0.001, 0.002};
    for (std::size_t k = 0; k < data.size(); ++k) {
      DataSpec d;
      d.measurement = data[k];
      d.sigma = sigma[k];
      d.where = "3D system test";
      c.data.push_back(d);
    }
    c.optimizer.threads = 2;
    c.optimizer.fd.relative_step = 0.05;
    c.optimizer.least_squares.parameter_tolerance = 1e-6;
    CalibrationOptions o;
    o.write_report = false;
    o.progress = [](const std::string& line) { fmt::print("    {}\n", line); };
    const CalibrationResult r = calibrate(c, o, make_default_forward_model());
    fmt::print("{} forward runs, {:.1f} s wall\n{}", r.forward_runs, r.wall_time_s,
               r.brief_report());
    ASSERT_NE(r.termination, CalibrationTermination::kFailed) << r.message;
    ASSERT_EQ(r.parameters.size(), 2u);
    EXPECT_NEAR(r.parameters[0].value / kFriction, 1.0, 0.01) << "friction";
    EXPECT_NEAR(r.parameters[1].value / kK_MPa, 1.0, 0.01) << "K";
  }
}

}  // namespace
}  // namespace vs
