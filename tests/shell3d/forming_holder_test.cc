// The force-controlled blank holder in the 3D forming driver: the quarter circular blank of
// example 2 (hemispherical punch deep drawing, free edge drawn in over the die shoulder, holder
// force spread over the flange on the die face) against the axisymmetric solver on the same data,
// and the response to doubling the holder force. A coarse mesh and 12 mm of travel (past the
// bending-dominated start; the rim has drawn in by ~0.4 mm) keep it at 16-25 s per 3D run;
// data/scenes/ex2_quarter_disc_deep_drawing_3d.toml is the longer run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "common/axisym_comparison.h"
#include "run/simulate.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"

namespace vs::shell3d {
namespace {

constexpr double kTravelMm = 12.0;
constexpr int kTwinElements = 40;  // 2 mm meridian elements on the 80 mm blank

// Tolerances, from the measured deviations (n = 4, 12 mm, 3D vs the 40-element axisymmetric
// twin, both at the default travel step cap): mean punch force over the last millimetre -0.76 %
// (holder 20 kN) and -0.67 % (40 kN), so 3 %; rim draw-in along y = 0 -1.8 % and -1.6 %, within
// the 10 % asked for (the draw-in, 0.38-0.40 mm, is a tenth of the 3D node spacing). On a 0.5 mm
// travel grid the 40 kN draw-in was 6.5 % off (n = 4 and n = 8 alike): the step, not the mesh.
constexpr double kForceTolerance = 0.03;
constexpr double kDrawInTolerance = 0.10;

// Example 2's data as a shell3d scene: quarter circular blank, 4 divisions (48 elements), the
// example's numerics (5 Simpson points, default travel step cap: ~70 steps to 12 mm).
Scene deep_drawing_3d(double holder_force_factor) {
  Scene s =
      load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex2_hemispherical_deep_drawing.toml");
  s.geometry = Geometry::kShell3d;
  s.blank.shape = BlankShape::kCircle;
  s.blank.symmetry = BlankSymmetry::kQuarter;
  s.blank.divisions = 4;
  s.process.punch_travel_mm = kTravelMm;
  s.process.output_travels_mm = {kTravelMm};
  for (ToolSpec& t : s.tools)
    if (t.kind == ToolKind::kBlankHolder) t.force_N *= holder_force_factor;
  return s;
}

// Initial minus current radius of the edge node on the symmetry line y = 0.
double draw_in_along_y0(const RunResult& r) {
  for (int node : r.shell->mesh.set("edge")) {
    const Eigen::Vector3d& p0 = r.shell->mesh.nodes[node];
    if (std::abs(p0.y()) > 1e-9 * p0.norm()) continue;
    const Eigen::Vector3d& x = r.shell->stages.back().x[node];
    return p0.norm() - std::hypot(x.x(), x.y());
  }
  ADD_FAILURE() << "no edge node on y = 0";
  return 0.0;
}

struct Outcome {
  double force_3d = 0.0, force_axi = 0.0;  // mean punch force over the last millimetre [N]
  double draw_3d = 0.0, draw_axi = 0.0;    // rim draw-in [mm]
  bool completed = false;
};

Outcome run_both(double holder_force_factor) {
  const Scene s = deep_drawing_3d(holder_force_factor);
  const RunResult shell = simulate_shell3d(s);
  const RunResult axi = simulate(axisymmetric_twin(s, kTwinElements));
  Outcome o;
  o.completed = shell.completed() && axi.completed();
  EXPECT_TRUE(shell.completed()) << shell.message;
  EXPECT_TRUE(axi.completed()) << axi.message;
  if (!o.completed) return o;
  o.force_3d = mean_force(shell.steps, kTravelMm - 1.0, kTravelMm);
  o.force_axi = mean_force(axi.steps, kTravelMm - 1.0, kTravelMm);
  o.draw_3d = draw_in_along_y0(shell);
  o.draw_axi = axi.steps.back().rim_draw_in_mm;
  std::printf(
      "holder x%.0f: mean force 3D %.1f N, axisym %.1f N (%+.2f %%); draw-in 3D %.4f mm, "
      "axisym %.4f mm (%+.2f %%); 3D %.1f s, %zu steps\n",
      holder_force_factor, o.force_3d, o.force_axi, 100.0 * (o.force_3d / o.force_axi - 1.0),
      o.draw_3d, o.draw_axi, 100.0 * (o.draw_3d / o.draw_axi - 1.0), shell.timings.total_s,
      shell.steps.size());
  return o;
}

// The example's holder force, run once for both tests.
const Outcome& nominal_holder() {
  static const Outcome o = run_both(1.0);
  return o;
}

void expect_close_to_axisymmetric(const Outcome& o) {
  ASSERT_TRUE(o.completed);
  EXPECT_GT(o.draw_axi, 0.0);  // the flange does draw in
  EXPECT_LT(std::abs(o.force_3d / o.force_axi - 1.0), kForceTolerance)
      << "3D " << o.force_3d << " N, axisymmetric " << o.force_axi << " N";
  EXPECT_LT(std::abs(o.draw_3d / o.draw_axi - 1.0), kDrawInTolerance)
      << "3D " << o.draw_3d << " mm, axisymmetric " << o.draw_axi << " mm";
}

TEST(Forming3dHolder, DeepDrawingMatchesAxisymmetricSolver) {
  expect_close_to_axisymmetric(nominal_holder());
}

// Doubling the holder force: more friction on the flange, so more punch force and less draw-in,
// in 3D as in the axisymmetric solver (measured at 12 mm: 3D +1.9 % force / -3.4 % draw-in,
// axisymmetric +1.8 % / -3.6 %), and the doubled case matches the reference as well.
TEST(Forming3dHolder, DoublingTheHolderForce) {
  const Outcome& one = nominal_holder();
  const Outcome two = run_both(2.0);
  ASSERT_TRUE(one.completed);
  expect_close_to_axisymmetric(two);
  EXPECT_GT(two.force_axi, one.force_axi);
  EXPECT_LT(two.draw_axi, one.draw_axi);
  EXPECT_GT(two.force_3d, one.force_3d);
  EXPECT_LT(two.draw_3d, one.draw_3d);
}

}  // namespace
}  // namespace vs::shell3d
