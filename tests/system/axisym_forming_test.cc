// Whole forming runs of the axisymmetric solver: equilibrium, volume, thickness, and the trends
// the paper reports for hemispherical stretching (section 5.1), on a coarse mesh for speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "../../experiments/common/axisym_comparison.h"
#include "../../experiments/common/metrics.h"
#include "../../experiments/common/stability.h"
#include "forming_util.h"
#include "output/suspect_results.h"

namespace vs {
namespace {

using test::load_with;

const char* kStretch = "ex1_hemispherical_stretching.toml";

RunResult Stretch(const std::string& friction, const std::string& elements = "40",
                  std::vector<std::pair<std::string, std::string>> more = {}) {
  std::vector<std::pair<std::string, std::string>> set = {
      {"tool.punch.friction", friction}, {"blank.elements", elements}, {"output.history", "false"}};
  set.insert(set.end(), more.begin(), more.end());
  return simulate(load_with(kStretch, set));
}

TEST(AxisymForming, PunchForceEqualsForceThroughEveryFreeCircle) {
  const RunResult r = Stretch("0.04");
  ASSERT_TRUE(r.completed()) << r.message;
  ASSERT_EQ(r.profiles.size(), 4u);  // 10, 20, 30 mm and the final state
  for (std::size_t k = 0; k < 3; ++k) {
    const Profile& p = r.profiles[k];
    // Punch force of the step at this travel.
    double F = 0.0;
    for (const auto& s : r.steps) {
      if (std::abs(s.punch_travel_mm - p.punch_travel_mm) < 1e-9) F = s.punch_force_N;
    }
    ASSERT_GT(F, 0.0);
    int checked = 0;
    for (std::size_t e = 0; e < p.contact.size(); ++e) {
      if (p.contact[e]) continue;  // unsupported region only
      EXPECT_NEAR(p.vertical_force_N[e] / F, 1.0, 0.01)
          << "travel " << p.punch_travel_mm << " element " << e;
      ++checked;
    }
    EXPECT_GT(checked, 3);
  }
}

TEST(AxisymForming, VolumeIsConservedAndThicknessStaysPositive) {
  const RunResult r = Stretch("0.2");
  ASSERT_TRUE(r.completed()) << r.message;
  // The volume of every output profile, summed here from its deformed nodes and element
  // thicknesses as truncated cones (pi (r_a + r_b) |x_b - x_a| h), against the blank's
  // pi R^2 h0 (not the solver's own volume_mm3): the thickness update must divide each element's
  // initial volume by its current mid-surface area (a thickness from the inner node's radius, or
  // from the initial length, fails it by > 1e-3).
  const double v0 = std::numbers::pi * 59.18 * 59.18 * 0.85;
  ASSERT_EQ(r.profiles.size(), 4u);
  for (const Profile& p : r.profiles) {
    ASSERT_EQ(p.node_r_mm.size(), p.thickness_mm.size() + 1);
    double v = 0.0;
    for (std::size_t e = 0; e < p.thickness_mm.size(); ++e) {
      const double dr = p.node_r_mm[e + 1] - p.node_r_mm[e],
                   dz = p.node_z_mm[e + 1] - p.node_z_mm[e];
      v += std::numbers::pi * (p.node_r_mm[e] + p.node_r_mm[e + 1]) * std::hypot(dr, dz) *
           p.thickness_mm[e];
    }
    EXPECT_NEAR(v / v0, 1.0, 1e-9) << "travel " << p.punch_travel_mm;
  }
  for (const auto& s : r.steps) EXPECT_GT(s.min_thickness_mm, 0.0);
  // Thickness strain is the negative sum of the in-plane strains (incompressibility).
  const Profile& p = r.profiles.back();
  for (std::size_t e = 0; e < p.r0_mm.size(); ++e) {
    EXPECT_NEAR(p.eps_thickness[e], -(p.eps_meridional[e] + p.eps_circumferential[e]), 1e-12);
  }
}

TEST(AxisymForming, FrictionMovesTheThinnestPointOffThePoleAndOutward) {
  const RunResult r0 = Stretch("0");
  const RunResult r4 = Stretch("0.04");
  const RunResult r2 = Stretch("0.2");
  ASSERT_TRUE(r0.completed() && r4.completed() && r2.completed());
  // No friction: the thinning is greatest on a flat plateau around the pole (the pole element is
  // within 5% of the thinnest: measured 4.7%, 1.7%, 1.1% at 10, 20, 30 mm; the discrete maximum
  // sits at r0 = 3.7-5.2 mm, inside the plateau), unlike with friction below.
  constexpr double kPlateau_mm = 6.5;
  for (std::size_t k = 0; k < 3; ++k) {
    const Profile& p = r0.profiles[k];
    EXPECT_GT(p.eps_thickness.front() / p.eps_thickness[test::thinnest(p)], 0.95) << k;
    EXPECT_LT(p.r0_mm[test::thinnest(p)], kPlateau_mm) << k;
  }
  // With friction the peak is off the pole; it lies further out for more friction...
  const Profile& p4 = r4.profiles[2];
  const Profile& p2 = r2.profiles[2];
  EXPECT_GT(p4.r0_mm[test::thinnest(p4)], kPlateau_mm);
  EXPECT_LT(p2.eps_thickness.front() / p2.eps_thickness[test::thinnest(p2)], 0.9);
  EXPECT_GT(p2.r0_mm[test::thinnest(p2)], p4.r0_mm[test::thinnest(p4)]);
  // ...and moves outward with travel (paper figs. 9-11).
  EXPECT_GT(r2.profiles[2].r0_mm[test::thinnest(r2.profiles[2])],
            r2.profiles[0].r0_mm[test::thinnest(r2.profiles[0])]);
  // The load rises slightly with friction (paper fig. 6): within 10% of frictionless.
  const double f0 = test::peak_force(r0), f2 = test::peak_force(r2);
  EXPECT_GT(f2, f0);
  EXPECT_LT(f2, 1.1 * f0);
}

TEST(AxisymForming, StickingFrictionRuns) {
  const RunResult r = Stretch("inf");
  ASSERT_TRUE(r.completed()) << r.message;
  // Material in contact cannot slide: the pole region hardly thins, the crown thins most.
  const Profile& p = r.profiles[2];
  EXPECT_GT(p.eps_thickness.front(), -0.02);
  EXPECT_LT(p.eps_thickness[test::thinnest(p)], -0.1);
}

TEST(AxisymForming, StickingIsNeitherPathNorMeshSensitive) {
  // The edge node of a stuck patch used to attach and release at every step (stuck it pulls,
  // free it runs into the punch), which made sticking results depend on the solver tolerance
  // (peak load 43.7 / 45.5 / 44.6 kN at tolerance 1e-6 / 3e-7 / 1e-7, 48 elements) and on the
  // mesh (44.4 / 45.8 / 48.9 kN at 24 / 48 / 69 elements). It now slides without friction until
  // the patch grows past it: 49.55 kN at every tolerance; 50.4 / 49.6 / 50.2 kN.
  // The mesh check is on the mean force over the last 5 mm (work / travel), not on the peak: the
  // load curve near 30 mm is a sawtooth (an element at the edge of the stuck cap necks, sticks to
  // the punch, and the force jumps: 24 elements, step-converged, 46.1 kN at 29.6 mm, 51.5 kN at
  // 30 mm), so the peak is wherever the last jump falls. Converged in the step (grid 0.0078 mm,
  // Heun / implicit) the peak is 51.53 / 51.51 kN at 24 and 49.29 / 49.21 kN at 48 elements,
  // 4.5 % apart: a 3 % bound on it held only at Heun's 0.025 element lengths per step (50.51 /
  // 49.69 kN), failed at half that step (51.28 / 49.46 kN, 3.6 %) and at implicit 0.25 (46.90 /
  // 50.92 kN). The mean over 25-30 mm is 43.84 / 44.30 kN converged (1.1 %), 43.88 / 44.40 kN
  // at Heun 0.025 and 43.83 / 44.23 kN at implicit 0.25 (within 0.2 % of converged).
  const RunResult a = Stretch("inf", "24");
  const RunResult b = Stretch("inf", "24", {{"numerics.tolerance", "1e-7"}});
  const RunResult c = Stretch("inf", "48");
  ASSERT_TRUE(a.completed() && b.completed() && c.completed());
  EXPECT_NEAR(test::peak_force(b) / test::peak_force(a), 1.0, 2e-3);
  EXPECT_NEAR(shell3d::mean_force(c.steps, 25.0, 30.0) / shell3d::mean_force(a.steps, 25.0, 30.0),
              1.0, 0.03);
  const double ha = a.profiles.back().thickness_mm[test::thinnest(a.profiles.back())];
  const double hc = c.profiles.back().thickness_mm[test::thinnest(c.profiles.back())];
  EXPECT_NEAR(hc / ha, 1.0, 0.03);
}

// Rate-independent flow with hardening has a stiff mode: two elements carrying the same load
// flow in whatever proportion keeps their flow stresses equal. With the hardening seen by the
// solve at the midpoint of the step (weight 1/2, before Nov 2026) a yield-stress difference flips
// sign every step undamped, and the strain increments alternate step to step; backward Euler
// (AxisymModel::freeze_material) damps it. Measure: rms over the steps past 10 mm of an element's
// effective-strain increment per travel minus the mean of its neighbours in time, over its mean.
// Measured at 0.05 element lengths per step (24 elements): pole element 0.19 before, 0.07 now;
// near the rim 0.73 before, 0.19 now.
TEST(AxisymForming, StrainIncrementsDoNotAlternateStepToStep) {
  const RunResult r =
      Stretch("0.04", "24",
              {{"output.history", "true"}, {"numerics.max_travel_increment_per_length", "0.05"}});
  ASSERT_TRUE(r.completed()) << r.message;
  auto alternation = [&](std::size_t e) {
    std::vector<double> rate;
    for (std::size_t k = 1; k < r.history.size(); ++k) {
      const Profile& a = r.history[k - 1];
      const Profile& b = r.history[k];
      const double dT = b.punch_travel_mm - a.punch_travel_mm;
      if (dT <= 0.0 || b.punch_travel_mm < 10.0) continue;
      rate.push_back((b.eps_effective[e] - a.eps_effective[e]) / dT);
    }
    double s2 = 0.0, mean = 0.0;
    for (std::size_t k = 1; k + 1 < rate.size(); ++k) {
      const double d = rate[k] - 0.5 * (rate[k - 1] + rate[k + 1]);
      s2 += d * d;
      mean += rate[k];
    }
    const double n = static_cast<double>(rate.size() - 2);
    return std::sqrt(s2 / n) / (mean / n);
  };
  EXPECT_LT(alternation(0), 0.12);
  EXPECT_LT(alternation(21), 0.4);
}

TEST(AxisymForming, RateIndependentResultsDoNotDependOnPunchSpeed) {
  const RunResult a =
      Stretch("0.04", "30",
              {{"process.punch_travel_mm", "10"}, {"process.output_travels_mm", "[5.0, 10.0]"}});
  const RunResult b = Stretch("0.04", "30",
                              {{"process.punch_travel_mm", "10"},
                               {"process.output_travels_mm", "[5.0, 10.0]"},
                               {"process.punch_speed_mm_per_s", "25"}});
  ASSERT_TRUE(a.completed() && b.completed());
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t i = 0; i < a.steps.size(); ++i) {
    EXPECT_NEAR(a.steps[i].punch_travel_mm, b.steps[i].punch_travel_mm, 1e-9);
    EXPECT_NEAR(a.steps[i].punch_force_N / b.steps[i].punch_force_N, 1.0, 1e-6);
  }
}

TEST(AxisymForming, DeterministicBitForBit) {
  const RunResult a = Stretch("0.2", "24");
  const RunResult b = Stretch("0.2", "24");
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t i = 0; i < a.steps.size(); ++i) {
    EXPECT_EQ(a.steps[i].punch_force_N, b.steps[i].punch_force_N);
  }
  EXPECT_EQ(a.profiles.back().thickness_mm, b.profiles.back().thickness_mm);
}

