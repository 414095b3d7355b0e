// Ironing in the 3D forming model (FormingModel::update_squeezed, the ironing form of
// model/gap_holder3.h): a cup whose flange thickens beyond the punch-die clearance is drawn into
// it; the wall in the clearance is held at the clearance, and the punch force follows the
// axisymmetric solver, which irons the same way (AxisymModel::add_squeeze).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/axisym_comparison.h"
#include "run/simulate.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"

namespace vs::shell3d {
namespace {

// The ESAFORM cup in 3D (quarter, fixed-gap holder 1.2 mm) made small and tight: blank radius
// 42 mm (the flange thickens by up to ~18 % as it is drawn in), die opening 31.05 mm over the
// 30 mm punch (clearance 1.05 mm), die shoulder 4 mm (the straight clearance starts 4 mm below
// the die face), 4 divisions, 17 mm of travel.
constexpr double kClearanceMm = 1.05;
constexpr double kTravelMm = 17.0;  // it diverges at 17.9 mm (model/ironing.h)

Scene tight_cup() {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/esaform_cup_3d_quarter.toml");
  s.blank.divisions = 4;
  s.blank.radius_mm = 42.0;
  for (ToolSpec& t : s.tools) {
    if (t.kind != ToolKind::kDie) continue;
    t.radius_mm = 30.0 + kClearanceMm;
    t.profile_radius_mm = 4.0;
  }
  s.process.punch_travel_mm = kTravelMm;
  s.process.output_travels_mm = {10.0, kTravelMm};
  return s;
}

const RunResult& tight_run() {
  static const RunResult r = simulate_shell3d(tight_cup());
  return r;
}

TEST(Forming3dIroning, WallInTheClearanceIsHeldAtTheClearance) {
  const RunResult& r = tight_run();
  ASSERT_TRUE(r.completed()) << r.message;
  const ShellStage& end = r.shell->stages.back();
  ASSERT_NEAR(end.punch_travel_mm, kTravelMm, 1e-9);
  // The die face is z = 0 and the punch comes from below: the straight clearance is z > 4 mm
  // (+ 0.5 mm off the shoulder's end), between the punch side (r = 30) and the die wall.
  int in_clearance = 0;
  double thickest_in = 0.0, thickest_flange = 0.0;
  for (std::size_t i = 0; i < end.x.size(); ++i) {
    const double rr = std::hypot(end.x[i].x(), end.x[i].y());
    if (rr > 30.0 && rr < 30.0 + kClearanceMm && end.x[i].z() > 4.5 &&
        end.x[i].z() < kTravelMm - 6.0) {
      ++in_clearance;
      thickest_in = std::max(thickest_in, end.thickness_mm[i]);
    }
  }
  for (const ShellStage& st : r.shell->stages) {
    for (double h : st.thickness_mm) thickest_flange = std::max(thickest_flange, h);
  }
  std::printf(
      "wall nodes in the clearance: %d, thickest %.4f mm (clearance %.2f mm); thickest "
      "anywhere at any stage %.4f mm\n",
      in_clearance, thickest_in, kClearanceMm, thickest_flange);
  EXPECT_GE(in_clearance, 8);
  // The sheet had to be ironed: it comes in thicker than the clearance.
  EXPECT_GT(thickest_flange, 1.05 * kClearanceMm);
  // Held at the clearance within the axisymmetric test's 2 % (the penalty, and an overshoot
  // ironed over a few steps).
  EXPECT_LT(thickest_in, 1.02 * kClearanceMm);
  // No node passes through a tool without the ironing constraint (contact/overlap_monitor.h).
  for (const std::string& w : r.warnings) {
    std::printf("warning: %s\n", w.c_str());
    EXPECT_EQ(w.find("not trustworthy"), std::string::npos) << w;
  }
}

// Against the axisymmetric twin (50 elements; it irons whole elements, AxisymModel::add_squeeze):
// the mean punch force while the cup is drawn (8-11 mm, before the first node is squeezed at
// 11.4 mm) and while its wall is ironed (13-17 mm). Measured: drawing +9.2 %, the mesh error of
// this 4-division 3D cup (the fixed-gap holder test measured +5.6 % on the larger blank);
// ironing -12.5 %: the axisymmetric force jumps by +-30 % from step to step there (it irons one
// whole element at a time) and the coarse 3D cup ends its draw earlier. An ironing force that
// missed the friction of the face the squeezing tool presses (a first version) was -84 %.
TEST(Forming3dIroning, PunchForceFollowsTheAxisymmetricSolver) {
  const RunResult& shell = tight_run();
  ASSERT_TRUE(shell.completed()) << shell.message;
  const RunResult axi = simulate(axisymmetric_twin(tight_cup(), 50));
  ASSERT_TRUE(axi.completed()) << axi.message;
  const double d3 = mean_force(shell.steps, 8.0, 11.0), da = mean_force(axi.steps, 8.0, 11.0);
  const double i3 = mean_force(shell.steps, kTravelMm - 4.0, kTravelMm);
  const double ia = mean_force(axi.steps, kTravelMm - 4.0, kTravelMm);
  std::printf(
      "mean punch force, drawing 8-11 mm: 3D %.1f N, axisym %.1f N (%+.2f %%); ironing "
      "%.0f-%.0f mm: 3D %.1f N, axisym %.1f N (%+.2f %%)\n",
      d3, da, 100.0 * (d3 / da - 1.0), kTravelMm - 4.0, kTravelMm, i3, ia, 100.0 * (i3 / ia - 1.0));
  EXPECT_NEAR(d3 / da, 1.0, 0.12);
  EXPECT_NEAR(i3 / ia, 1.0, 0.2);
}

}  // namespace
}  // namespace vs::shell3d
