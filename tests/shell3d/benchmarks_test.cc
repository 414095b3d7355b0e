// Linear elastic benchmarks (numerics.md 1.3-1.4) of the 9-node shell at fixed viscosity.
// Paper rule: regression values (they reproduce the independent own-calc table of numerics.md
// 1.4 to its three digits, locking included). MITC9: against the reference solutions.
#include <gtest/gtest.h>

#include "benchmark_setups.h"

namespace vs::shell3d {
namespace {

using bench::clamped_plate;
using bench::pinched_cylinder;
using bench::pinched_hemisphere;
using bench::scordelis_lo;
using bench::twisted_beam;

constexpr auto kPaper = Shell9Rule::kSelective;
constexpr auto kMitc9 = Shell9Rule::kMitc9;
constexpr double kRegression = 5e-4;  // on the ratio computed / reference

TEST(PaperRuleRegression, ScordelisLo) {  // numerics.md: 0.825, 0.985
  EXPECT_NEAR(scordelis_lo(kPaper, 4), 0.82460, kRegression);
  EXPECT_NEAR(scordelis_lo(kPaper, 8), 0.98510, kRegression);
}

TEST(PaperRuleRegression, PinchedHemisphereLocks) {  // numerics.md: 0.056, 0.282, 0.847
  EXPECT_NEAR(pinched_hemisphere(kPaper, 4), 0.05629, kRegression);
  EXPECT_NEAR(pinched_hemisphere(kPaper, 8), 0.28235, kRegression);
  EXPECT_NEAR(pinched_hemisphere(kPaper, 16), 0.84726, kRegression);
}

TEST(PaperRuleRegression, PinchedCylinder) {  // numerics.md: 0.854, 0.995
  EXPECT_NEAR(pinched_cylinder(kPaper, 8), 0.85454, kRegression);
  EXPECT_NEAR(pinched_cylinder(kPaper, 16), 0.99543, kRegression);
}

TEST(PaperRuleRegression, TwistedBeam) {  // numerics.md: 0.997 / 0.998 (2x12)
  EXPECT_NEAR(twisted_beam(kPaper, 2, true), 0.99723, kRegression);
  EXPECT_NEAR(twisted_beam(kPaper, 2, false), 0.99733, kRegression);
}

TEST(PaperRuleRegression, ThinTwistedBeamLocks) {  // numerics.md: 0.600 / 0.599 (4x24)
  EXPECT_NEAR(twisted_beam(kPaper, 4, true, true), 0.59992, kRegression);
  EXPECT_NEAR(twisted_beam(kPaper, 4, false, true), 0.59857, kRegression);
}

TEST(PaperRuleRegression, ClampedPlate) {
  // Quarter model n x n = full plate 2n x 2n; numerics.md: 1.0033 (8x8 full), 1.0028 (16x16).
  EXPECT_NEAR(clamped_plate(kPaper, 4), 1.00331, kRegression);
  EXPECT_NEAR(clamped_plate(kPaper, 8), 1.00284, kRegression);
}

TEST(Mitc9Benchmarks, ScordelisLo) {
  EXPECT_NEAR(scordelis_lo(kMitc9, 4), 1.0, 0.01);  // 0.9926
  EXPECT_NEAR(scordelis_lo(kMitc9, 8), 1.0, 0.01);  // 0.9952
}

TEST(Mitc9Benchmarks, PinchedHemisphere) {
  EXPECT_NEAR(pinched_hemisphere(kMitc9, 4), 1.0, 0.02);   // 0.9847
  EXPECT_NEAR(pinched_hemisphere(kMitc9, 8), 1.0, 0.015);  // 0.9901
  EXPECT_NEAR(pinched_hemisphere(kMitc9, 16), 1.0, 0.01);  // 0.9945
}

TEST(Mitc9Benchmarks, PinchedCylinderWithinThreePercent) {
  // Reissner-Mindlin point-load solutions rise above the thin-shell reference with refinement.
  EXPECT_NEAR(pinched_cylinder(kMitc9, 8), 1.0, 0.03);   // 0.9998
  EXPECT_NEAR(pinched_cylinder(kMitc9, 16), 1.0, 0.03);  // 1.0096
}

TEST(Mitc9Benchmarks, TwistedBeams) {
  EXPECT_NEAR(twisted_beam(kMitc9, 2, true), 1.0, 0.005);         // 0.9979
  EXPECT_NEAR(twisted_beam(kMitc9, 2, false), 1.0, 0.005);        // 0.9977
  EXPECT_NEAR(twisted_beam(kMitc9, 2, true, true), 1.0, 0.005);   // 0.9981
  EXPECT_NEAR(twisted_beam(kMitc9, 2, false, true), 1.0, 0.005);  // 0.9990
}

TEST(Mitc9Benchmarks, ClampedPlate) {
  // Kirchhoff reference; the +0.28 % is transverse shear deformation at L/h = 100.
  EXPECT_NEAR(clamped_plate(kMitc9, 8), 1.0028, 5e-4);
  // Thin limit, L/h = 1000: no shear locking (numerics.md: 1.00006 at 16x16 full).
  EXPECT_NEAR(clamped_plate(kMitc9, 8, 0.001), 1.0, 5e-4);
  EXPECT_NEAR(clamped_plate(kPaper, 8, 0.001), 1.0, 5e-4);
}

}  // namespace
}  // namespace vs::shell3d
