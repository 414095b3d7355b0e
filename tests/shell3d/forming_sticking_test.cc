// Sticking contact of the 3D forming driver against the axisymmetric solver beyond the first few
// millimetres (example 4a vs example 1): the extent of the stuck cap along the symmetry line y = 0
// and the punch force / thickness strain at travels where the driver used to drift away.
//
// The DISABLED_ diagnostic prints both runs side by side (travel, force, stuck-cap radius,
// thickness strain profile); environment variables VS_DIAG_TRAVEL, VS_DIAG_N, VS_DIAG_INC,
// VS_DIAG_PL, VS_DIAG_AXI_PL, VS_DIAG_AXI_N, VS_DIAG_MU (friction instead of sticking),
// VS_DIAG_EVERY, VS_DIAG_STEPS, VS_DIAG_VERBOSE, VS_DIAG_PROFILES, VS_DIAG_AXI_ONLY,
// VS_DIAG_TI / VS_DIAG_AXI_TI (time integration of the 3D run / the twin: 0 heun, 1 euler,
// 2 implicit; default: the scene default) select the run and what is printed:
//   VS_DIAG_TRAVEL=10 build/tests/vs_shell3d_tests --gtest_also_run_disabled_tests
//       --gtest_filter='*DiagnoseSticking*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "common/axisym_comparison.h"
#include "model/forming_fields.h"
#include "model/forming_model.h"
#include "run/simulate.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"