TEST(AxisymForming, ConsistentFrictionGivesTheLaggedAnswerInFewerIterations) {
  // Friction from the current normal reactions with their Newton derivative, against the lagged
  // and relaxed reactions: the same converged solutions (to the solver tolerance, 1e-6), with
  // fewer iterations (measured: 2.7x at 48 elements, friction 0.2, 30 mm).
  const Scene scene = load_with(kStretch, {{"tool.punch.friction", "0.2"},
                                           {"blank.elements", "24"},
                                           {"output.history", "false"},
                                           {"process.punch_travel_mm", "10"},
                                           {"process.output_travels_mm", "[5.0, 10.0]"}});
  RunOptions lagged;
  lagged.consistent_friction = false;
  const RunResult a = simulate(scene, lagged);
  const RunResult b = simulate(scene);
  ASSERT_TRUE(a.completed() && b.completed()) << a.message << b.message;
  ASSERT_EQ(a.steps.size(), b.steps.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.steps.size(); ++i) {
    worst = std::max(worst, std::abs(a.steps[i].punch_force_N - b.steps[i].punch_force_N));
  }
  EXPECT_LT(worst, 1e-4 * test::peak_force(a));
  const Profile& pa = a.profiles.back();
  const Profile& pb = b.profiles.back();
  for (std::size_t e = 0; e < pa.eps_thickness.size(); ++e) {
    EXPECT_NEAR(pa.eps_thickness[e], pb.eps_thickness[e], 1e-5) << e;
  }
  EXPECT_LT(b.total_iterations, 0.7 * a.total_iterations);
  EXPECT_EQ(a.friction_fallbacks, 0);
}

