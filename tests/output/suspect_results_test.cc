// The load-curve noise check: counts and rms second differences against hand-made curves.
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

}  // namespace
}  // namespace vs