namespace vs::shell3d {
namespace {

double env(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v ? std::atof(v) : fallback;
}

Scene sticking_scene(int n, double travel, const std::vector<double>& outputs) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml");
  s.blank.divisions = n;
  s.process.punch_travel_mm = travel;
  s.process.output_travels_mm = outputs;
  s.tools.at(0).friction = std::numeric_limits<double>::infinity();
  return s;
}

// Largest initial radius of a node on y = 0 touching a tool / of an axisymmetric element in
// contact.
double stuck_radius_3d(const RunResult& r, const ShellStage& st, double h0) {
  const LineProfile p = line_profile(r.shell->mesh, st, "y0", h0);
  double rc = 0.0;
  for (std::size_t i = 0; i < p.nodes.size(); ++i)
    if (p.contact_tool[i] >= 0) rc = std::max(rc, p.r0_mm[i]);
  return rc;
}

double stuck_radius_axi(const Profile& p) {
  double rc = 0.0;
  for (std::size_t i = 0; i < p.r0_mm.size(); ++i)
    if (p.contact[i]) rc = std::max(rc, p.r0_mm[i]);
  return rc;
}

double mean_force_at(const std::vector<StepRecord>& steps, double travel) {
  return mean_force(steps, travel - 1.0, travel);
}

// The reference of every 3D comparison is the axisymmetric twin, and it must be converged in the
// travel step. It used to inherit the 3D scene's 0.5 mm grid (0.25 of its 2 mm elements, ten times
// the stability cap of forward/run/travel_grid): its sticking force was then 1.3 % low at 10 mm and
// 6 % low at 20 mm, which was most of the "3D sheet too stiff" divergence of
// experiments/05_shell3d. The twin now keeps the axisymmetric per-length cap whatever the 3D
// scene asks for; halving it moves the mean force at 20 mm by 0.2 % (measured).
TEST(Forming3dSticking, AxisymmetricTwinIsConvergedInTheTravelStep) {
  Scene s = sticking_scene(4, 20.0, {20.0});
  s.numerics.max_travel_increment_per_length = 1e9;  // a 3D scene on its coarse 0.5 mm grid
  const Scene twin = axisymmetric_twin(s, 30);
  EXPECT_LE(twin.numerics.max_travel_increment_per_length, kTwinTravelIncrementPerLength);
  Scene half = twin;
  half.numerics.max_travel_increment_per_length *= 0.5;
  Scene coarse = twin;
  coarse.numerics.max_travel_increment_per_length = 1e9;
  const RunResult r = simulate(twin), h = simulate(half), c = simulate(coarse);
  ASSERT_TRUE(r.completed() && h.completed() && c.completed());
  const double fr = mean_force_at(r.steps, 20.0), fh = mean_force_at(h.steps, 20.0),
               fc = mean_force_at(c.steps, 20.0);
  EXPECT_LT(std::abs(fr - fh) / fh, 0.005) << fr << " vs " << fh;
  // The old reference on the 0.5 mm grid was 6 % low at 20 mm; most of that was the edge node of
  // the stuck patch attaching and releasing at every step (fixed in simulate.cc, Driver::attach:
  // it now slides without friction until the patch grows past it). Since then the 0.5 mm grid is
  // within 0.2 % here (measured), but it stays outside the stability cap, so the twin keeps the
  // cap.
  EXPECT_LT(std::abs(fc - fh) / fh, 0.02) << fc << " vs " << fh;
}

// Sticking 3D vs axisymmetric at 8 mm, where the comparison used to be 5.8 % off in mean force
// (against the coarse-step reference above; this test would have failed): now 2.1 % on the 3D
// 0.5 mm grid and 3.3-3.4 % on the 0.29 / 0.14 mm grids (3D per-length caps 0.05 and the default
// 0.025; measured), hence the 4 % bound. The stuck cap along y = 0 trails
// the axisymmetric one by up to one node spacing (3.7 mm): the 9-node element between the last
// stuck midside node and the next free corner cannot bend its velocity at the contact front
// (forward/shell3d/README.md), which is also what the thickness-strain tolerance (0.025; measured
// 0.021) allows for.
TEST(Forming3dSticking, MatchesAxisymmetricSolverAt8mm) {
  Scene s = sticking_scene(4, 8.0, {6.0, 8.0});
  // The 0.5 mm grid keeps the test at ~30 s (experiments/05_shell3d has the finer steps). The
  // figures above are Heun's; the implicit update (the 3D default since 26 Nov 2026) is +6.0 % in
  // mean force at 8 mm on this grid (its step error, as in forming_test.cc's sticking test).
  s.numerics.max_travel_increment_per_length = 1e9;
  s.numerics.time_integration = TimeIntegration::kHeun;
  s.numerics.start_refinement = 0;
  const RunResult shell = simulate_shell3d(s);
  ASSERT_TRUE(shell.completed()) << shell.message;
  const RunResult axi = simulate(axisymmetric_twin(s, 30));
  ASSERT_TRUE(axi.completed()) << axi.message;
  const auto cmp = compare_with_axisymmetric(s, shell, axi);
  ASSERT_EQ(cmp.size(), 2u);
  const double h0 = s.blank.thickness_mm;
  for (std::size_t k = 0; k < cmp.size(); ++k) {
    const TravelComparison& c = cmp[k];
    EXPECT_LT(std::abs(c.mean_force_deviation), 0.04)
        << "travel " << c.punch_travel_mm << ": mean force 3D " << c.mean_force_3d_N
        << " N, axisymmetric " << c.mean_force_axisym_N << " N";
    EXPECT_LT(c.max_eps_thickness_deviation(), 0.025) << "travel " << c.punch_travel_mm;
    const double r3 = stuck_radius_3d(shell, shell.shell->stages[k], h0);
    const double ra = stuck_radius_axi(axi.profiles[k]);
    EXPECT_GT(r3, ra - 3.7 - 0.2) << "travel " << c.punch_travel_mm;
    EXPECT_LT(r3, ra + 3.7 + 0.2) << "travel " << c.punch_travel_mm;
  }
}

// The bundled clamped square (ex4b, 8 divisions, sticking) against the same run with 4x finer
// travel steps and 8x finer strain steps (the study's step-converged setting), at its first output
// (5 mm). With 0.5 mm steps (the scene's cap until 27 Nov 2026) the force there was 1.1 % high
// (and 7 % at 2 mm): nodes that stick one after another in the converged run stuck in the same
// step (experiments/11_continuum_3d, section 5, "At equal accuracy"). Measured with the scene's
// 0.25 mm: +0.20 % in force, thickness strain along y = 0 within 0.0032 (at the pole node); with
// 0.5 mm the force check fails (+1.24 %).
TEST(Forming3dSticking, ClampedSquareSceneIsConvergedInTheStepAtItsFirstOutput) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4b_square_clamped.toml");
  s.process.punch_travel_mm = 5.0;
  s.process.output_travels_mm = {5.0};
  Scene fine = s;
  fine.numerics.max_travel_increment_mm = s.numerics.max_travel_increment_mm / 4.0;
  fine.numerics.max_strain_increment = 0.0025;
  const RunResult r = simulate_shell3d(s), f = simulate_shell3d(fine);
  ASSERT_TRUE(r.completed() && f.completed()) << r.message << " / " << f.message;
  ASSERT_FALSE(r.shell->stages.empty());
  ASSERT_FALSE(f.shell->stages.empty());
  const double fr = r.steps.back().punch_force_N, ff = f.steps.back().punch_force_N;
  EXPECT_NEAR(r.steps.back().punch_travel_mm, 5.0, 1e-9);
  EXPECT_NEAR(f.steps.back().punch_travel_mm, 5.0, 1e-9);
  EXPECT_LT(std::abs(fr - ff) / ff, 0.006) << fr << " N against " << ff << " N with finer steps";
  const double h0 = s.blank.thickness_mm;
  const LineProfile pr = line_profile(r.shell->mesh, r.shell->stages.back(), "y0", h0);
  const LineProfile pf = line_profile(f.shell->mesh, f.shell->stages.back(), "y0", h0);
  ASSERT_EQ(pr.eps_thickness.size(), pf.eps_thickness.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < pr.eps_thickness.size(); ++i)
    worst = std::max(worst, std::abs(pr.eps_thickness[i] - pf.eps_thickness[i]));
  EXPECT_LT(worst, 0.005);
}