TEST(AxisymForming, FailureStopsWithAMessageAndKeepsTheSteps) {
  // Two iterations per step cannot converge: the run must stop cleanly, not crash or loop.
  const RunResult r =
      Stretch("0.04", "20", {{"numerics.max_iterations", "2"}, {"numerics.max_cutbacks", "2"}});
  EXPECT_FALSE(r.completed());
  EXPECT_FALSE(r.message.empty());
  EXPECT_FALSE(r.profiles.empty());
}

TEST(AxisymForming, DeepDrawingAndCupScenesRunToTheEnd) {
  for (const char* name : {"ex2_hemispherical_deep_drawing.toml", "ex3_flat_punch_cup.toml"}) {
    const RunResult r = simulate(load_with(name, {{"output.history", "false"}}));
    EXPECT_TRUE(r.completed()) << name << ": " << r.message;
    EXPECT_GT(r.steps.back().rim_draw_in_mm, 5.0) << name;  // the flange draws in
    EXPECT_GT(test::peak_force(r), 1e4) << name;
    // Nothing overlaps a tool: the cup's rim, thicker than the 1.2 mm punch-die clearance at the
    // end of the draw, is ironed to the clearance (the squeeze check would warn otherwise).
    const bool squeezed = std::any_of(
        r.warnings.begin(), r.warnings.end(),
        [](const std::string& w) { return w.find("squeezed between tools") != std::string::npos; });
    EXPECT_FALSE(squeezed) << name;
  }
}

