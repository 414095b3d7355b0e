// Quick variants of the experiments (experiments/README.md): each study in a reduced form, with
// the invariants the full studies rely on. Runs in seconds.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "../../experiments/common/calibration_cost.h"
#include "../../experiments/common/harness.h"
#include "../../experiments/common/metrics.h"
#include "../../experiments/common/stability_cases.h"
#include "../../experiments/common/step_stability.h"
#include "../../experiments/common/work_precision.h"
#ifdef VS_HAVE_SHELL3D
#include "../../experiments/common/shell3d_study.h"
#endif

namespace {

using namespace vsx;

const std::string kEx1 = scene_path(VS_SOURCE_DIR, "ex1_hemispherical_stretching");
constexpr double kInf = std::numeric_limits<double>::infinity();

vs::RunResult run_ex1(const Overrides& ov) { return run_once(make_scene(kEx1, ov), kInf).result; }

// 01_performance in small: ex1 to 20 mm at 12, 24, 48 and 69 elements (all valid meshes); the
// peak loads agree with the finest valid mesh and every run is timed.
TEST(ExperimentsQuick, PerformanceMeshRefinementConverges) {
  // Meshes up to element length = thickness (69 elements of 0.858 mm for ex1; 70 elements are
  // 0.845 mm < 0.85 mm and the solver warns); finer shell meshes are outside the thin-shell
  // model. The load at a given travel carries ~0.5% of mesh noise from the discrete contact front
  // (measured peak 24 805 / 25 427 / 25 504 / 25 623 N to 20 mm for 12 / 24 / 48 / 69 elements;
  // 70 elements give 25 356 N), so the check is agreement, not monotone order; 12 elements
  // (4.9 mm) are 3.2% low.
  std::vector<double> peak;
  for (int n : {12, 24, 48, 69}) {
    const TimedRun t = run_once(make_scene(kEx1, {{"blank.elements", std::to_string(n)},
                                                  {"process.punch_travel_mm", "20"},
                                                  {"process.output_travels_mm", "[10.0, 20.0]"}}),
                                kInf);
    ASSERT_TRUE(t.result.completed()) << t.result.message;
    EXPECT_TRUE(t.result.warnings.empty()) << n << " elements: outside the valid mesh range";
    peak.push_back(peak_load(t.result).force_N);
  }
  EXPECT_LT(rel(peak[0], peak[3]), 0.04);
  EXPECT_LT(rel(peak[1], peak[3]), 0.01);
  EXPECT_LT(rel(peak[2], peak[3]), 0.01);
}

// The issue-2 goal at the performance benchmark's speed setting (twice the default travel step,
// strain-rate cut-off 1e-2), full 30 mm: 24 elements are within 1 % of the finest valid mesh (69)
// at the same setting in peak load and pole thickness strain (measured 0.24 % / 0.83 %; the time,
// 40-44 ms CPU, is the benchmark's to measure, not a test's).
TEST(ExperimentsQuick, PerformanceSpeedSettingIsWithinOnePercentAt24Elements) {
  auto run = [](int n) {
    const TimedRun t =
        run_once(make_scene(kEx1, {{"tool.punch.friction", "0.04"},
                                   {"blank.elements", std::to_string(n)},
                                   {"numerics.max_travel_increment_per_length", "0.05"},
                                   {"numerics.strain_rate_cutoff", "1e-2"}}),
                 kInf);
    EXPECT_TRUE(t.result.completed()) << t.result.message;
    return t;
  };
  const TimedRun coarse = run(24), fine = run(69);
  ASSERT_TRUE(coarse.result.completed() && fine.result.completed());
  EXPECT_LT(rel(peak_load(coarse.result).force_N, peak_load(fine.result).force_N), 0.01);
  EXPECT_LT(rel(pole_thickness_strain(coarse.result.profiles.back()),
                pole_thickness_strain(fine.result.profiles.back())),
            0.01);
}

// 02_work_precision in small: refining elements and the step caps together reduces the error of
// the peak load and of the load curve against the finest level. Meshes 8..64 elements stay within
// the valid range (element length >= thickness: at most 69 elements for ex1). Both geometry
// updates: heun, and implicit (the axisymmetric default). For implicit the peak load is not
// compared at level 0: its step error there (+0.85 % at 1 mm steps) has the opposite sign of the
// 8-element mesh error (-1.9 %) and cancels it (measured: peak error 1.08 % at level 0, 1.33 % at
// level 1; step-converged, 8 / 16 elements give 5521 / 5538 N against 5627 N at 64;
// experiments/06_step_stability, "Implicit at 0.25 as the scene default").
TEST(ExperimentsQuick, WorkPrecisionErrorDecreasesWithRefinement) {
  EXPECT_EQ(max_valid_elements(make_scene(kEx1, {})), 69);
  for (const std::string update : {"heun", "implicit"}) {
    SCOPED_TRACE(update);
    const Overrides base{{"process.punch_travel_mm", "8"},
                         {"process.output_travels_mm", "[4.0, 8.0]"},
                         {"numerics.time_integration", update}};
    std::vector<Outcome> all;
    for (int k = 0; k < 4; ++k) {
      const double f = std::ldexp(1.0, k);
      Outcome o;
      o.setting = {"refined", k == 3 ? "L2" : fmt::format("c{}", k), base};
      o.setting.ov.push_back({"blank.elements", std::to_string(static_cast<int>(8 * f))});
      o.setting.ov.push_back({"numerics.max_travel_increment_mm", fmt::format("{}", 1.0 / f)});
      o.setting.ov.push_back({"numerics.max_travel_increment_per_length", "1e9"});
      o.setting.ov.push_back({"numerics.max_strain_increment", fmt::format("{}", 0.04 / f)});
      o.run = run_once(make_scene(kEx1, o.setting.ov), kInf);
      ASSERT_TRUE(o.run.result.completed()) << o.run.result.message;
      EXPECT_TRUE(o.run.result.warnings.empty()) << "mesh outside the valid range";
      measure(&o);
      all.push_back(std::move(o));
    }
    // Reference: the three finest levels.
    std::vector<Outcome> levels(all.begin() + 1, all.end());
    for (Outcome& o : levels) o.setting.family = "refined";
    const Reference ref = make_reference(&levels, {4.0, 8.0}, 8.0);
    ASSERT_TRUE(ref.ok) << ref.note;
    const Errors e0 = errors_against(all[0], ref), e1 = errors_against(all[1], ref);
    if (update == "heun") {
      EXPECT_LT(e1.peak, e0.peak);
    }
    EXPECT_LT(e1.curve, e0.curve);
    EXPECT_LT(e1.strain_abs, e0.strain_abs);
    EXPECT_LT(e0.combined, 0.5);
  }
}

// 03_stability in small: every case converges with sane physics or stops with a message; the
// volume is conserved; thickness stays positive.
TEST(ExperimentsQuick, StabilityCasesConvergeOrStopCleanly) {
  for (const StabilityCase& c : stability_cases(VS_SOURCE_DIR, true)) {
    const StabilityRow r = evaluate_stability(VS_SOURCE_DIR, c, 30.0);
    SCOPED_TRACE(c.name + ": " + r.run.result.message);
    EXPECT_NE(r.verdict, "GARBAGE");
    EXPECT_NE(r.verdict, "aborted");
    if (r.verdict == "stopped") {
      EXPECT_FALSE(r.run.result.message.empty());
    }
    if (r.steps > 0) {
      EXPECT_GT(r.min_thickness_ratio, 0.0);
    }
  }
}

// Thickness comes from the constant element volume, so the sheet volume is exact to round-off.
TEST(ExperimentsQuick, VolumeConservedToRoundOff) {
  for (const char* f : {"0.04", "sticking"}) {
    const StabilityRow r = evaluate_stability(VS_SOURCE_DIR,
                                              {"volume",
                                               f,
                                               "ex1_hemispherical_stretching",
                                               {{"tool.punch.friction", f},
                                                {"process.punch_travel_mm", "3"},
                                                {"process.output_travels_mm", "[3.0]"}}},
                                              30.0);
    EXPECT_LE(r.volume_drift, 1e-9) << "friction " << f;
  }
}

// Unit scaling: all lengths x 10 at the same punch speed gives the same strains and forces x 100.
TEST(ExperimentsQuick, ScaledGeometryGivesScaledAnswers) {
  const Overrides travel{{"process.punch_travel_mm", "5"}, {"process.output_travels_mm", "[5.0]"}};
  const Overrides scaled = ex1_scaled(make_scene(kEx1, travel), 10.0);
  const vs::RunResult a = run_ex1(travel), b = run_ex1(scaled);
  ASSERT_TRUE(a.completed()) << a.message;
  ASSERT_TRUE(b.completed()) << b.message;
  const ScaleMismatch m = scale_mismatch(a, b, 10.0);
  EXPECT_LT(m.force_rel_l2, 1e-3);
  EXPECT_LT(m.eps_t_max_abs, 1e-4);
}

// 06_step_stability in small: a punch-friction sweep of 2e-4 (24 elements, F at 14 mm), its
// largest deviation from a straight line ("jitter") and the load curve's roughness.
struct StepSweep {
  double jitter = 0.0, roughness = 0.0;
};
StepSweep sweep_friction(const char* integration, const char* per_length) {
  std::vector<double> mu, f;
  StepSweep out;
  for (int k = 0; k < 5; ++k) {
    const double m = 0.099 + 0.0005 * k;
    const vs::Scene scene =
        make_scene(kEx1, {{"blank.elements", "24"},
                          {"process.punch_travel_mm", "16"},
                          {"process.output_travels_mm", "[16.0]"},
                          {"material.r_value", "1.5"},
                          {"numerics.tolerance", "1e-8"},
                          {"numerics.time_integration", integration},
                          {"numerics.max_travel_increment_mm", "5"},
                          {"numerics.max_travel_increment_per_length", per_length},
                          {"tool.punch.friction", fmt::format("{:.6f}", m)}});
    const TimedRun run = run_once(scene, kInf);
    EXPECT_TRUE(run.result.completed()) << run.result.message;
    if (!run.result.completed()) return {1.0, 1.0};
    mu.push_back(m);
    f.push_back(force_at(run.result, 14.0));
    if (k == 2) out.roughness = load_roughness(run.result, 6.0, 16.0);
  }
  out.jitter = linear_fit_max_deviation(mu, f) / f.front();
  return out;
}

// The explicit (Heun) update is smooth at its default step and visibly less so at a step four
// times larger (its stability limit). Measured: jitter 1.9e-8 / 2.3e-4 of the force, load
// roughness 0.050 / 0.066; with the midpoint hardening used before Nov 2026 it was 3.7e-4 /
// 3.8e-3 and 0.042 / 0.19 (the backward-Euler hardening removed most of it).
TEST(ExperimentsQuick, StepStabilityDefaultStepIsSmoothInTheParameters) {
  const StepSweep small = sweep_friction("heun", "0.025");
  const StepSweep large = sweep_friction("heun", "0.1");
  fmt::print(
      "heun: step 0.025 l: jitter {:.2e}, roughness {:.3f}; 0.1 l: jitter {:.2e}, "
      "roughness {:.3f}\n",
      small.jitter, small.roughness, large.jitter, large.roughness);
  EXPECT_LT(small.jitter, 1e-5);
  EXPECT_LT(small.roughness, 0.1);
  EXPECT_LT(large.roughness, 0.1);
  EXPECT_GT(large.jitter, 100.0 * small.jitter);
}

// The implicit geometry update is stable where Heun is not: at 0.2 element lengths per step
// (0.49 mm) the implicit update's outputs stay smooth in the parameters to the 1e-6,
// while Heun's jitter by orders of magnitude more (measured in the 06 study at 16-20 mm:
// implicit 2e-8 at 0.1-0.4 element lengths; Heun 3e-3 at 0.2, roughness 0.24).
TEST(ExperimentsQuick, ImplicitUpdateIsSmoothWhereHeunIsUnstable) {
  const StepSweep implicit = sweep_friction("implicit", "0.2");
  const StepSweep heun = sweep_friction("heun", "0.2");
  fmt::print(
      "step 0.2 l: implicit jitter {:.2e}, roughness {:.3f}; heun jitter {:.2e}, "
      "roughness {:.3f}\n",
      implicit.jitter, implicit.roughness, heun.jitter, heun.roughness);
  EXPECT_LT(implicit.jitter, 1e-6);
  EXPECT_LT(implicit.roughness, 0.1);
  EXPECT_GT(heun.jitter, 100.0 * implicit.jitter);
  EXPECT_GT(heun.roughness, 2.0 * implicit.roughness);
}

// The implicit update with theta = 1/2 moves the geometry with the mean of the start and end
// rates (the trapezoidal rule, second order in the step); theta = 1 with the end rates only
// (backward Euler, first order). At the same step, 0.2 element lengths, the trapezoidal error
// against a converged Heun run (0.0125 element lengths) must be a small fraction of backward
// Euler's: a second-order error C2 dt^2 against a first-order C1 dt whose own halving (0.2 ->
// 0.1 l) shows it is in its asymptotic range. The bound 1/4 is what a second-order method gives
// at the step where halving it roughly halves the first-order error; an update that moved the
// geometry with the end rates whatever theta says is backward Euler and fails it with a ratio
// near 1. Measured (ex1, 24 elements, friction 0.1, to 16 mm): force error 0.2 N (theta 1/2) and
// 127 N (theta 1); thinnest-element error 1.7e-4 mm and 2.9e-3 mm; backward Euler at 0.1 l
// 58 N, 1.2e-3 mm; the reference's own step error (0.0125 -> 0.00625 l) 0.3 N, 1.4e-5 mm.
TEST(ExperimentsQuick, ImplicitHalfThetaIsSecondOrderInTheStep) {
  auto run = [](const char* integration, const char* theta, const char* per_length) {
    const vs::RunResult r = run_ex1({{"blank.elements", "24"},
                                     {"process.punch_travel_mm", "16"},
                                     {"process.output_travels_mm", "[16.0]"},
                                     {"numerics.tolerance", "1e-10"},
                                     {"numerics.max_travel_increment_mm", "5"},
                                     {"numerics.max_travel_increment_per_length", per_length},
                                     {"tool.punch.friction", "0.1"},
                                     {"numerics.time_integration", integration},
                                     {"numerics.implicit_theta", theta}});
    EXPECT_TRUE(r.completed()) << r.message;
    EXPECT_FALSE(r.steps.empty());
    if (r.steps.empty()) return std::pair<double, double>{0.0, 0.0};
    EXPECT_NEAR(r.steps.back().punch_travel_mm, 16.0, 1e-9);
    return std::pair<double, double>{r.steps.back().punch_force_N, r.steps.back().min_thickness_mm};
  };
  const auto ref = run("heun", "0.5", "0.0125");
  const auto ref_half = run("heun", "0.5", "0.00625");
  const auto trapezoid = run("implicit", "0.5", "0.2");
  const auto backward = run("implicit", "1", "0.2");
  const auto backward_half = run("implicit", "1", "0.1");
  auto err = [&](std::pair<double, double> a) {
    return std::pair<double, double>{std::abs(a.first - ref.first),
                                     std::abs(a.second - ref.second)};
  };
  const auto e_ref = std::pair<double, double>{std::abs(ref_half.first - ref.first),
                                               std::abs(ref_half.second - ref.second)};
  const auto e_tr = err(trapezoid), e_be = err(backward), e_be_half = err(backward_half);
  fmt::print(
      "error at 0.2 l: theta 1/2 {:.2f} N, {:.2e} mm; theta 1 {:.2f} N, {:.2e} mm (0.1 l: {:.2f} "
      "N, {:.2e} mm); reference {:.2f} N, {:.2e} mm\n",
      e_tr.first, e_tr.second, e_be.first, e_be.second, e_be_half.first, e_be_half.second,
      e_ref.first, e_ref.second);
  // Backward Euler's error is resolved (far above the reference's) and first order
  EXPECT_GT(e_be.first, 20.0 * e_ref.first);
  EXPECT_GT(e_be.second, 20.0 * e_ref.second);
  // (halving ratio below 2^1.5, the geometric midpoint between first order, 2, and second, 4).
  EXPECT_GT(e_be.first / e_be_half.first, 1.5);
  EXPECT_LT(e_be.first / e_be_half.first, std::pow(2.0, 1.5));
  EXPECT_GT(e_be.second / e_be_half.second, 1.5);
  EXPECT_LT(e_be.second / e_be_half.second, std::pow(2.0, 1.5));
  // The trapezoidal rule's is a small fraction of it.
  EXPECT_LT(e_tr.first, 0.25 * e_be.first);
  EXPECT_LT(e_tr.second, 0.25 * e_be.second);
}

#ifdef VS_HAVE_SHELL3D
// 05_shell3d in small (the study's --quick form, experiments/common/shell3d_study.h): the quarter
// disc of example 4a, punch friction 0.2, to 2 mm at n = 4 (48 elements), against its
// axisymmetric twin (30 elements). The run completes and stays within the stated deviations at
// 1 and 2 mm, and closer than on the coarsest mesh (n = 2); the 40-element axisymmetric run
// measures the reference's own noise. Measured (22 Nov 2026; n = 4: 48 elements, 1 085 dofs,
// ~1.6 s CPU): largest |mean-force deviation| 2.39 % (n = 2: 7.25 %), largest |force deviation|
// 2.36 %, |d eps_t| 0.0019; reference noise 0.81 % / 0.0035.
constexpr int kShell3dQuickDivisions = 4;
constexpr double kShell3dQuickNoiseTolerance = 0.015;
constexpr double kShell3dQuickMeanForceTolerance = 0.035;
constexpr double kShell3dQuickForceTolerance = 0.035;
constexpr double kShell3dQuickThicknessStrainTolerance = 0.005;

TEST(ExperimentsQuick, Shell3dQuarterDiscFollowsAxisymmetricTwin) {
  const Shell3dStudy study = shell3d_study(VS_SOURCE_DIR, true);
  const vs::Scene base = shell3d_base_scene(study);
  const AxisymRun ref = run_axisym_twin(base, study.axisym_elements);
  const AxisymRun check = run_axisym_twin(base, study.axisym_check_elements);
  ASSERT_TRUE(ref.result.completed()) << ref.result.message;
  ASSERT_TRUE(check.result.completed()) << check.result.message;
  const Deviations noise = summarise(compare_axisym(study.outputs_mm, check.result, ref.result));
  ASSERT_EQ(noise.travels, 2);
  const Shell3dRow coarsest = run_shell3d_case(base, {"mitc9", 2}, ref.result);
  const Shell3dRow row = run_shell3d_case(base, {"mitc9", kShell3dQuickDivisions}, ref.result);
  fmt::print(
      "axisym noise: dF mean {:+.2f} %, d eps_t {:.4f}; 3D n = {}: {:.2f} s, dF {:+.2f} %, "
      "dF mean {:+.2f} %, max |dF| {:.2f} %, max |dF mean| {:.2f} %, max |d eps_t| {:.4f}\n",
      100 * noise.mean_force_at_travel, noise.max_eps_thickness, kShell3dQuickDivisions, row.wall_s,
      100 * row.dev.force_at_travel, 100 * row.dev.mean_force_at_travel,
      100 * row.dev.max_abs_force, 100 * row.dev.max_abs_mean_force, row.dev.max_eps_thickness);
  ASSERT_TRUE(row.completed) << row.message;
  ASSERT_EQ(row.dev.travels, 2);
  EXPECT_LT(noise.max_abs_mean_force, kShell3dQuickNoiseTolerance);
  EXPECT_LT(row.dev.max_abs_mean_force, kShell3dQuickMeanForceTolerance);
  EXPECT_LT(row.dev.max_abs_force, kShell3dQuickForceTolerance);
  EXPECT_LT(row.dev.max_eps_thickness, kShell3dQuickThicknessStrainTolerance);
  for (const auto& c : row.cmp) EXPECT_GT(c.force_3d_N, 0.0);
  ASSERT_TRUE(coarsest.completed) << coarsest.message;
  EXPECT_LT(row.dev.max_abs_mean_force, coarsest.dev.max_abs_mean_force);
}
#endif

// 07_calibration_cost in small (experiments/common/calibration_cost.h): the twin to 10 mm (load
// at 1..10 mm, thickness strain at 10 mm), Swift K identified from a start 20 % off, the other
// parameters fixed at the truth. Data from the fit's own model (12 elements) are recovered
// exactly (optimiser and forward map are sound); data from a finer model (48 elements) carry the
// coarse model's discretisation error into K, and a finer model in the fit (24 elements) reduces
// that bias. Measured (22 Nov 2026): K +0.000 % / +0.720 % / +0.472 %, 13-14 forward runs per
// fit, 2-5 s in all. Friction is not used here: at 12 elements and 10 mm even the model's own data
// give it back 18 % off (it is weakly and not smoothly determined by these data), see the full
// study for its bias.
constexpr double kCalibrationSelfTolerance = 1e-3;
constexpr double kCalibrationCoarseBiasLimit = 0.02;

TEST(ExperimentsQuick, CalibrationCostCoarseModelBias) {
  TwinSetup setup;
  setup.scene_path = scene_path(VS_SOURCE_DIR, "ex1_hemispherical_stretching");
  setup.travel_mm = 10.0;
  setup.strain_travels_mm = {10.0};
  setup.free = {false, true, false, false};
  setup.threads = 2;
  const Overrides e12{{"blank.elements", "12"}}, e24{{"blank.elements", "24"}};
  const TwinData own = twin_data(setup, e12);
  const TwinData fine = twin_data(setup, {{"blank.elements", "48"}});
  ASSERT_TRUE(own.ok) << own.message;
  ASSERT_TRUE(fine.ok) << fine.message;
  const TwinFit self = twin_fit(setup, own, e12);
  const TwinFit coarse = twin_fit(setup, fine, e12);
  const TwinFit finer = twin_fit(setup, fine, e24);
  for (const auto& [label, f] :
       {std::pair{"12 el, own data", &self}, std::pair{"12 el, 48-el data", &coarse},
        std::pair{"24 el, 48-el data", &finer}}) {
    fmt::print("{}: K {:+.3f} %, {} forward runs, {:.1f} s\n", label, 100 * f->error[1],
               f->forward_runs, f->wall_s);
    EXPECT_TRUE(f->converged) << label << ": " << f->message;
  }
  EXPECT_LT(std::abs(self.error[1]), kCalibrationSelfTolerance);
  EXPECT_LT(std::abs(coarse.error[1]), kCalibrationCoarseBiasLimit);
  EXPECT_LT(std::abs(finer.error[1]), std::abs(coarse.error[1]));
}

}  // namespace
