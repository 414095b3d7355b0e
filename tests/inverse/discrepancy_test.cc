// The model-discrepancy correction ([[discrepancy]], inverse/discrepancy.h): a "reference" model
// that is StretchingFake plus a model-form error b(r0); the forward model is StretchingFake.
#include "discrepancy.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "calibrate.h"
#include "core/error.h"
#include "inverse_test_support.h"
#include "report.h"
#include "scene/load_scene.h"
#include "synthetic.h"

namespace vs {
namespace {

using namespace vs::testing;

// The reference's error against the forward model: a dip at the pole and a rise outside, like the
// shell against the continuum (experiments/08), scaled by (1 + slope x friction).
double model_error(double r0, double friction, double slope) {
  return (1.0 + slope * friction) * (-0.006 * std::exp(-(r0 / 12.0) * (r0 / 12.0)) + 0.001);
}

struct Case {
  CalibrationConfig config;
  Scene scene;
  std::vector<double> radii;
};

// The reference model's profile at `friction`: the forward model's plus model_error.
Measurement reference_profile(const Case& c, double friction, double slope) {
  Scene scene = c.scene;
  for (auto& tool : scene.tools) {
    if (tool.name == "punch") tool.friction = friction;
  }
  const RunResult run = StretchingFake{}(scene);
  Measurement m =
      make_synthetic_measurements(
          scene, run, {{MeasurementKind::kThicknessStrain, "thick_25", 25.0, c.radii, 0.0, 0.0}}, 1)
          .at(0);
  for (std::size_t i = 0; i < m.x.size(); ++i) m.y[i] += model_error(m.x[i], friction, slope);
  return m;
}

// Friction from a 25 mm thickness profile of the reference model at friction 0.1 (40 elements),
// starting at 0.08.
Case friction_case(double slope) {
  Case c;
  const fs::path dir = scratch_dir();
  const fs::path scene_file = write_scene(dir);
  c.scene = load_scene(scene_file.string());
  c.scene.process.output_travels_mm = {25.0};
  c.scene.blank.elements = 40;
  for (int i = 0; i <= 20; ++i) c.radii.push_back(2.0 * i);
  c.config.scenes = {{"scene", scene_file.string(), "test"}};
  c.config.parameters = {param("tool.punch.friction", 0.08, 0.0, 0.5, 0.1)};
  c.config.forward.overrides = {{"blank.elements", "40"}};
  c.config.data = {data_set(reference_profile(c, 0.1, slope), 0.002)};
  return c;
}

DiscrepancySpec source(const Case& c, const std::string& name, double friction, double slope) {
  DiscrepancySpec s;
  s.name = name;
  s.set = {{"tool.punch.friction", fmt::format("{}", friction)}};
  s.references = {{"thick_25", reference_profile(c, friction, slope)}};
  s.where = "cal.toml:20";
  return s;
}

// An error that does not depend on the parameters: without the correction the fit moves friction
// to imitate it; with references at other frictions (0 and 0.3, not the data's 0.1) it is removed
// exactly, and each reference alone gives the same fit.
TEST(Discrepancy, RemovesAModelFormErrorThatDoesNotDependOnTheParameters) {
  Case c = friction_case(0.0);
  const auto plain = calibrate(c.config, quiet(), StretchingFake{});
  ASSERT_EQ(plain.termination, CalibrationTermination::kConverged) << plain.message;
  EXPECT_GT(std::abs(plain.free_values()[0] - 0.1), 2e-3);  // biased by the model-form error

  c.config.discrepancies = {source(c, "ref mu 0", 0.0, 0.0), source(c, "ref mu 0.3", 0.3, 0.0)};
  const auto corrected = calibrate(c.config, quiet(), StretchingFake{});
  ASSERT_EQ(corrected.termination, CalibrationTermination::kConverged) << corrected.message;
  EXPECT_NEAR(corrected.free_values()[0], 0.1, 1e-5);
  EXPECT_EQ(corrected.discrepancy_forward_runs, 2);
  ASSERT_EQ(corrected.discrepancies.size(), 2u);
  for (const DiscrepancySource& s : corrected.discrepancies) {
    ASSERT_TRUE(s.ok) << s.message;
    ASSERT_EQ(s.curves.size(), 1u);
    EXPECT_EQ(s.curves[0].data, "thick_25");
    EXPECT_NEAR(s.curves[0].max_abs, 0.005, 1e-4);  // the error at the pole, 0.006 - 0.001
    for (std::size_t i = 0; i < c.radii.size(); ++i) {
      EXPECT_NEAR(s.curves[0].correction[i], model_error(c.radii[i], 0.0, 0.0), 1e-12);
    }
  }
  // Each reference alone is an alternative (named after it); both give the same fit here.
  ASSERT_EQ(corrected.model_form.size(), 2u);
  EXPECT_EQ(corrected.model_form[0].name, "discrepancy 'ref mu 0' alone");
  EXPECT_EQ(corrected.model_form[1].edits, "corrected by 'ref mu 0.3' only");
  for (const auto& f : corrected.model_form) EXPECT_NEAR(f.values.at(0), 0.1, 1e-5) << f.name;
  // Reported: the printed summary, calibration.json and the fit's CSV (simulated includes it).
  EXPECT_NE(corrected.brief_report().find("discrepancy correction in the simulated curves"),
            std::string::npos);
  EXPECT_NE(corrected.brief_report().find("'ref mu 0' (tool.punch.friction=0): thick_25 rms"),
            std::string::npos)
      << corrected.brief_report();
  const std::string json = calibration_json(corrected, c.config);
  EXPECT_NE(json.find("\"discrepancy\": {"), std::string::npos);
  EXPECT_NE(json.find("\"max_abs_correction\""), std::string::npos);
  ASSERT_EQ(corrected.fits.size(), 1u);
  const DataSetFit& fit = corrected.fits[0];
  ASSERT_EQ(fit.correction.size(), c.radii.size());
  for (std::size_t i = 0; i < fit.x.size(); ++i) {
    EXPECT_NEAR(fit.simulated[i], fit.measured[i], 1e-6);  // data = forward + error, recovered
  }
  EXPECT_NE(fit_csv(fit).find(",discrepancy_correction\n"), std::string::npos);

  // model_form.discrepancy = []: the fit without the correction, as an alternative.
  c.config.model_forms = {{"uncorrected", {}, "test", {}, std::vector<std::string>{}}};
  c.config.discrepancy_alternatives = false;
  const auto with_plain = calibrate(c.config, quiet(), StretchingFake{});
  ASSERT_EQ(with_plain.model_form.size(), 1u);
  EXPECT_EQ(with_plain.model_form[0].edits, "without the discrepancy correction");
  EXPECT_NEAR(with_plain.model_form[0].values.at(0), plain.free_values()[0], 1e-6);
}

// An alternative that drops a data set a reference covers: the refit leaves that reference's
// curve out too (it used to stop the whole calibration with an input error after the main fit).
TEST(Discrepancy, DroppedDataSetsLeaveTheirReferencesOut) {
  Case c = friction_case(0.0);
  std::vector<double> travels;
  for (int i = 1; i <= 25; ++i) travels.push_back(i);
  auto load_at = [&](double friction) {
    Scene scene = c.scene;
    for (auto& tool : scene.tools) {
      if (tool.name == "punch") tool.friction = friction;
    }
    return make_synthetic_measurements(scene, StretchingFake{}(scene),
                                       {{MeasurementKind::kLoadTravel, "load", 0.0, travels}}, 1)
        .at(0);
  };
  c.config.data.push_back(data_set(load_at(0.1), 50.0));
  DiscrepancySpec s = source(c, "ref", 0.0, 0.0);
  s.references.emplace_back("load", load_at(0.0));
  c.config.discrepancies = {s};
  c.config.model_forms = {{"without the load", {}, "test", {"load"}, std::nullopt}};
  const auto result = calibrate(c.config, quiet(), StretchingFake{});
  ASSERT_EQ(result.termination, CalibrationTermination::kConverged) << result.message;
  ASSERT_EQ(result.discrepancies.at(0).curves.size(), 2u);
  ASSERT_EQ(result.model_form.size(), 1u);
  EXPECT_EQ(result.model_form[0].termination, "converged") << result.model_form[0].message;
  EXPECT_NEAR(result.model_form[0].values.at(0), 0.1, 1e-5);
}

// An error that grows with friction: references at 0 and 0.3 bracket the data's (0.1), the mean
// leaves a small bias, and the range over the references alone contains the truth.
TEST(Discrepancy, ParameterDependentErrorShowsInTheModelFormRange) {
  Case c = friction_case(2.0);
  c.config.discrepancies = {source(c, "ref mu 0", 0.0, 2.0), source(c, "ref mu 0.3", 0.3, 2.0)};
  const auto result = calibrate(c.config, quiet(), StretchingFake{});
  ASSERT_EQ(result.termination, CalibrationTermination::kConverged) << result.message;
  ASSERT_EQ(result.model_form_ranges.size(), 1u);
  const auto& range = result.model_form_ranges[0];
  EXPECT_LT(range.lower, 0.1);
  EXPECT_GT(range.upper, 0.1);
  EXPECT_GT(range.upper - range.lower, 1e-3);  // the references disagree
  EXPECT_TRUE(range.exceeds_interval);
}

// A reference run that fails stops the calibration before the fit, with the reason.
TEST(Discrepancy, FailedReferenceRunStopsWithTheReason) {
  Case c = friction_case(0.0);
  c.config.discrepancies = {source(c, "ref mu 0.3", 0.3, 0.0)};
  StretchingFake failing;
  failing.fail_above_friction = 0.2;
  const auto result = calibrate(c.config, quiet(), failing);
  EXPECT_EQ(result.termination, CalibrationTermination::kFailed);
  EXPECT_NE(result.message.find("discrepancy 'ref mu 0.3': the forward run at its parameters "
                                "gives no curve for thick_25: fake: no convergence"),
            std::string::npos)
      << result.message;
}

TEST(Discrepancy, ConfigReadsTheReferencesAndRejectsBadOnesInOneLine) {
  const fs::path dir = scratch_dir();
  write_scene(dir);
  write_file(dir / "load.csv", kLoadCsv);
  write_file(dir / "thick.csv", kThickCsv);
  write_file(dir / "ref_thick.csv",
             "# source: continuum\n# units: mm, 1\nr0_mm,eps_thickness\n0,-0.12\n25,-0.2\n"
             "40,-0.1\n");
  write_file(
      dir / "ref_load.csv",
      "# source: continuum\n# units: mm, kN\npunch_travel_mm,punch_force_kN\n0,0\n3.5,0.4\n");
  write_file(
      dir / "short_load.csv",
      "# source: continuum\n# units: mm, N\npunch_travel_mm,punch_force_N\n1.5,0\n3.5,400\n");
  const std::string head = R"(scene = "scene.toml"
[[parameter]]
address = "tool.punch.friction"
initial = 0.05
lower = 0.0
upper = 0.5
[[parameter]]
address = "material.hardening.n"
fixed = true
[[data]]
kind = "load_travel"
file = "load.csv"
sigma = 50.0
[[data]]
kind = "thickness_strain"
file = "thick.csv"
travel_mm = 30
sigma = 0.01
)";
  write_file(dir / "c.toml", head + R"([[discrepancy]]
name = "continuum"
set = { "tool.punch.friction" = 0.0, "blank.elements" = 30 }
files = { load = "ref_load.csv", thick = "ref_thick.csv" }
[[model_form]]
name = "uncorrected"
discrepancy = []
)");
  const CalibrationConfig c = load_calibration_config((dir / "c.toml").string());
  ASSERT_EQ(c.discrepancies.size(), 1u);
  const DiscrepancySpec& s = c.discrepancies[0];
  EXPECT_EQ(s.name, "continuum");
  EXPECT_NE(std::find(s.set.begin(), s.set.end(),
                      std::pair<std::string, std::string>{"tool.punch.friction", "0"}),
            s.set.end());
  ASSERT_EQ(s.references.size(), 2u);
  EXPECT_EQ(s.references[0].first, "load");
  EXPECT_EQ(s.references[0].second.y.at(1), 400.0);  // kN read as N
  EXPECT_EQ(s.references[1].second.kind, MeasurementKind::kThicknessStrain);
  EXPECT_EQ(s.references[1].second.travel_mm, 30.0);
  ASSERT_EQ(c.model_forms.size(), 1u);
  ASSERT_TRUE(c.model_forms[0].discrepancy.has_value());
  EXPECT_TRUE(c.model_forms[0].discrepancy->empty());

