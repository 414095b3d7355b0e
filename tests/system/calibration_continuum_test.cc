// The lack-of-fit diagnostic on a stored continuum reference (issue 15): the CalculiX solution
// of ex1 with punch friction 0.1 (experiments/08_continuum_reference/results/ex1_mu010_r60_l4)
// is something the shell model cannot represent exactly (it thins the pole less, by ~0.01 at
// 25 mm, section 5 of that README). A short fit of friction and K on the thickness-strain
// profile at 25 mm and the load curve must end with the profile's misfit called STRUCTURAL,
// while the same fit on the shell's own curves (synthetic, noise-free) calls nothing structural.
// Coarse mesh (24 elements) and at most a few iterations: a few seconds. And the committed
// section-10 calibration config reproduces the fit its README documents, and its
// discrepancy-corrected twin (section 13) the friction within 5 %.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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
const std::string kResults =
    std::string(VS_SOURCE_DIR) + "/experiments/08_continuum_reference/results/";
const std::string kReference = kResults + "ex1_mu010_r60_l4/";

// Columns `x_name`, `y_name` of a plain CSV (one header line).
void read_columns(const std::string& path, const std::string& x_name, const std::string& y_name,
                  std::vector<double>* x, std::vector<double>* y) {
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::string line;
  // The stored references have CRLF line ends.
  auto next_line = [&in, &line] {
    if (!std::getline(in, line)) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  };
  next_line();
  std::vector<std::string> header;
  std::stringstream hs(line);
  for (std::string cell; std::getline(hs, cell, ',');) header.push_back(cell);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t cx = column(x_name), cy = column(y_name);
  ASSERT_LT(cx, header.size());
  ASSERT_LT(cy, header.size());
  while (next_line()) {
    if (line.empty()) continue;
    std::vector<double> cells;
    std::stringstream ls(line);
    for (std::string cell; std::getline(ls, cell, ',');) cells.push_back(std::stod(cell));
    x->push_back(cells.at(cx));
    y->push_back(cells.at(cy));
  }
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (at <= x[i]) return y[i - 1] + (y[i] - y[i - 1]) * (at - x[i - 1]) / (x[i] - x[i - 1]);
  }
  return y.back();
}

// The continuum's load at 1..25 mm and thickness strain at `travels` for r0 = 0..50 mm.
std::vector<Measurement> continuum_data(const std::string& folder = kReference,
                                        const std::vector<int>& travels = {25}) {
  std::vector<double> t, f;
  read_columns(folder + "load_travel.csv", "punch_travel_mm", "punch_force_N", &t, &f);
  Measurement load;
  load.name = "load";
  load.kind = MeasurementKind::kLoadTravel;
  for (int i = 1; i <= 25; ++i) {
    load.x.push_back(i);
    load.y.push_back(interpolate(t, f, i));
  }
  std::vector<Measurement> data = {load};
  for (int travel : travels) {
    std::vector<double> r0, e;
    read_columns(fmt::format("{}strains_travel_{}mm.csv", folder, travel), "r0_mm", "eps_thickness",
                 &r0, &e);
    Measurement thick;
    thick.name = fmt::format("thick_{}mm", travel);
    thick.kind = MeasurementKind::kThicknessStrain;
    thick.travel_mm = travel;
    for (int i = 0; i <= 20; ++i) {
      thick.x.push_back(2.5 * i);
      thick.y.push_back(interpolate(r0, e, 2.5 * i));
    }
    data.push_back(thick);
  }
  return data;
}

CalibrationConfig config_for(const std::vector<Measurement>& data) {
  CalibrationConfig c;
  c.scenes = {{"scene", kScene, "continuum test"}};
  c.forward.tolerance = 1e-8;
  c.forward.overrides = {
      {"blank.elements", "24"}, {"process.punch_travel_mm", "25"}, {"tool.punch.friction", "0.1"}};
  c.parameters = {testing::param("tool.punch.friction", 0.1, 0.0, 0.5, 0.1),
                  testing::param("material.hardening.K_MPa", 589.0, 100.0, 2000.0, 500.0)};
  const double sigma[] = {200.0, 0.003};  // ~1 % of each curve
  for (std::size_t k = 0; k < data.size(); ++k) {
    c.data.push_back(testing::data_set(data[k], sigma[k]));
  }
  c.optimizer.least_squares.max_iterations = 4;
  c.optimizer.fd.relative_step = 0.05;
  return c;
}