TEST(Forming3dSticking, DISABLED_DiagnoseSticking) {
  const double travel = env("VS_DIAG_TRAVEL", 10.0);
  const int n = static_cast<int>(env("VS_DIAG_N", 4));
  std::vector<double> outputs;
  const double every = env("VS_DIAG_EVERY", 2.0);
  for (double t = every; t <= travel + 1e-9; t += every) outputs.push_back(t);
  Scene s = sticking_scene(n, travel, outputs);
  s.tools.at(0).friction = env("VS_DIAG_MU", s.tools.at(0).friction);
  s.numerics.max_travel_increment_mm = env("VS_DIAG_INC", s.numerics.max_travel_increment_mm);
  s.numerics.max_travel_increment_per_length =
      env("VS_DIAG_PL", s.numerics.max_travel_increment_per_length);
  auto integration = [](const char* name, TimeIntegration fallback) {
    const double v = env(name, -1.0);
    if (v < 0.0) return fallback;
    return v < 0.5 ? TimeIntegration::kHeun
                   : (v < 1.5 ? TimeIntegration::kEuler : TimeIntegration::kImplicit);
  };
  s.numerics.time_integration = integration("VS_DIAG_TI", s.numerics.time_integration);
  const double h0 = s.blank.thickness_mm;
  Scene a = axisymmetric_twin(s, static_cast<int>(env("VS_DIAG_AXI_N", 30)));
  a.numerics.max_travel_increment_per_length = env("VS_DIAG_AXI_PL", kTwinTravelIncrementPerLength);
  a.numerics.time_integration = integration("VS_DIAG_AXI_TI", a.numerics.time_integration);
  const RunResult axi = simulate(a);
  std::printf("axisym: %s, %zu steps\n", axi.message.c_str(), axi.steps.size());
  if (env("VS_DIAG_AXI_ONLY", 0) != 0) {
    for (const Profile& p : axi.profiles) {
      double f = 0.0;
      for (const StepRecord& r : axi.steps)
        if (std::abs(r.punch_travel_mm - p.punch_travel_mm) < 1e-9) f = r.punch_force_N;
      std::printf("axi T=%.1f stuck r0=%.2f min eps_t=%.3f F=%.0f Fmean=%.0f\n", p.punch_travel_mm,
                  stuck_radius_axi(p),
                  *std::min_element(p.eps_thickness.begin(), p.eps_thickness.end()), f,
                  mean_force(axi.steps, p.punch_travel_mm - 1.0, p.punch_travel_mm));
    }
    return;
  }
  {
    FormingModel m(s);
    std::printf("element size %.3f mm, grid %.4f mm\n", shortest_element_size(m),
                std::min(s.numerics.max_travel_increment_mm,
                         s.numerics.max_travel_increment_per_length * shortest_element_size(m)));
  }
  RunOptions opt;
  opt.verbose = env("VS_DIAG_VERBOSE", 0) != 0;
  if (env("VS_DIAG_STEPS", 0) != 0) {
    opt.on_step = [](const StepRecord& r) {
      std::printf("step %3d T=%8.4f F=%9.1f contact=%d it=%d cut=%d\n", r.step, r.punch_travel_mm,
                  r.punch_force_N, r.contact_nodes, r.iterations, r.cutbacks);
    };
  }
  const RunResult shell = simulate_shell3d(s, opt);
  std::printf("3D: %s, %zu steps, %d iterations, %.1f s\n", shell.message.c_str(),
              shell.steps.size(), shell.total_iterations, shell.timings.total_s);
  const auto cmp = compare_with_axisymmetric(s, shell, axi);
  for (const TravelComparison& c : cmp) {
    const ShellStage* st = nullptr;
    for (const ShellStage& x : shell.shell->stages)
      if (std::abs(x.punch_travel_mm - c.punch_travel_mm) < 1e-9) st = &x;
    const Profile* pa = nullptr;
    for (const Profile& p : axi.profiles)
      if (std::abs(p.punch_travel_mm - c.punch_travel_mm) < 1e-9) pa = &p;
    std::printf(
        "T=%5.1f F3d=%8.0f Faxi=%8.0f dF=%+6.2f%% dFmean=%+6.2f%% deps=%.4f  stuck r0: 3D %.2f "
        "axi %.2f\n",
        c.punch_travel_mm, c.force_3d_N, c.force_axisym_N, 100 * c.force_deviation,
        100 * c.mean_force_deviation, c.max_eps_thickness_deviation(),
        stuck_radius_3d(shell, *st, h0), stuck_radius_axi(*pa));
    if (env("VS_DIAG_PROFILES", 1) != 0) {
      const LineProfile p = line_profile(shell.shell->mesh, *st, "y0", h0);
      FormingModel m(s);
      FormingState fs = m.initial_state();
      fs.tool_offset[m.punch_index()] = Eigen::Vector2d(0.0, c.punch_travel_mm);
      m.place_tools(fs);
      for (std::size_t i = 0; i < p.nodes.size(); ++i) {
        const double gap = m.project(m.punch_index(), st->x[p.nodes[i]],
                                     st->thickness_mm[p.nodes[i]], p.r0_mm[i] == 0.0)
                               .gap;
        std::printf("   r0 %6.2f  eps_t 3D %+.4f axi %+.4f  contact %d gap %.4f\n", p.r0_mm[i],
                    p.eps_thickness[i], interpolate(pa->r0_mm, pa->eps_thickness, p.r0_mm[i]),
                    p.contact_tool[i], gap);
      }
    }
  }
}

}  // namespace
}  // namespace vs::shell3d