TEST(AxisymForming, CupRimIsIronedToTheClearance) {
  // ex3: flat punch radius 30 mm, die opening 31.2 mm: clearance 1.2 mm for a 1 mm sheet whose
  // rim thickens to ~1.3-1.45 mm in the flange (R = 0.41). At 42 mm the drawn wall between punch
  // and die wall is held at the clearance (penalty: to ~1 %), and the run completes.
  const RunResult r = simulate(load_with("ex3_flat_punch_cup.toml", {{"output.history", "false"}}));
  ASSERT_TRUE(r.completed()) << r.message;
  const Profile& p = r.profiles.back();
  ASSERT_NEAR(p.punch_travel_mm, 42.0, 1e-9);
  int in_bore = 0;
  double thickest_in_bore = 0.0, thickest_before = 0.0;
  for (std::size_t e = 0; e < p.r_mm.size(); ++e) {
    if (p.r_mm[e] < 30.9 && p.z_mm[e] > 1.0) {  // the wall beside the punch
      ++in_bore;
      thickest_in_bore = std::max(thickest_in_bore, p.thickness_mm[e]);
    }
  }
  for (const Profile& q : r.profiles) {
    if (q.punch_travel_mm > 30.0 + 1e-9) break;
    for (double h : q.thickness_mm) thickest_before = std::max(thickest_before, h);
  }
  EXPECT_GT(in_bore, 5);
  EXPECT_GT(thickest_before, 1.25);  // without ironing the wall would carry this
  EXPECT_LT(thickest_in_bore, 1.2 * 1.02);
  // Equilibrium with the ironed wall: the force through the free wall circles equals the punch
  // force on the nodes inside them (the rest is the punch-wall friction on the ironed wall).
  const double F = r.steps.back().punch_force_N;
  const double eq = free_wall_equilibrium_error(p, F);
  EXPECT_LT(eq, 1e-3) << "punch force " << F;
}

// Ironing thins a squeezed element as a whole, so on coarse elements it overestimates the force
// (ex3 at 13 elements, 4.1 thicknesses long: a 66.6 kN spike at 37.5 mm, against 38.7-40.0 kN
// with 26-52 elements). The run says so when an ironed element is longer than 3 thicknesses,
// and only then.
TEST(AxisymForming, IroningOnCoarseElementsWarns) {
  auto warns = [](const RunResult& r) {
    for (const std::string& w : r.warnings) {
      if (w.find("ironed on an element") != std::string::npos) return true;
    }
    return false;
  };
  const RunResult coarse = simulate(load_with(
      "ex3_flat_punch_cup.toml", {{"output.history", "false"}, {"blank.elements", "13"}}));
  const RunResult fine = simulate(load_with(
      "ex3_flat_punch_cup.toml", {{"output.history", "false"}, {"blank.elements", "26"}}));
  ASSERT_TRUE(coarse.completed() && fine.completed());
  EXPECT_TRUE(warns(coarse));
  EXPECT_FALSE(warns(fine));
}

