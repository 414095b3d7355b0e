// Honest calibration (issue 15 part 4, issues 14/16): the lack-of-fit diagnostic on residual
// vectors and on small fits, parameters at a bound (active set, the bound's effect), the
// model-form range, the noise-floor stop, and their config keys.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <atomic>
#include <cmath>

#include "calibrate.h"
#include "core/error.h"
#include "inverse_test_support.h"
#include "lack_of_fit.h"
#include "least_squares.h"
#include "report.h"
#include "scene/load_scene.h"
#include "synthetic.h"

namespace vs {
namespace {

using namespace vs::testing;

std::vector<double> white_noise(unsigned long long seed, int n) {
  GaussianNoise noise(seed);
  std::vector<double> e;
  for (int i = 0; i < n; ++i) e.push_back(noise.next());
  return e;
}

TEST(LackOfFit, IndependentNoiseIsQuiet) {
  // Two one-sided tests at 1 % each: about 2 % of noise vectors are flagged; 40 seeds.
  int flagged = 0;
  for (unsigned long long seed = 1; seed <= 40; ++seed) {
    const LackOfFit l = lack_of_fit(white_noise(seed, 40), "noise", {});
    EXPECT_NE(l.verdict, LackOfFitVerdict::kNotTested);
    if (l.verdict != LackOfFitVerdict::kNoise) ++flagged;
  }
  EXPECT_LE(flagged, 3);
}

TEST(LackOfFit, SmoothPatternOfOneSigmaIsStructural) {
  std::vector<double> e = white_noise(3, 40);
  for (std::size_t i = 0; i < e.size(); ++i)
    e[i] = 0.3 * e[i] + 2.0 * std::sin(0.2 * static_cast<double>(i));
  const LackOfFit l = lack_of_fit(e, "bent", {});
  EXPECT_EQ(l.verdict, LackOfFitVerdict::kStructural) << l.text;
  EXPECT_LT(l.runs, l.runs_expected);
  EXPECT_GT(l.lag1, 0.5);
  EXPECT_NE(l.text.find("STRUCTURAL"), std::string::npos);
}

TEST(LackOfFit, OffsetOfOneSignIsStructural) {
  std::vector<double> e(20, 1.5);
  const LackOfFit l = lack_of_fit(e, "offset", {});
  EXPECT_EQ(l.verdict, LackOfFitVerdict::kStructural) << l.text;
  EXPECT_EQ(l.runs, 1);
  EXPECT_NEAR(l.runs_p, std::pow(2.0, -19.0), 1e-12);
}

TEST(LackOfFit, PatternFarBelowSigmaIsNegligible) {
  std::vector<double> e;
  for (int i = 0; i < 30; ++i) e.push_back(1e-4 * std::sin(0.1 * i));
  const LackOfFit l = lack_of_fit(e, "tiny", {});
  EXPECT_EQ(l.verdict, LackOfFitVerdict::kNegligible) << l.text;
}

TEST(LackOfFit, RunsTestClosedForm) {
  // + + - - + + - - (n+ = n- = 4): 4 runs, E = 1 + 2*4*4/8 = 5, Var = 2*16*(32-8)/(64*7).
  const std::vector<double> e = {1, 1, -1, -1, 1, 1, -1, -1};
  const LackOfFit l = lack_of_fit(e, "closed", {});
  EXPECT_EQ(l.runs, 4);
  EXPECT_DOUBLE_EQ(l.runs_expected, 5.0);
  EXPECT_NEAR(l.runs_z, -1.0 / std::sqrt(2.0 * 16.0 * 24.0 / (64.0 * 7.0)), 1e-12);
  EXPECT_EQ(lack_of_fit({1, -1, 1}, "few", {}).verdict, LackOfFitVerdict::kNotTested);
}

// No sigma stated: the pattern is measured in forward resolutions, not in an invented sigma.
TEST(LackOfFit, UnstatedSigmaPatternFarAboveTheResolutionIsStructural) {
  std::vector<double> difference, resolution;
  for (int i = 0; i < 30; ++i) {
    difference.push_back(5e-4 * std::sin(0.2 * i));  // a strain misfit of ~3.5e-4 rms
    resolution.push_back(4e-8);
  }
  const LackOfFit l = lack_of_fit_unstated(difference, resolution, "1", "thick", {});
  EXPECT_EQ(l.verdict, LackOfFitVerdict::kStructural) << l.text;
  EXPECT_FALSE(l.sigma_stated);
  EXPECT_NEAR(l.resolution, 4e-8, 1e-20);
  EXPECT_NEAR(l.rms, l.rms_difference / 4e-8, 1e-9 * l.rms);
  EXPECT_GT(l.rms_difference, 3e-4);
  EXPECT_NE(l.text.find("STRUCTURAL"), std::string::npos);
  EXPECT_NE(l.text.find("systematic"), std::string::npos);
  EXPECT_NE(l.text.find("No sigma was stated"), std::string::npos) << l.text;
  EXPECT_NE(l.text.find(fmt::format("{:.3g} (strain)", l.rms_difference)), std::string::npos)
      << l.text;
  // The runs and autocorrelation figures are those of the stated-sigma test on the same shape.
  const LackOfFit stated = lack_of_fit(difference, "thick", {});
  EXPECT_EQ(stated.runs, l.runs);
  EXPECT_DOUBLE_EQ(stated.lag1, l.lag1);
}

TEST(LackOfFit, UnstatedSigmaPatternAtTheResolutionIsNegligible) {
  // A smooth pattern of 2 resolutions: what a fit stopped at the noise floor leaves.
  std::vector<double> difference, resolution;
  for (int i = 0; i < 30; ++i) {
    difference.push_back(2.0 * 0.05 * std::sqrt(2.0) * std::sin(0.2 * i + 0.1));
    resolution.push_back(0.05);
  }
  const LackOfFit l = lack_of_fit_unstated(difference, resolution, "N", "load", {});
  EXPECT_EQ(l.verdict, LackOfFitVerdict::kNegligible) << l.text;
  EXPECT_LT(l.runs, l.runs_expected);
  EXPECT_NE(l.text.find(" N"), std::string::npos) << l.text;
  LackOfFitOptions strict;
  strict.min_resolutions = 1.0;
  EXPECT_EQ(lack_of_fit_unstated(difference, resolution, "N", "load", strict).verdict,
            LackOfFitVerdict::kStructural);
  // Points without a resolution are left out.
  resolution.assign(30, 0.0);
  EXPECT_EQ(lack_of_fit_unstated(difference, resolution, "N", "load", {}).verdict,
            LackOfFitVerdict::kNotTested);
}

// Load curve data for LinearFake (force = K + 1000 friction t) at t = 1..30, optionally with a
// curvature the model cannot represent, and noise of `sigma`.
Measurement linear_data(double K, double friction, double curvature, double sigma,
                        unsigned long long seed) {
  Measurement m;
  m.name = "load";
  m.kind = MeasurementKind::kLoadTravel;
  GaussianNoise noise(seed);
  for (int i = 1; i <= 30; ++i) {
    m.x.push_back(i);
    m.y.push_back(K + 1000.0 * friction * i + curvature * (i - 15.5) * (i - 15.5) +
                  sigma * noise.next());
  }
  return m;
}

CalibrationConfig linear_config(const fs::path& dir, const Measurement& m, double sigma) {
  CalibrationConfig config;
  config.scenes = {{"scene", write_scene(dir).string(), "test"}};
  config.parameters = {param("material.hardening.K_MPa", 400.0, 1.0, 2000.0, 100.0),
                       param("tool.punch.friction", 0.3, 0.0, 1.0, 0.1)};
  config.data = {data_set(m, sigma)};
  return config;
}

TEST(LackOfFitFit, FiresOnBiasedModelDataAndStaysQuietOnSynthetic) {
  const fs::path dir = scratch_dir();
  const double sigma = 20.0;
  // Model data: the fitted model plus noise.
  const auto synthetic = calibrate(
      linear_config(dir, linear_data(480.0, 0.15, 0.0, sigma, 7), sigma), quiet(), LinearFake{});
  ASSERT_EQ(synthetic.fits.size(), 1u);
  EXPECT_EQ(synthetic.fits[0].lack_of_fit.verdict, LackOfFitVerdict::kNoise)
      << synthetic.fits[0].lack_of_fit.text;
  // Deliberately biased: a curvature (10 sigma at the ends) that a line cannot follow.
  const auto biased = calibrate(linear_config(dir, linear_data(480.0, 0.15, 1.0, sigma, 7), sigma),
                                quiet(), LinearFake{});
  EXPECT_EQ(biased.fits[0].lack_of_fit.verdict, LackOfFitVerdict::kStructural)
      << biased.fits[0].lack_of_fit.text;
  EXPECT_NE(biased.brief_report().find("STRUCTURAL"), std::string::npos);
  const std::string json = calibration_json(biased, linear_config(dir, {}, sigma));
  EXPECT_NE(json.find("\"verdict\": \"structural\""), std::string::npos);
}

// A data set with no sigma, weighted by the relative default (1 % of its range).
DataSpec default_sigma_set(Measurement m) {
  DataSpec d;
  d.measurement = std::move(m);
  d.where = "test";
  return d;
}

TEST(LackOfFitFit, FiresOnBiasedModelDataAtDefaultSigma) {
  // A curvature of 6.7 N rms that a line cannot follow, no noise, no sigma stated: 0.15 of the
  // default sigma (1 % of the 4350 N range), far above the forward resolution (20 x 1e-9 x
  // 5001 N = 1e-4 N). A threshold in default sigmas would call it negligible.
  const fs::path dir = scratch_dir();
  CalibrationConfig config = linear_config(dir, {}, 1.0);
  config.data = {default_sigma_set(linear_data(480.0, 0.15, 0.1, 0.0, 7))};
  const auto biased = calibrate(config, quiet(), LinearFake{});
  ASSERT_EQ(biased.fits.size(), 1u);
  const LackOfFit& l = biased.fits[0].lack_of_fit;
  EXPECT_EQ(l.verdict, LackOfFitVerdict::kStructural) << l.text;
  EXPECT_FALSE(l.sigma_stated);
  EXPECT_NEAR(l.resolution, 20.0 * 1e-9 * (480.0 + 150.0 * 30.0 + 0.1 * 14.5 * 14.5), 1e-9);
  EXPECT_NEAR(l.rms_difference, biased.fits[0].rms_difference, 1e-9);
  EXPECT_GT(l.rms_difference, 5.0);
  EXPECT_LT(l.rms_difference, 0.5 * 0.01 * 4350.0);  // below the old threshold
  EXPECT_NE(l.text.find("No sigma was stated"), std::string::npos) << l.text;
  EXPECT_NE(l.text.find(" N"), std::string::npos) << l.text;
  EXPECT_NE(biased.brief_report().find("STRUCTURAL"), std::string::npos);
  const std::string json = calibration_json(biased, config);
  EXPECT_NE(json.find("\"verdict\": \"structural\""), std::string::npos);
  EXPECT_NE(json.find("\"rms_unit\": \"forward_resolution\""), std::string::npos);
  // The verdict does not feed the fit: the same values as with a stated sigma of the default
  // size (the weights are the same).
  CalibrationConfig stated = config;
  stated.data[0].sigma = data_set_sigma(config.data[0]).sigma;
  const auto with_sigma = calibrate(stated, quiet(), LinearFake{});
  EXPECT_EQ(with_sigma.free_values(), biased.free_values());
  EXPECT_EQ(with_sigma.fits[0].lack_of_fit.verdict, LackOfFitVerdict::kNegligible)
      << with_sigma.fits[0].lack_of_fit.text;
}

TEST(LackOfFitFit, StructuralVerdictOfAnUnfinishedFitSaysSo) {
  // The biased data of the test above, with the fit stopped after one iteration from a start far
  // off: its misfit is partly the unfinished fit, and the verdict must say that. The converged
  // fit's verdict must not.
  const fs::path dir = scratch_dir();
  CalibrationConfig config = linear_config(dir, {}, 1.0);
  config.data = {default_sigma_set(linear_data(480.0, 0.15, 0.1, 0.0, 7))};
  const auto converged = calibrate(config, quiet(), LinearFake{});
  ASSERT_EQ(converged.termination, CalibrationTermination::kConverged) << converged.message;
  EXPECT_TRUE(converged.fits.at(0).lack_of_fit.fit_converged);
  EXPECT_EQ(converged.fits[0].lack_of_fit.text.find("stopped before converging"),
            std::string::npos);
  config.parameters[0].initial = 1500.0;
  config.optimizer.least_squares.max_iterations = 1;
  const auto early = calibrate(config, quiet(), LinearFake{});
  ASSERT_EQ(early.termination, CalibrationTermination::kNotConverged) << early.message;
  const LackOfFit& l = early.fits.at(0).lack_of_fit;
  EXPECT_EQ(l.verdict, LackOfFitVerdict::kStructural) << l.text;
  EXPECT_FALSE(l.fit_converged);
  EXPECT_NE(l.text.find("stopped before converging (NO_CONVERGENCE, 1 iterations"),
            std::string::npos)
      << l.text;
  EXPECT_NE(calibration_json(early, config).find("\"fit_converged\": false"), std::string::npos);
}

// StretchingFake with the forward solver's convergence jitter: 3 x tolerance x the curve's
// scale, smooth along the curve (a pattern) with a phase that changes with the parameters.
struct JitteredStretchingFake {
  RunResult operator()(const Scene& scene) const {
    RunResult run = StretchingFake{}(scene);
    const double tolerance = scene.numerics.tolerance;
    const double phase =
        std::fmod(1e4 * (scene.material.hardening.K_MPa + 1e3 * punch_friction(scene)), 6.283);
    for (auto& s : run.steps) {
      s.punch_force_N +=
          3.0 * tolerance * std::abs(s.punch_force_N) * std::sin(0.7 * s.punch_travel_mm + phase);
    }
    for (auto& p : run.profiles) {
      for (std::size_t i = 0; i < p.r0_mm.size(); ++i) {
        p.eps_thickness[i] += 3.0 * tolerance * 0.3 * std::sin(0.2 * p.r0_mm[i] + phase);
      }
    }
    return run;
  }
};

// Noise-free synthetic data of `fake` (the load curve to 25 mm and the thickness strain at
// 25 mm) from the test scene written into a scratch folder; `tolerance` > 0 is the scene's solver
// tolerance for the run.
template <class Fake>
std::vector<Measurement> stretching_data(const Fake& fake, fs::path* scene_file,
                                         double tolerance = 0.0) {
  *scene_file = write_scene(scratch_dir());
  Scene scene = load_scene(scene_file->string());
  scene.process.output_travels_mm = {15.0, 25.0};
  if (tolerance > 0.0) scene.numerics.tolerance = tolerance;
  const RunResult run = fake(scene);
  std::vector<double> travels, radii;
  for (int i = 1; i <= 25; ++i) travels.push_back(i);
  for (int i = 0; i <= 20; ++i) radii.push_back(2.0 * i);
  return make_synthetic_measurements(
      scene, run,
      {{MeasurementKind::kLoadTravel, "load", 0.0, travels, 0.0, 0.0},
       {MeasurementKind::kThicknessStrain, "thick_25", 25.0, radii, 0.0, 0.0}},
      1);
}

TEST(LackOfFitFit, NoiseFreeSyntheticAtDefaultSigmaIsQuiet) {
  CalibrationConfig config;
  fs::path scene_file;
  const auto data =
      stretching_data(JitteredStretchingFake{}, &scene_file, config.forward.tolerance);
  config.scenes = {{"scene", scene_file.string(), "test"}};
  config.parameters = {param("tool.punch.friction", 0.08, 0.0, 0.5, 0.1),
                       param("material.hardening.K_MPa", 400.0, 100.0, 2000.0, 500.0)};
  config.data = {default_sigma_set(data[0]), default_sigma_set(data[1])};
  const auto result = calibrate(config, quiet(), JitteredStretchingFake{});
  ASSERT_EQ(result.fits.size(), 2u);
  for (const auto& fit : result.fits) {
    EXPECT_FALSE(fit.lack_of_fit.sigma_stated);
    EXPECT_NE(fit.lack_of_fit.verdict, LackOfFitVerdict::kStructural) << fit.lack_of_fit.text;
    EXPECT_NE(fit.lack_of_fit.verdict, LackOfFitVerdict::kNotTested) << fit.lack_of_fit.text;
  }
  // The quiet verdict is the resolution threshold's doing: the jitter is a pattern, and with no
  // threshold the same fit is called structural.
  config.uncertainty.lack_of_fit.min_resolutions = 0.0;
  const auto strict = calibrate(config, quiet(), JitteredStretchingFake{});
  EXPECT_EQ(strict.free_values(), result.free_values());
  EXPECT_EQ(strict.fits[0].lack_of_fit.verdict, LackOfFitVerdict::kStructural)
      << strict.fits[0].lack_of_fit.text;
}

TEST(LackOfFitFit, NoiseFreeSyntheticStretchingIsNotStructural) {
  fs::path scene_file;
  const auto data = stretching_data(StretchingFake{}, &scene_file);
  CalibrationConfig config;
  config.scenes = {{"scene", scene_file.string(), "test"}};
  config.parameters = {param("tool.punch.friction", 0.08, 0.0, 0.5, 0.1),
                       param("material.hardening.K_MPa", 400.0, 100.0, 2000.0, 500.0)};
  config.data = {data_set(data[0], 100.0), data_set(data[1], 0.002)};
  const auto result = calibrate(config, quiet(), StretchingFake{});
  for (const auto& fit : result.fits) {
    EXPECT_NE(fit.lack_of_fit.verdict, LackOfFitVerdict::kStructural) << fit.lack_of_fit.text;
  }
}

// Friction-free data whose best fit wants a NEGATIVE friction: friction ends on its lower bound
// 0, is held there, and K is the constrained optimum (the mean of the data).
TEST(AtBound, HeldOnTheBoundWithItsEffectReported) {
  const fs::path dir = scratch_dir();
  const double sigma = 20.0;
  const Measurement m = linear_data(480.0, -0.02, 0.0, sigma, 11);
  int runs[2] = {0, 0};
  for (bool active_set : {true, false}) {
    CalibrationConfig config = linear_config(dir, m, sigma);
    config.optimizer.least_squares.active_set = active_set;
    const auto result = calibrate(config, quiet(), LinearFake{});
    fmt::print("active_set {}: {} forward runs, {} iterations, {} passes\n{}", active_set,
               result.forward_runs, result.iterations, result.passes, result.brief_report());
    runs[active_set ? 0 : 1] = result.forward_runs;
    if (!active_set) continue;
    EXPECT_EQ(result.termination, CalibrationTermination::kConverged) << result.message;
    EXPECT_EQ(result.free_values()[1], 0.0);
    double mean = 0.0;
    for (double y : m.y) mean += y / 30.0;
    // To the noise floor (factor 20 x tolerance 1e-9 of a ~45 kN curve in 20 N sigmas).
    EXPECT_NEAR(result.free_values()[0], mean, 1e-3 * mean);
    ASSERT_EQ(result.bound_effects.size(), 1u);
    const BoundEffect& b = result.bound_effects[0];
    EXPECT_EQ(b.name, "tool.punch.friction");
    EXPECT_EQ(b.side, -1);
    EXPECT_TRUE(b.active);
    EXPECT_GT(b.gradient, 0.0);
    EXPECT_LT(b.unconstrained, 0.0);
    EXPECT_GT(b.cost_decrease, 0.0);
    EXPECT_FALSE(result.uncertainty.parameters[1].determined);  // the bound's value
    EXPECT_NE(result.brief_report().find("AT its lower bound"), std::string::npos);
    EXPECT_NE(calibration_json(result, config).find("\"bound_effect\""), std::string::npos);
  }
  EXPECT_LE(runs[0], runs[1]);
}

TEST(AtBound, InteriorOptimumIsNotHeld) {
  const fs::path dir = scratch_dir();
  CalibrationConfig config = linear_config(dir, linear_data(480.0, 0.15, 0.0, 20.0, 7), 20.0);
  config.parameters[1].initial = 0.0;  // starts on the bound, the optimum is inside
  const auto result = calibrate(config, quiet(), LinearFake{});
  EXPECT_EQ(result.termination, CalibrationTermination::kConverged) << result.message;
  EXPECT_GT(result.free_values()[1], 0.1);
  EXPECT_TRUE(result.bound_effects.empty());
}

// Friction from StretchingFake's noise-free thickness profile at 25 mm (40 elements, truth 0.1),
// starting at 0.08; the scene and data in this test's scratch folder.
CalibrationConfig friction_from_thickness_config() {
  const fs::path dir = scratch_dir();
  const fs::path scene_file = write_scene(dir);
  Scene scene = load_scene(scene_file.string());
  scene.process.output_travels_mm = {25.0};
  scene.blank.elements = 40;
  const RunResult run = StretchingFake{}(scene);
  std::vector<double> radii;
  for (int i = 0; i <= 20; ++i) radii.push_back(2.0 * i);
  const auto data = make_synthetic_measurements(
      scene, run, {{MeasurementKind::kThicknessStrain, "thick_25", 25.0, radii, 0.0, 0.0}}, 1);
  CalibrationConfig config;
  config.scenes = {{"scene", scene_file.string(), "test"}};
  config.parameters = {param("tool.punch.friction", 0.08, 0.0, 0.5, 0.1)};
  config.data = {data_set(data[0], 0.002)};
  config.forward.overrides = {{"blank.elements", "40"}};
  return config;
}

// The fake's profiles are sampled at element midpoints, so the mesh is a model choice that moves
// the identified friction a little: the range must contain the main fit and the alternative.
TEST(ModelForm, RangeOverTheAlternatives) {
  CalibrationConfig config = friction_from_thickness_config();
  config.model_forms = {{"coarse mesh", {{"blank.elements", "8"}}, "test", {}, std::nullopt},
                        {"same mesh", {{"blank.elements", "40"}}, "test", {}, std::nullopt}};
  const auto result = calibrate(config, quiet(), StretchingFake{});
  ASSERT_EQ(result.model_form.size(), 2u);
  ASSERT_EQ(result.model_form_ranges.size(), 1u);
  const double main = result.free_values()[0];
  EXPECT_NEAR(main, 0.1, 1e-4);
  const double coarse = result.model_form[0].values.at(0);
  const auto& range = result.model_form_ranges[0];
  EXPECT_GT(std::abs(coarse - main), 1e-4);  // the coarse mesh moves friction
  EXPECT_DOUBLE_EQ(range.lower, std::min(main, coarse));
  EXPECT_DOUBLE_EQ(range.upper, std::max(main, coarse));
  EXPECT_NEAR(result.model_form[1].values.at(0), main, 1e-6);
  EXPECT_GT(result.model_form_forward_runs, 0);
  EXPECT_NE(result.brief_report().find("model-form range"), std::string::npos);
  const std::string json = calibration_json(result, config);
  EXPECT_NE(json.find("\"model_form_lower\""), std::string::npos);
}

// StretchingFake that warns, as the solver does, when its elements are shorter than the
// thickness (blank.elements beyond radius / thickness).
struct WarningStretchingFake {
  RunResult operator()(const Scene& scene) const {
    RunResult run = StretchingFake{}(scene);
    if (scene.blank.radius_mm / scene.blank.elements < scene.blank.thickness_mm)
      run.warnings.push_back("fake: elements shorter than the thickness");
    run.warnings.push_back("fake: always");
    run.warnings.push_back("fake: always");  // repeated: reported once
    return run;
  }
};

// The forward model's warnings at the initial parameters are said at once (progress), those at
// the identified parameters reach the result, the printed report and calibration.json, each once; a
// model-form fit carries its own (here only the fine mesh's runs warn about the element length).
TEST(ForwardWarnings, TheReportRepeatsTheWarningsOfTheIdentifiedRunAndOfEachModelForm) {
  CalibrationConfig config = friction_from_thickness_config();
  config.model_forms = {{"fine mesh", {{"blank.elements", "60"}}, "test", {}, std::nullopt}};
  std::vector<std::string> lines;
  CalibrationOptions options = quiet();
  options.progress = [&lines](const std::string& line) { lines.push_back(line); };
  const auto result = calibrate(config, options, WarningStretchingFake{});
  // Said before the fit starts (the second line, after the problem's size), once per warning.
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines[1], "warning: at the initial parameters the forward model warns: fake: always");
  EXPECT_EQ(std::count(lines.begin(), lines.end(), lines[1]), 1);
  ASSERT_EQ(result.termination, CalibrationTermination::kConverged) << result.message;
  EXPECT_EQ(result.forward_warnings, std::vector<std::string>{"fake: always"});
  ASSERT_EQ(result.model_form.size(), 1u);
  EXPECT_EQ(
      result.model_form[0].forward_warnings,
      (std::vector<std::string>{"fake: elements shorter than the thickness", "fake: always"}));
  const std::string brief = result.brief_report();
  EXPECT_NE(brief.find("at the identified parameters the forward model warns: fake: always"),
            std::string::npos)
      << brief;
  EXPECT_NE(brief.find("its forward model warns: fake: elements shorter than the thickness"),
            std::string::npos)
      << brief;
  const std::string json = calibration_json(result, config);
  EXPECT_NE(json.find("\"forward_warnings\": [\n    \"fake: always\"\n  ]"), std::string::npos)
      << json;
  EXPECT_NE(json.find("\"fake: elements shorter than the thickness\""), std::string::npos);

