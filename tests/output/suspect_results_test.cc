// The checks of a finished run: the load-curve noise (counts and rms second differences against
// hand-made curves) and the free wall's equilibrium (hand-made profiles).
#include "output/suspect_results.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace vs {
namespace {

std::vector<StepRecord> curve(const std::vector<double>& forces) {
  std::vector<StepRecord> steps;
  for (std::size_t k = 0; k < forces.size(); ++k) {
    StepRecord r;
    r.step = static_cast<int>(k);
    r.punch_travel_mm = 0.1 * static_cast<double>(k);
    r.punch_force_N = forces[k];
    steps.push_back(r);
  }
  return steps;
}

TEST(LoadCurveNoise, RiseAndFallIsOneReversal) {
  std::vector<double> f;
  for (int k = 0; k <= 200; ++k) f.push_back(1000.0 * std::sin(3.0 * k / 200.0));
  const LoadCurveNoise n = load_curve_noise(curve(f));
  EXPECT_EQ(n.increments, 200);
  EXPECT_EQ(n.reversals, 1);
  EXPECT_FALSE(n.noise_like);
  EXPECT_TRUE(suspect_result_warnings(RunResult{}).empty());
}

TEST(LoadCurveNoise, ZigzagIsNoise) {
  // F = 1000 + 10 (-1)^k: every increment reverses; second differences are 40 in magnitude.
  std::vector<double> f;
  for (int k = 0; k < 101; ++k) f.push_back(1000.0 + (k % 2 == 0 ? 10.0 : -10.0));
  const LoadCurveNoise n = load_curve_noise(curve(f));
  EXPECT_EQ(n.increments, 100);
  EXPECT_EQ(n.reversals, 99);
  EXPECT_NEAR(n.rms_second_difference, 40.0 / 1010.0, 1e-12);
  EXPECT_TRUE(n.noise_like);
  RunResult r;
  r.steps = curve(f);
  const std::vector<std::string> w = suspect_result_warnings(r);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("reverses 99 times in 100 steps"), std::string::npos) << w[0];
}

TEST(LoadCurveNoise, FewReversalsOrFlatStepsAreNotNoise) {
  // 19 reversals: below the count that makes a curve noise-like.
  std::vector<double> f;
  for (int k = 0; k < 20; ++k) f.push_back(k % 2 == 0 ? 1.0 : 2.0);
  EXPECT_FALSE(load_curve_noise(curve(f)).noise_like);
  // About 48 reversals over 999 rising increments: below a quarter of them.
  std::vector<double> g;
  for (int k = 0; k < 1000; ++k) g.push_back(k + (k % 41 == 0 && k > 0 ? -3.0 : 0.0));
  const LoadCurveNoise few = load_curve_noise(curve(g));
  EXPECT_GE(few.reversals, 20);
  EXPECT_FALSE(few.noise_like);
  // Round-off wiggles on a plateau (below 1e-6 of the peak) are flat, not reversals.
  std::vector<double> plateau;
  for (int k = 0; k < 100; ++k) plateau.push_back(5000.0 + (k % 2) * 1e-6);
  EXPECT_EQ(load_curve_noise(curve(plateau)).reversals, 0);
  EXPECT_EQ(load_curve_noise(curve({1.0, 2.0})).increments, 0);
}

// A meridian of 8 elements: 0-1 on the punch, 2-7 free (the wall to a pinned rim). The punch
// pushes 100 N on nodes 0-2 (node 2 ends the patch: 40 + 40 + 20 N), so every circle of the free
// wall carries 100 N in a balanced state.
Profile wall_profile(const std::vector<double>& vertical_force) {
  Profile p;
  p.punch_travel_mm = 10.0;
  p.contact = {1, 1, 0, 0, 0, 0, 0, 0};
  p.vertical_force_N = vertical_force;
  p.punch_force_node_N = {40.0, 40.0, 20.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  return p;
}

TEST(FreeWallEquilibrium, BalancedWallIsExactAndADeviationIsRelativeToThePunchForce) {
  // Element 2 touches the patch's end node (it carries that node's reaction): skipped.
  const std::vector<double> balanced = {50.0, 90.0, 0.0, 100.0, 100.0, 100.0, 100.0, 100.0};
  EXPECT_EQ(free_wall_equilibrium_error(wall_profile(balanced), 100.0), 0.0);
  std::vector<double> off = balanced;
  off[5] = 103.0;  // 3 N of 100 N
  off[2] = 500.0;  // skipped
  EXPECT_NEAR(free_wall_equilibrium_error(wall_profile(off), 100.0), 0.03, 1e-12);
  // Without per-node punch forces the whole punch force is the reference.
  Profile whole = wall_profile(off);
  whole.punch_force_node_N.clear();
  EXPECT_NEAR(free_wall_equilibrium_error(whole, 100.0), 0.03, 1e-12);
  // No resultants (a 3D line), no punch force, no free stretch of 3 elements: not measured.
  Profile none = wall_profile(balanced);
  none.vertical_force_N.clear();
  EXPECT_TRUE(std::isnan(free_wall_equilibrium_error(none, 100.0)));
  EXPECT_TRUE(std::isnan(free_wall_equilibrium_error(wall_profile(balanced), 0.0)));
  Profile short_free = wall_profile(balanced);
  short_free.contact = {1, 1, 1, 1, 1, 1, 0, 0};
  EXPECT_TRUE(std::isnan(free_wall_equilibrium_error(short_free, 100.0)));
}

TEST(FreeWallEquilibrium, WarnsAboveTwoPercentAtTheWorstOutputTravel) {
  RunResult r;
  r.steps = curve({0.0, 50.0, 100.0});  // travels 0, 0.1, 0.2 mm
  std::vector<double> off = {50.0, 90.0, 0.0, 100.0, 100.0, 101.9, 100.0, 100.0};
  Profile p = wall_profile(off);
  p.punch_travel_mm = 0.2;
  r.profiles.push_back(p);
  EXPECT_TRUE(suspect_result_warnings(r).empty());  // 1.9 %
  r.profiles.back().vertical_force_N[6] = 104.4;
  const std::vector<std::string> w = suspect_result_warnings(r);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("at punch travel 0.2 mm"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("by 4.4 %"), std::string::npos) << w[0];
  // A profile at a travel without a step is not checked.
  r.profiles.back().punch_travel_mm = 0.15;
  EXPECT_TRUE(suspect_result_warnings(r).empty());
}

}  // namespace
}  // namespace vs