// A sheet 1e-4 times the punch radius thick is a membrane: the implicit update's trapezoidal
// geometry (theta = 1/2) damps the free wall's stiff mode only weakly, and at 20 mm of ex1 the
// shape written is off equilibrium: the resultants carry 4.4 % more or less than the punch force
// through the wall (experiments/03_stability, the one GARBAGE verdict of its report), while the
// force itself is right (277.8 N, 277.7 N at a fifth of the step, and 10x the 1e-3 sheet's). The
// run says so; backward Euler (theta = 1) damps the mode and is balanced (measured 8e-4), and so
// is the bundled sheet (measured 2e-5).
TEST(AxisymForming, OffEquilibriumShapeWarns) {
  auto run = [](const std::string& thickness, const std::string& theta) {
    return simulate(load_with("ex1_hemispherical_stretching.toml",
                              {{"output.history", "false"},
                               {"tool.punch.friction", "0.04"},
                               {"blank.thickness_mm", thickness},
                               {"numerics.implicit_theta", theta},
                               {"process.output_travels_mm", "[10.0, 20.0, 30.0]"}}));
  };
  auto warns = [](const RunResult& r) {
    for (const std::string& w : suspect_result_warnings(r)) {
      if (w.find("differs from the punch force") != std::string::npos) return true;
    }
    return false;
  };
  const RunResult thin = run("0.00508", "0.5");
  const RunResult thin_euler = run("0.00508", "1");
  const RunResult bundled = run("0.85", "0.5");
  ASSERT_TRUE(thin.completed() && thin_euler.completed() && bundled.completed());
  EXPECT_TRUE(warns(thin));
  EXPECT_FALSE(warns(thin_euler));
  EXPECT_FALSE(warns(bundled));
  EXPECT_NEAR(test::peak_force(thin) / test::peak_force(thin_euler), 1.0, 2e-3);
}

TEST(AxisymForming, StretchingIsNotSqueezed) {
  const RunResult r = Stretch("0.04", "24");
  ASSERT_TRUE(r.completed()) << r.message;
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

// The axisymmetric twin of the 3D quarter disc (ex4a, friction 0.2) is the 3D solver's accuracy
// reference. At the default shear penalty its 30- and 120-element runs differ by up to 0.0096 in
// thickness strain at 30 mm: the 2-node element's contact reactions alternate node to node near
// the edge of the punch contact, more as the elements shorten (experiments/05_shell3d, "The twin's
// mesh dependence"; experiments/08_continuum_reference section 14). With the penalty at 0.1 the
// two agree within 0.0006 (measured); the bound is 0.0015. The default's figure is printed.
TEST(AxisymForming, TwinIsMeshIndependentWithTheSoftShearPenalty) {
  Scene quarter = load_scene(test::scene_path("ex4a_quarter_disc_sticking.toml"));
  for (auto& t : quarter.tools) t.friction = 0.2;
  auto largest_difference = [&](double scale) {
    Scene coarse = shell3d::axisymmetric_twin(quarter, 30),
          fine = shell3d::axisymmetric_twin(quarter, 120);
    coarse.numerics.transverse_shear_scale = fine.numerics.transverse_shear_scale = scale;
    coarse.output.history = fine.output.history = false;
    const RunResult a = simulate(coarse), b = simulate(fine);
    EXPECT_TRUE(a.completed() && b.completed()) << a.message << b.message;
    const Profile* pa = vsx::profile_at(a, 30.0);
    const Profile* pb = vsx::profile_at(b, 30.0);
    EXPECT_TRUE(pa && pb);
    return pa && pb ? vsx::thickness_strain_max_abs(*pb, *pa) : 1.0;
  };
  const double soft = largest_difference(0.1);
  EXPECT_LT(soft, 0.0015);
  std::printf("30 against 120 elements at 30 mm: %.4f (factor 0.1), %.4f (default)\n", soft,
              largest_difference(1.0));
}

}  // namespace
}  // namespace vs