  auto error_of = [&](const std::string& tail_text) {
    write_file(dir / "bad.toml", head + tail_text);
    try {
      load_calibration_config((dir / "bad.toml").string());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string entry = "[[discrepancy]]\nname = \"ref\"\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {entry + "files = { load = \"ref_load.csv\" }\n",
       "bad.toml:19: [[discrepancy]] 'ref' needs set"},
      {entry + "set = { \"blank.elements\" = 30 }\nfiles = { load = \"ref_load.csv\" }\n",
       "bad.toml:19: discrepancy 'ref': set must give every free parameter at the value the "
       "reference was computed with (missing: tool.punch.friction)"},
      {entry + "set = { \"tool.punch.friction\" = \"low\" }\nfiles = { load = \"ref_load.csv\" }\n",
       "discrepancy 'ref': set tool.punch.friction = low must be a number"},
      {entry + "set = { \"tool.punch.friction\" = 0 }\nfiles = { lod = \"ref_load.csv\" }\n",
       "key 'discrepancy.files.lod': 'lod' is not a data set of this config (data sets: load, "
       "thick)"},
      {entry + "set = { \"tool.punch.friction\" = 0 }\nfiles = { load = \"short_load.csv\" }\n",
       "discrepancy 'ref': " + (dir / "short_load.csv").string() +
           " spans punch_travel_mm = 1.5 to 3.5, but data set 'load' needs 1 to 3 (a reference "
           "is interpolated, never extrapolated)"},
      {entry + "set = { \"tool.punch.friction\" = 0 }\nfiles = { load = \"missing.csv\" }\n",
       "missing.csv"},
      {entry + "set = { \"tool.punch.friction\" = 0 }\nfiles = { load = \"ref_load.csv\" }\n" +
           entry + "set = { \"tool.punch.friction\" = 0 }\nfiles = { load = \"ref_load.csv\" }\n",
       "discrepancy name 'ref' used twice"},
      {entry + "set = { \"tool.punch.friction\" = 0 }\nfiles = { load = \"ref_load.csv\" }\n"
               "[[model_form]]\nname = \"m\"\ndiscrepancy = [\"rf\"]\n",
       "model_form 'm': discrepancy names 'rf', which is not a [[discrepancy]] of this config"},
      {entry + "set = { \"tool.punch.friction\" = 0 }\nfile = { load = \"ref_load.csv\" }\n",
       "did you mean 'files'"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string e = error_of(text);
    EXPECT_NE(e.find(expected), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

}  // namespace
}  // namespace vs
