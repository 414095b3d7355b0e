// cup_height_profile data: the reader (header, headerless ESAFORM form, provenance, angle checks),
// the periodic interpolation, the prediction from a 3D run's final rim profile and its errors, the
// shape-only offset, the config checks, and twin experiments against a closed-form fake 3D cup.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "calibrate.h"
#include "calibration_config.h"
#include "core/error.h"
#include "cup_height_curve.h"
#include "inverse_test_support.h"
#include "measurement.h"
#include "mesh/forming_mesh.h"
#include "residual_pipeline.h"
#include "scene/load_scene.h"
#include "synthetic.h"

namespace vs {
namespace {

using namespace vs::testing;

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

const std::string kEsaformProfile =
    std::string(VS_SOURCE_DIR) +
    "/data/measured/esaform2021-aa6016t4-cup/AA6016_Experiment_Fig91_CupProfile_angle.txt";

std::string read_error(const fs::path& path, const MeasurementReadOptions& options = {}) {
  try {
    read_measurement_file(path.string(), MeasurementKind::kCupHeightProfile, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// ---------------------------------------------------------------------------------------------
// Reader.

TEST(CupHeightProfileData, ReadsTheHeaderlessEsaformFileWithTheSourceFromTheConfig) {
  MeasurementReadOptions options;
  options.source = "Habraken et al. 2022 Fig. 91, digitised (README beside the file)";
  const Measurement m =
      read_measurement_file(kEsaformProfile, MeasurementKind::kCupHeightProfile, options);
  ASSERT_EQ(m.x.size(), 25u);
  EXPECT_DOUBLE_EQ(m.x.front(), 0.480331);
  EXPECT_DOUBLE_EQ(m.y.front(), 34.515);
  EXPECT_DOUBLE_EQ(m.x[12], 180.217);
  EXPECT_DOUBLE_EQ(m.y[12], 35.256);
  EXPECT_DOUBLE_EQ(m.x.back(), 359.954);
  EXPECT_TRUE(m.point_sigma.empty());
  ASSERT_EQ(m.provenance.size(), 2u);
  EXPECT_EQ(m.provenance[0].first, "source");
  EXPECT_EQ(m.provenance[0].second, options.source);
  EXPECT_EQ(m.provenance[1].first, "units");
  EXPECT_EQ(measurement_kind_from_string("cup_height_profile", "test"),
            MeasurementKind::kCupHeightProfile);
  EXPECT_EQ(abscissa_name(MeasurementKind::kCupHeightProfile), "angle_from_rd_deg");
  EXPECT_EQ(ordinate_name(MeasurementKind::kCupHeightProfile), "cup_height_mm");
  EXPECT_EQ(ordinate_unit(MeasurementKind::kCupHeightProfile), "mm");
  EXPECT_FALSE(is_strain_profile(MeasurementKind::kCupHeightProfile));
}

TEST(CupHeightProfileData, HeaderlessNeedsOneSource) {
  EXPECT_NE(read_error(kEsaformProfile).find("data.source"), std::string::npos);
  const fs::path dir = scratch_dir();
  write_file(dir / "own.txt", "# source: lab book 3\n0 34.5\n90 35.0\n180 34.6\n");
  // Space-separated rows, the file's own source, units implied by the form.
  const Measurement m =
      read_measurement_csv((dir / "own.txt").string(), MeasurementKind::kCupHeightProfile);
  ASSERT_EQ(m.x.size(), 3u);
  EXPECT_DOUBLE_EQ(m.x[1], 90.0);
  EXPECT_DOUBLE_EQ(m.y[2], 34.6);
  MeasurementReadOptions twice;
  twice.source = "config";
  EXPECT_NE(read_error(dir / "own.txt", twice).find("state it once"), std::string::npos);
}

TEST(CupHeightProfileData, ReadsTheHeaderFormWithSigmaAndChecksUnits) {
  const fs::path dir = scratch_dir();
  write_file(dir / "p.csv",
             "# source: s\n# units: deg, mm\nangle_from_rd_deg,cup_height_mm,sigma\n"
             "0,34,0.1\n45,33,0.2\n90,35,0.1\n");
  const Measurement m =
      read_measurement_csv((dir / "p.csv").string(), MeasurementKind::kCupHeightProfile);
  ASSERT_EQ(m.point_sigma.size(), 3u);
  EXPECT_DOUBLE_EQ(m.point_sigma[1], 0.2);
  EXPECT_DOUBLE_EQ(m.y[1], 33.0);
  write_file(dir / "units.csv",
             "# source: s\n# units: mm, mm\nangle_from_rd_deg,cup_height_mm\n0,34\n90,35\n");
  EXPECT_NE(read_error(dir / "units.csv").find("abscissa is in deg"), std::string::npos);
  write_file(dir / "units2.txt", "# source: s\n# units: deg, N\n0, 34\n90, 35\n");
  EXPECT_NE(read_error(dir / "units2.txt").find("units2.txt:2: units"), std::string::npos);
}

TEST(CupHeightProfileData, RejectsAnglesOutsideOneTurn) {
  const fs::path dir = scratch_dir();
  const std::string h = "# source: s\n";
  write_file(dir / "beyond.txt", h + "10, 34\n370, 35\n");
  EXPECT_NE(read_error(dir / "beyond.txt").find("beyond.txt:3: angle_from_rd_deg = 370"),
            std::string::npos);
  write_file(dir / "turn.txt", h + "0, 34\n180, 35\n360, 34\n");
  EXPECT_NE(read_error(dir / "turn.txt").find("no angle twice modulo 360"), std::string::npos);
  write_file(dir / "down.txt", h + "0, 34\n180, 35\n90, 34\n");
  EXPECT_NE(read_error(dir / "down.txt").find("does not increase"), std::string::npos);
  write_file(dir / "three.txt", h + "0, 34, 1\n");
  EXPECT_NE(
      read_error(dir / "three.txt").find("three.txt:2: a headerless cup profile has 2 numbers"),
      std::string::npos);
  write_file(dir / "junk.txt", h + "0, 34\n90, 3x\n");
  EXPECT_NE(read_error(dir / "junk.txt").find("junk.txt:3: '3x' is not a number"),
            std::string::npos);
}

TEST(CupHeightProfileData, ReadsARunsOwnCupProfileCsv) {
  const fs::path dir = scratch_dir();
  write_file(dir / "cup_profile.csv",
             "# punch_travel_mm=42, rolling_direction_deg=0, unfolded=1\n"
             "angle_from_rd_deg,cup_height_mm,x_mm,y_mm,z_mm\n"
             "0,34.1,40,0,-30\n45,33.2,30,30,-29\n90,34.3,0,40,-30\n");
  const Measurement m =
      read_measurement_csv((dir / "cup_profile.csv").string(), MeasurementKind::kCupHeightProfile);
  ASSERT_EQ(m.x.size(), 3u);
  EXPECT_DOUBLE_EQ(m.y[1], 33.2);
  EXPECT_EQ(m.provenance[0].first, "source");
}

// ---------------------------------------------------------------------------------------------
// Periodic interpolation.

TEST(CupHeightProfileCurve, PeriodicInterpolationJoinsAcrossZero) {
  const std::vector<double> a = {10.0, 100.0, 250.0};
  const std::vector<double> v = {1.0, 2.0, 4.0};
  EXPECT_DOUBLE_EQ(periodic_interpolate_deg(a, v, 10.0), 1.0);
  EXPECT_DOUBLE_EQ(periodic_interpolate_deg(a, v, 55.0), 1.5);
  EXPECT_DOUBLE_EQ(periodic_interpolate_deg(a, v, 250.0), 4.0);
  // From (250, 4) to (370, 1): 4 - 3 t with t = (angle - 250) / 120.
  EXPECT_DOUBLE_EQ(periodic_interpolate_deg(a, v, 300.0), 4.0 - 3.0 * 50.0 / 120.0);
  EXPECT_DOUBLE_EQ(periodic_interpolate_deg(a, v, 0.0), 4.0 - 3.0 * 110.0 / 120.0);
  EXPECT_DOUBLE_EQ(periodic_interpolate_deg(a, v, 5.0), 4.0 - 3.0 * 115.0 / 120.0);
  // Any turn.
  EXPECT_DOUBLE_EQ(periodic_interpolate_deg(a, v, -60.0), periodic_interpolate_deg(a, v, 300.0));
  EXPECT_DOUBLE_EQ(periodic_interpolate_deg(a, v, 775.0), 1.5);
  EXPECT_DOUBLE_EQ(periodic_interpolate_deg(a, v, 360.0), periodic_interpolate_deg(a, v, 0.0));
  EXPECT_TRUE(std::isnan(periodic_interpolate_deg({10.0}, {1.0}, 10.0)));
}

// ---------------------------------------------------------------------------------------------
// A closed-form 3D cup: the rim hangs H(theta) below the bottom, with
//   H = 33 + rbar + A4 cos(4 theta) + A2 cos(2 theta),
//   A4 = 1.5 (r0 + r90 - 2 r45) / (1 + rbar),  A2 = 0.8 (r90 - r0),  rbar = (r0 + 2 r45 + r90) / 4,
// ears at 0 and 90 deg when r45 is the smallest, as for Hill 1948; the mean height grows with
// rbar. Every node is moved to 0.6 of its radius and down in proportion to its radius, thickness
// 1 mm: the rim height of the cup profile is H at the rim nodes exactly.

double fake_height(const AnisotropySpec& a, double theta_deg) {
  const double rbar = 0.25 * (a.r0 + 2.0 * a.r45 + a.r90);
  return 33.0 + rbar +
         1.5 * (a.r0 + a.r90 - 2.0 * a.r45) / (1.0 + rbar) * std::cos(4.0 * rad(theta_deg)) +
         0.8 * (a.r90 - a.r0) * std::cos(2.0 * rad(theta_deg));
}

struct CupFake {
  bool fail = false;
  RunResult operator()(const Scene& scene) const {
    RunResult run;
    run.geometry = Geometry::kShell3d;
    auto shell = std::make_shared<ShellFields>();
    shell->mesh = shell3d::forming_mesh(scene);
    ShellStage st;
    st.punch_travel_mm = scene.process.punch_travel_mm;
    for (const Eigen::Vector3d& x0 : shell->mesh.nodes) {
      const double r0 = x0.head<2>().norm();
      const double theta_deg = std::atan2(x0.y(), x0.x()) * 180.0 / kPi;
      const double h = fake_height(scene.material.anisotropy, theta_deg);
      st.x.emplace_back(0.6 * x0.x(), 0.6 * x0.y(), -(r0 / scene.blank.radius_mm) * (h - 0.5));
      st.thickness_mm.push_back(1.0);
      st.contact_tool.push_back(-1);
    }
    shell->stages.push_back(st);
    run.shell = shell;
    StepRecord step;
    step.punch_travel_mm = scene.process.punch_travel_mm;
    run.steps.push_back(step);
    if (fail) {
      run.termination = Termination::kFailed;
      run.message = "diverged at 12 mm";
    }
    return run;
  }
};

constexpr const char* kCupScene = R"(title = "fake cup"
geometry = "shell3d"
[blank]
radius_mm = 50.0
thickness_mm = 1.0
edge = "free"
shape = "circle"
symmetry = "quarter"
divisions = 3
[material.anisotropy]
model = "hill48_r"
r0 = 0.526
r45 = 0.253
r90 = 0.601
[material.hardening]
law = "swift"
K_MPa = 478.2
eps0 = 0.0068
n = 0.2895
[[tool]]
name = "punch"
kind = "flat_punch"
radius_mm = 30.0
profile_radius_mm = 5.0
friction = 0.07
[[tool]]
name = "die"
kind = "die"
radius_mm = 31.2
profile_radius_mm = 10.0
friction = 0.07
[[tool]]
name = "holder"
kind = "blank_holder"
force_N = 10000.0
friction = 0.07
[process]
punch_travel_mm = 40.0
)";

fs::path write_cup_scene(const fs::path& dir, const std::string& text = kCupScene) {
  write_file(dir / "cup.toml", text);
  return dir / "cup.toml";
}

Measurement cup_measurement(std::vector<double> angles) {
  Measurement m;
  m.name = "cup";
  m.kind = MeasurementKind::kCupHeightProfile;
  m.x = std::move(angles);
  m.y.assign(m.x.size(), 34.0);
  return m;
}

TEST(CupHeightProfileCurve, FinalRimProfileAtTheMeasuredAngles) {
  const fs::path dir = scratch_dir();
  const Scene scene = load_scene(write_cup_scene(dir).string());
  const RunResult run = CupFake{}(scene);
  // Divisions 3: rim nodes every 7.5 deg; at them the curve is the closed form, between them the
  // chord.
  const Measurement m = cup_measurement({0.0, 15.0, 97.5, 183.75, 352.5});
  const SimulatedCurve c = simulate_curve(m, run, &scene);
  ASSERT_TRUE(c.ok) << c.message;
  const AnisotropySpec& a = scene.material.anisotropy;
  EXPECT_NEAR(c.y[0], fake_height(a, 0.0), 1e-12);
  EXPECT_NEAR(c.y[1], fake_height(a, 15.0), 1e-12);
  EXPECT_NEAR(c.y[2], fake_height(a, 97.5), 1e-12);
  EXPECT_NEAR(c.y[3], 0.5 * (fake_height(a, 180.0) + fake_height(a, 187.5)), 1e-12);
  EXPECT_NEAR(c.y[4], fake_height(a, 352.5), 1e-12);
  // Not a flat profile: the test would notice a constant.
  EXPECT_GT(c.y[0] - c.y[4], 0.05);
}

TEST(CupHeightProfileCurve, ClearErrorsWithoutAFinalRimProfile) {
  const fs::path dir = scratch_dir();
  const Scene scene = load_scene(write_cup_scene(dir).string());
  const Measurement m = cup_measurement({0.0, 45.0});
  EXPECT_NE(simulate_curve(m, CupFake{}(scene)).message.find("need the scene"), std::string::npos);
  const SimulatedCurve failed = simulate_curve(m, CupFake{true}(scene), &scene);
  EXPECT_FALSE(failed.ok);
  EXPECT_NE(failed.message.find("did not complete"), std::string::npos);
  EXPECT_NE(failed.message.find("diverged at 12 mm"), std::string::npos);
  RunResult axisymmetric;
  EXPECT_NE(simulate_curve(m, axisymmetric, &scene).message.find("shell3d"), std::string::npos);
  Scene clamped = scene;
  clamped.blank.edge = EdgeCondition::kClamped;
  EXPECT_NE(simulate_curve(m, CupFake{}(scene), &clamped).message.find("blank edge is not free"),
            std::string::npos);
}

TEST(CupHeightProfileCurve, ShapeOnlyRemovesTheWeightedBestOffset) {
  const fs::path dir = scratch_dir();
  const Scene scene = load_scene(write_cup_scene(dir).string());
  const RunResult run = CupFake{}(scene);
  DataSet d;
  d.measurement = cup_measurement({0.0, 30.0, 45.0, 90.0, 200.0});
  d.scene_spec = std::make_shared<const Scene>(scene);
  d.weights = {10.0, 10.0, 20.0, 10.0, 5.0};
  const SimulatedCurve exact = simulate_curve(d.measurement, run, &scene);
  ASSERT_TRUE(exact.ok);
  // Measured = simulated + 0.7 mm: the shape fits exactly, the absolute heights do not.
  for (std::size_t i = 0; i < exact.y.size(); ++i) d.measurement.y[i] = exact.y[i] + 0.7;
  ResidualPipeline absolute({d});
  const Residuals ra = absolute.residuals({run});
  ASSERT_TRUE(ra.ok);
  for (Eigen::Index i = 0; i < ra.values.size(); ++i) {
    EXPECT_NEAR(ra.values[i], -0.7 * d.weights[static_cast<std::size_t>(i)], 1e-10);
  }
  d.shape_only = true;
  ResidualPipeline shape({d});
  const Residuals rs = shape.residuals({run});
  ASSERT_TRUE(rs.ok);
  EXPECT_LT(rs.values.cwiseAbs().maxCoeff(), 1e-10);
  // A measured bump at one point: the offset is the weighted mean, c = w^2 bump / sum w^2, and the
  // weighted residuals sum (with weights w) to zero.
  d.measurement.y = exact.y;
  d.measurement.y[2] += 0.3;
  EXPECT_NEAR(shape_offset(exact.y, d.measurement.y, d.weights), 400.0 * 0.3 / 725.0, 1e-14);
  const Residuals rb = ResidualPipeline({d}).residuals({run});
  double weighted_sum = 0.0;
  for (Eigen::Index i = 0; i < rb.values.size(); ++i) {
    weighted_sum += d.weights[static_cast<std::size_t>(i)] * rb.values[i];
  }
  EXPECT_NEAR(weighted_sum, 0.0, 1e-10);
  EXPECT_NEAR(rb.values[2], 20.0 * (400.0 * 0.3 / 725.0 - 0.3), 1e-10);
}

// ---------------------------------------------------------------------------------------------
// Twin experiments: data from the fake at the truth, fits from other starts.

struct CupTwin {
  fs::path dir;
  CalibrationConfig config;
};

CupTwin cup_twin(double offset_mm, bool shape_only, bool fit_r0) {
  CupTwin t;
  t.dir = scratch_dir();
  const fs::path scene_file = write_cup_scene(t.dir);
  const Scene scene = load_scene(scene_file.string());
  std::vector<double> angles;  // every 15 deg from 2.5, as a digitised figure, not at nodes
  for (int k = 0; k < 24; ++k) angles.push_back(2.5 + 15.0 * k);
  const auto measured = make_synthetic_measurements(
      scene, CupFake{}(scene), {{MeasurementKind::kCupHeightProfile, "cup", 0.0, angles, 0.0, 0.0}},
      1);
  Measurement m = measured.front();
  for (double& y : m.y) y += offset_mm;
  t.config.scenes = {{"scene", scene_file.string(), "test"}};
  t.config.parameters = {
      param("material.anisotropy.r0", fit_r0 ? 0.7 : 0.526, 0.1, 2.0, 0.2, !fit_r0),
      param("material.anisotropy.r45", 0.45, 0.1, 2.0, 0.2),
      param("material.anisotropy.r90", 0.40, 0.1, 2.0, 0.2),
  };
  DataSpec d = data_set(m, 0.05);
  d.shape_only = shape_only;
  t.config.data.push_back(d);
  t.config.optimizer.threads = 2;
  t.config.optimizer.noise_floor_factor = 0.0;
  return t;
}

TEST(CupHeightProfileCalibration, RecoversTheThreeRValuesFromAbsoluteHeights) {
  const CupTwin t = cup_twin(0.0, false, true);
  const CalibrationResult result = calibrate(t.config, quiet(), CupFake{});
  ASSERT_NE(result.termination, CalibrationTermination::kFailed) << result.message;
  const Eigen::VectorXd x = result.free_values();
  EXPECT_NEAR(x[0], 0.526, 1e-6);
  EXPECT_NEAR(x[1], 0.253, 1e-6);
  EXPECT_NEAR(x[2], 0.601, 1e-6);
  ASSERT_EQ(result.fits.size(), 1u);
  EXPECT_LT(result.fits[0].rms_difference, 1e-8);
}

TEST(CupHeightProfileCalibration, ShapeOnlyIgnoresAnOffsetOfTheMeasuredHeights) {
  // The measured cup 0.9 mm higher than the model makes it (friction, hardening): fitting the
  // absolute heights pulls the r-values to raise the mean, the shape-only fit does not.
  const CupTwin shape = cup_twin(0.9, true, false);
  const CalibrationResult rs = calibrate(shape.config, quiet(), CupFake{});
  ASSERT_NE(rs.termination, CalibrationTermination::kFailed) << rs.message;
  EXPECT_NEAR(rs.free_values()[0], 0.253, 1e-6);
  EXPECT_NEAR(rs.free_values()[1], 0.601, 1e-6);
  EXPECT_NEAR(rs.fits[0].shape_offset_mm, 0.9, 1e-6);
  const CupTwin absolute = cup_twin(0.9, false, false);
  const CalibrationResult ra = calibrate(absolute.config, quiet(), CupFake{});
  EXPECT_GT(std::abs(ra.free_values()[0] - 0.253) + std::abs(ra.free_values()[1] - 0.601), 0.05);
}

TEST(CupHeightProfileCalibration, ScenesAndParametersTheRimNeedsAreChecked) {
  CupTwin t = cup_twin(0.0, true, false);
  t.config.parameters.push_back(param("blank.radius_mm", 50.0, 45.0, 55.0, 1.0));
  try {
    calibrate(t.config, quiet(), CupFake{});
    ADD_FAILURE() << "a blank parameter was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("blank.radius_mm"), std::string::npos) << e.what();
  }
  CupTwin axi = cup_twin(0.0, true, false);
  write_file(axi.dir / "axi.toml", kSceneToml);
  axi.config.scenes[0].path = (axi.dir / "axi.toml").string();
  axi.config.parameters = {param("material.r_value", 1.0, 0.5, 2.0, 0.5)};
  try {
    calibrate(axi.config, quiet(), CupFake{});
    ADD_FAILURE() << "an axisymmetric scene was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs a 3D cup"), std::string::npos) << e.what();
  }
}

TEST(CupHeightProfileConfig, KeysOfTheDataTable) {
  const fs::path dir = scratch_dir();
  write_cup_scene(dir);
  const std::string head =
      "scene = \"cup.toml\"\n[[parameter]]\naddress = "
      "\"material.anisotropy.r45\"\nlower = 0.1\nupper = 1.0\n"
      "[[data]]\nkind = \"cup_height_profile\"\nfile = \"" +
      kEsaformProfile + "\"\nsigma = 0.1\n";
  const std::string source = "source = \"Habraken et al. 2022, Fig. 91\"\n";
  write_file(dir / "ok.toml", head + source + "shape_only = true\n");
  const CalibrationConfig config = load_calibration_config((dir / "ok.toml").string());
  ASSERT_EQ(config.data.size(), 1u);
  EXPECT_TRUE(config.data[0].shape_only);
  EXPECT_EQ(config.data[0].measurement.x.size(), 25u);
  EXPECT_EQ(config.data[0].measurement.provenance[0].second, "Habraken et al. 2022, Fig. 91");
  auto error_of = [&](const std::string& name, const std::string& text) {
    write_file(dir / name, text);
    try {
      load_calibration_config((dir / name).string());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of("travel.toml", head + source + "travel_mm = 40\n")
                .find("travel.toml:11: key 'data.travel_mm'"),
            std::string::npos);
  EXPECT_NE(error_of("nosource.toml", head).find("data.source"), std::string::npos);
  write_file(dir / "load.csv", kLoadCsv);
  EXPECT_NE(error_of("shape.toml",
                     "scene = \"cup.toml\"\n[[parameter]]\naddress = \"tool.punch.friction\"\n"
                     "[[data]]\nkind = \"load_travel\"\nfile = \"load.csv\"\nsigma = 1\n"
                     "shape_only = true\n")
                .find("shape_only applies to cup_height_profile"),
            std::string::npos);
}

}  // namespace
}  // namespace vs