  // Without warnings in the forward runs: none in the report.
  config.model_forms.clear();
  const auto quiet_result = calibrate(config, quiet(), StretchingFake{});
  EXPECT_TRUE(quiet_result.forward_warnings.empty());
  EXPECT_EQ(quiet_result.brief_report().find("warns"), std::string::npos);
}

// drop_data: an alternative that leaves a data set out. The thickness profile is the truth's
// (friction 0.1), the load is 3 % high, so the main fit (both) is pulled off 0.1 and the
// alternative without the load is exactly the fit on the profile alone.
TEST(ModelForm, DropDataRefitsWithoutTheNamedDataSets) {
  CalibrationConfig config = friction_from_thickness_config();
  Scene scene = load_scene(config.scenes[0].path);
  scene.process.output_travels_mm = {25.0};
  scene.blank.elements = 40;
  std::vector<double> travels;
  for (int i = 1; i <= 25; ++i) travels.push_back(i);
  auto load = make_synthetic_measurements(
      scene, StretchingFake{}(scene), {{MeasurementKind::kLoadTravel, "load", 0.0, travels}}, 1);
  for (double& y : load[0].y) y *= 1.03;
  config.data.push_back(data_set(load[0], 50.0));
  CalibrationConfig profile_only = config;
  profile_only.data.pop_back();
  config.model_forms = {{"profile only", {}, "test", {"load"}, std::nullopt}};
  const auto result = calibrate(config, quiet(), StretchingFake{});
  const auto direct = calibrate(profile_only, quiet(), StretchingFake{});
  ASSERT_EQ(result.model_form.size(), 1u);
  ASSERT_EQ(result.model_form[0].values.size(), 1u);
  const double main = result.free_values()[0], without = result.model_form[0].values[0];
  EXPECT_NEAR(direct.free_values()[0], 0.1, 1e-4);
  EXPECT_NEAR(without, direct.free_values()[0], 1e-6);
  EXPECT_GT(std::abs(main - without), 1e-3);  // the biased load moves the main fit
  EXPECT_DOUBLE_EQ(result.model_form_ranges[0].lower, std::min(main, without));
  EXPECT_DOUBLE_EQ(result.model_form_ranges[0].upper, std::max(main, without));
  EXPECT_EQ(result.model_form[0].edits, "without data load");
  EXPECT_EQ(result.model_form[0].dropped_data, std::vector<std::string>{"load"});
  EXPECT_NE(calibration_json(result, config).find("\"dropped_data\": [\n          \"load\""),
            std::string::npos);

  // Checked before any run: a name that is no data set, and an alternative left without data.
  std::atomic<int> calls{0};
  StretchingFake counting;
  counting.calls = &calls;
  const auto error = [&](std::vector<std::string> drop) {
    CalibrationConfig bad = config;
    bad.model_forms = {{"bad", {}, "cal.toml:9", std::move(drop), std::nullopt}};
    try {
      calibrate(bad, quiet(), counting);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error({"lod"}).find("cal.toml:9: model_form 'bad': drop_data names 'lod', which is "
                                "not a data set of this config"),
            std::string::npos);
  EXPECT_NE(error({"load", "thick_25"})
                .find("cal.toml:9: model_form 'bad': the data it keeps "
                      "(0 points) cannot determine 1 free parameters"),
            std::string::npos);
  EXPECT_NE(error({}).find("has no scene edits (set), drops no data and keeps every discrepancy "
                           "source"),
            std::string::npos);
  EXPECT_EQ(calls.load(), 0);
}

TEST(ModelForm, BadSceneEditIsAnInputErrorBeforeAnyRun) {
  const fs::path dir = scratch_dir();
  CalibrationConfig config = linear_config(dir, linear_data(480.0, 0.15, 0.0, 20.0, 7), 20.0);
  config.model_forms = {{"bad", {{"blank.elements", "-3"}}, "cal.toml:12", {}, std::nullopt}};
  std::atomic<int> calls{0};
  StretchingFake fake;
  fake.calls = &calls;
  try {
    calibrate(config, quiet(), fake);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cal.toml:12: model_form 'bad'"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(calls.load(), 0);
}

TEST(NoiseFloor, ClosedForms) {
  Eigen::VectorXd r(3), noise(3);
  r << 3.0, 4.0, 0.0;
  noise << 0.0, 0.0, 2.0;
  EXPECT_DOUBLE_EQ(noise_floor_cost(r, noise), 5.0 * 2.0 + 0.5 * 4.0);
  EXPECT_EQ(noise_floor_cost(r, Eigen::VectorXd()), 0.0);
  Eigen::MatrixXd j(3, 2);
  j << 1, 0, 0, 1, 0, 0;
  EXPECT_NEAR(predicted_decrease(j, r, {}), 0.5 * 25.0, 1e-12);
  EXPECT_NEAR(predicted_decrease(j, r, {true, false}), 0.5 * 16.0, 1e-12);
  EXPECT_EQ(predicted_decrease(j, r, {true, true}), 0.0);
}

TEST(NoiseFloor, ForwardResolutionWidensTheInterval) {
  Eigen::MatrixXd j(3, 2);
  j << 2, 0, 0, 1, 0, 0;
  UncertaintySummary summary;
  summary.parameters.resize(2);
  for (auto& u : summary.parameters) {
    u.std_error = 0.1;
    u.interval_lower = -0.2;
    u.interval_upper = 0.2;
  }
  // F = 0.5: (J^T J)^-1 = diag(1/4, 1), resolution sqrt(2 F (J^T J)^-1_jj) = 0.5 and 1.
  add_forward_resolution(j, 0.5, &summary);
  EXPECT_NEAR(summary.parameters[0].forward_resolution, 0.5, 1e-12);
  EXPECT_NEAR(summary.parameters[1].forward_resolution, 1.0, 1e-12);
  EXPECT_NEAR(summary.parameters[1].interval_lower, -1.2, 1e-12);
  EXPECT_NEAR(summary.parameters[1].interval_upper, 1.2, 1e-12);
}

// A coarse forward resolution (factor 1e5 x tolerance 1e-9 = 1e-4 of each curve) ends the fit
// as soon as the remaining decrease is below it, with fewer runs and the statement in words.
TEST(NoiseFloor, StopsWhenTheDecreaseCannotBeResolved) {
  const fs::path dir = scratch_dir();
  const fs::path scene_file = write_scene(dir);
  Scene scene = load_scene(scene_file.string());
  scene.process.output_travels_mm = {25.0};
  const RunResult run = StretchingFake{}(scene);
  std::vector<double> travels, radii;
  for (int i = 1; i <= 25; ++i) travels.push_back(i);
  for (int i = 0; i <= 20; ++i) radii.push_back(2.0 * i);
  const auto data = make_synthetic_measurements(
      scene, run,
      {{MeasurementKind::kLoadTravel, "load", 0.0, travels, 0.0, 0.0},
       {MeasurementKind::kThicknessStrain, "thick_25", 25.0, radii, 0.0, 0.0}},
      1);
  CalibrationConfig config;
  config.scenes = {{"scene", scene_file.string(), "test"}};
  config.parameters = {param("tool.punch.friction", 0.07, 0.0, 0.5, 0.1),
                       param("material.hardening.K_MPa", 350.0, 100.0, 2000.0, 500.0),
                       param("material.hardening.n", 0.14, 0.05, 0.6, 0.2)};
  config.data = {data_set(data[0], 100.0), data_set(data[1], 0.002)};
  config.optimizer.noise_floor_factor = 0.0;
  const auto plain = calibrate(config, quiet(), StretchingFake{});
  config.optimizer.noise_floor_factor = 1e5;
  const auto floor = calibrate(config, quiet(), StretchingFake{});
  fmt::print("no floor: {} runs; floor: {} runs\n{}", plain.forward_runs, floor.forward_runs,
             floor.brief_report());
  EXPECT_FALSE(plain.noise_floor);
  EXPECT_TRUE(floor.noise_floor);
  EXPECT_EQ(floor.termination, CalibrationTermination::kConverged);
  EXPECT_NE(floor.message.find("stopped at the noise floor"), std::string::npos);
  EXPECT_LT(floor.forward_runs, plain.forward_runs);
  // Stopped where the remaining misfit is at the resolution: the parameters within ~1e-3.
  EXPECT_NEAR(floor.free_values()[0] / 0.1, 1.0, 1e-2);
  EXPECT_NEAR(floor.free_values()[1] / 500.0, 1.0, 1e-2);
  // Noise-free data: the statistical interval alone is the leftover misfit; with the forward
  // resolution the truth is inside.
  ASSERT_TRUE(floor.uncertainty_available);
  const double truth[] = {0.1, 500.0, 0.2};
  for (int i = 0; i < 3; ++i) {
    const auto& u = floor.uncertainty.parameters.at(static_cast<std::size_t>(i));
    EXPECT_GT(u.forward_resolution, 0.0) << u.name;
    EXPECT_LE(u.interval_lower, truth[i]) << u.name;
    EXPECT_GE(u.interval_upper, truth[i]) << u.name;
  }
}

TEST(HonestConfig, ReadsTheNewKeysAndRejectsBadOnesInOneLine) {
  const fs::path dir = scratch_dir();
  write_scene(dir);
  write_file(dir / "load.csv", kLoadCsv);
  const std::string head = R"(scene = "scene.toml"
[[parameter]]
address = "tool.punch.friction"
initial = 0.05
lower = 0.0
upper = 0.5
[[data]]
kind = "load_travel"
file = "load.csv"
sigma = 50.0
)";
  write_file(dir / "c.toml", head + R"([optimizer]
noise_floor_factor = 5
active_set = false
[uncertainty]
lack_of_fit_significance = 0.05
lack_of_fit_min_rms = 2
lack_of_fit_min_resolutions = 25
[[model_form]]
name = "fine mesh"
set = { "blank.elements" = 40 }
[[model_form]]
name = "cut-off"
set = { "numerics.strain_rate_cutoff" = 1e-4 }
)");
  const CalibrationConfig c = load_calibration_config((dir / "c.toml").string());
  EXPECT_EQ(c.optimizer.noise_floor_factor, 5.0);
  EXPECT_FALSE(c.optimizer.least_squares.active_set);
  EXPECT_EQ(c.uncertainty.lack_of_fit.significance, 0.05);
  EXPECT_EQ(c.uncertainty.lack_of_fit.min_rms, 2.0);
  EXPECT_EQ(c.uncertainty.lack_of_fit.min_resolutions, 25.0);
  ASSERT_EQ(c.model_forms.size(), 2u);
  EXPECT_EQ(c.model_forms[0].name, "fine mesh");
  EXPECT_EQ(c.model_forms[0].overrides.at(0).first, "blank.elements");
  EXPECT_EQ(c.model_forms[0].overrides.at(0).second, "40");
  EXPECT_NE(c.model_forms[1].where.find("c.toml:"), std::string::npos);

  auto error_of = [&](const std::string& tail_text) {
    write_file(dir / "bad.toml", head + tail_text);
    try {
      load_calibration_config((dir / "bad.toml").string());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string missing_set = error_of("[[model_form]]\nname = \"x\"\n");
  EXPECT_NE(missing_set.find("needs set"), std::string::npos) << missing_set;
  const std::string misspelt = error_of("[[model_form]]\nname = \"x\"\nsett = {a = 1}\n");
  EXPECT_NE(misspelt.find("did you mean 'set'"), std::string::npos) << misspelt;
  const std::string range = error_of("[optimizer]\nnoise_floor_factor = -1\n");
  EXPECT_NE(range.find("noise_floor_factor"), std::string::npos) << range;
  const std::string resolutions = error_of("[uncertainty]\nlack_of_fit_min_resolutions = -1\n");
  EXPECT_NE(resolutions.find("lack_of_fit_min_resolutions"), std::string::npos) << resolutions;
  const std::string twice = error_of(
      "[[model_form]]\nname = \"x\"\nset = {a = 1}\n[[model_form]]\nname = \"x\"\nset = "
      "{a = 2}\n");
  EXPECT_NE(twice.find("used twice"), std::string::npos) << twice;
  for (const std::string& e : {missing_set, misspelt, range, resolutions, twice}) {
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

}  // namespace
}  // namespace vs