// The committed section-10 config (experiments/08_continuum_reference/calibration: load from
// 10 mm, thickness at 15 and 25 mm, normal-stress term and elastic correction on, 40 elements,
// with its six model-form refits; about 3 s): the figures its README documents. K and n within
// 1 % of the truth (the goal, met); friction -14.8 % (uncorrected: the next test's
// discrepancy correction meets the goal, 5 %), outside its statistical interval and outside the
// model-form range [0.0752, 0.0904] (its upper end from the transverse-shear penalty at 0.3,
// section 14), every data set's misfit structural, and no forward warning at 40 elements.
TEST(CalibrationContinuum, CommittedConfigReproducesItsDocumentedFit) {
  const std::string path = std::string(VS_SOURCE_DIR) +
                           "/experiments/08_continuum_reference/calibration/"
                           "calibrate_ex1_mu010_contact_elastic_from10.toml";
  const auto result =
      calibrate(load_calibration_config(path), vs::testing::quiet(), make_default_forward_model());
  ASSERT_EQ(result.termination, CalibrationTermination::kConverged) << result.message;
  const Eigen::VectorXd v = result.free_values();
  EXPECT_NEAR(v[0], 0.0852, 0.0005);              // friction (truth 0.1)
  EXPECT_LT(std::abs(v[1] / 589.0 - 1.0), 0.01);  // K
  EXPECT_LT(std::abs(v[2] / 0.216 - 1.0), 0.01);  // n
  ASSERT_TRUE(result.uncertainty_available);
  EXPECT_LT(result.uncertainty.parameters[0].interval_upper, 0.1);
  ASSERT_EQ(result.model_form.size(), 6u);
  ASSERT_EQ(result.model_form_ranges.size(), 3u);
  EXPECT_NEAR(result.model_form_ranges[0].lower, 0.0752, 0.0005);
  EXPECT_NEAR(result.model_form_ranges[0].upper, 0.0904, 0.0005);
  EXPECT_TRUE(result.model_form_ranges[0].exceeds_interval);
  for (const auto& fit : result.fits)
    EXPECT_EQ(fit.lack_of_fit.verdict, LackOfFitVerdict::kStructural) << fit.name;
  EXPECT_TRUE(result.forward_warnings.empty());
}

// The same calibration corrected by two continuum references computed at parameters that are not
// the data's (K 530 MPa, n 0.19, friction 0 and 0.3; experiments/08_continuum_reference section
// 13; about 10 s with its six model-form refits): friction within the 5 % of the truth,
// K and n within 1 %, and the truth inside the model-form range, which now includes each
// reference alone.
TEST(CalibrationContinuum, DiscrepancyCorrectedConfigMeetsTheFrictionGoal) {
  const std::string path = std::string(VS_SOURCE_DIR) +
                           "/experiments/08_continuum_reference/calibration/"
                           "calibrate_ex1_mu010_discrepancy.toml";
  const auto result =
      calibrate(load_calibration_config(path), vs::testing::quiet(), make_default_forward_model());
  ASSERT_EQ(result.termination, CalibrationTermination::kConverged) << result.message;
  ASSERT_EQ(result.discrepancies.size(), 2u);
  for (const auto& source : result.discrepancies) {
    ASSERT_TRUE(source.ok) << source.message;
    EXPECT_EQ(source.curves.size(), 3u) << source.name;
  }
  const Eigen::VectorXd v = result.free_values();
  EXPECT_NEAR(v[0], 0.1005, 0.0005);              // friction (truth 0.1): within 1 %
  EXPECT_LT(std::abs(v[1] / 589.0 - 1.0), 0.01);  // K
  EXPECT_LT(std::abs(v[2] / 0.216 - 1.0), 0.01);  // n
  ASSERT_EQ(result.model_form.size(), 6u);        // the config's four and each reference alone
  ASSERT_EQ(result.model_form_ranges.size(), 3u);
  EXPECT_LT(result.model_form_ranges[0].lower, 0.1);
  EXPECT_GT(result.model_form_ranges[0].upper, 0.1);
  EXPECT_TRUE(result.forward_warnings.empty());
}

TEST(CalibrationContinuum, LackOfFitFiresOnTheContinuumProfile) {
  const auto result =
      calibrate(config_for(continuum_data()), vs::testing::quiet(), make_default_forward_model());
  fmt::print("{}", result.brief_report());
  ASSERT_EQ(result.fits.size(), 2u);
  for (const auto& fit : result.fits) fmt::print("  {}\n", fit.lack_of_fit.text);
  EXPECT_EQ(result.fits[1].lack_of_fit.verdict, LackOfFitVerdict::kStructural)
      << result.fits[1].lack_of_fit.text;
}

TEST(CalibrationContinuum, LackOfFitQuietOnTheShellsOwnCurves) {
  // The same fit on the shell's own curves at the same parameters.
  const CalibrationConfig base = config_for(continuum_data());
  toml::table table = read_scene_table(kScene);
  for (const auto& [address, text] : base.forward.overrides) {
    set_scene_value_from_text(table, address, text);
  }
  set_scene_number(table, "numerics.tolerance", base.forward.tolerance);
  set_scene_value_from_text(table, "process.output_travels_mm", "[25]");
  const Scene scene = scene_from_table(table, kScene, "");
  const RunResult run = make_default_forward_model()(scene);
  ASSERT_TRUE(run.completed()) << run.message;
  const auto reference = continuum_data();
  const auto data = make_synthetic_measurements(
      scene, run,
      {{MeasurementKind::kLoadTravel, "load", 0.0, reference[0].x, 0.0, 0.0},
       {MeasurementKind::kThicknessStrain, "thick_25mm", 25.0, reference[1].x, 0.0, 0.0}},
      1);
  CalibrationConfig config = config_for(data);
  config.parameters[0].initial = 0.09;  // a little off, so that the fit has work to do
  const auto result = calibrate(config, vs::testing::quiet(), make_default_forward_model());
  fmt::print("{}", result.brief_report());
  for (const auto& fit : result.fits) {
    EXPECT_NE(fit.lack_of_fit.verdict, LackOfFitVerdict::kStructural) << fit.lack_of_fit.text;
  }
}

// Issue 15's case, for the figures (not a CI test: ~4 min): friction-free continuum data, punch
// friction, K and n free from x0.7, the scene's 50 elements, 25 mm; the friction optimum lies
// below the bound 0. Plain Ceres (projected steps, no noise-floor stop) against the defaults
// (active set, noise-floor stop). Run with
//   build/tests/vs_system_tests --gtest_also_run_disabled_tests
//       --gtest_filter='*DISABLED_FrictionFreeContinuumAtTheBound*'
// Measured 2026-11-25 (load ~6 on 2 cores): plain 50 iterations, 327 forward runs, not converged,
// cost 80.07; defaults 3 iterations, 26 forward runs, converged (noise floor), cost 75.55,
// friction at 0 with the bound's effect stated.
TEST(CalibrationContinuum, DISABLED_FrictionFreeContinuumAtTheBound) {
  const auto data = continuum_data(kResults + "ex1_mu000_r60_l4/", {15, 25});
  for (bool plain : {true, false}) {
    CalibrationConfig c;
    c.scenes = {{"scene", kScene, "continuum figures"}};
    c.forward.tolerance = 1e-8;
    c.forward.overrides = {{"process.punch_travel_mm", "25"}};
    c.parameters = {testing::param("tool.punch.friction", 0.07, 0.0, 0.5, 0.1),
                    testing::param("material.hardening.K_MPa", 412.3, 100.0, 2000.0, 500.0),
                    testing::param("material.hardening.n", 0.1512, 0.05, 0.6, 0.2)};
    for (const auto& m : data) c.data.push_back(testing::data_set(m, 0.0));  // 1 % of range
    c.optimizer.fd.relative_step = 0.05;
    if (plain) {
      c.optimizer.noise_floor_factor = 0.0;
      c.optimizer.least_squares.active_set = false;
    }
    const auto result = calibrate(c, vs::testing::quiet(), make_default_forward_model());
    fmt::print("{}: {}", plain ? "plain Ceres" : "defaults", result.brief_report());
    EXPECT_NE(result.termination, CalibrationTermination::kFailed);
  }
}

}  // namespace
}  // namespace vs
