// The Newton solver's stopping test (newton_converged) on hand-made iteration norms: the usual
// update-and-residual test, and the two round-off stagnation tests.
#include <gtest/gtest.h>

#include <string>

#include "solver/newton.h"

namespace vs {
namespace {

NewtonSummary norms(double update, double residual, double residual_abs = 1.0) {
  NewtonSummary s;
  s.update_norm = update;
  s.residual_norm = residual;
  s.residual_abs = residual_abs;
  return s;
}

TEST(NewtonStopping, UpdateAndResidualWithinTheToleranceAfterTheFirstIteration) {
  NewtonOptions o;
  o.tolerance = 1e-6;
  EXPECT_TRUE(newton_converged(o, norms(5e-7, 5e-7), 2));
  EXPECT_FALSE(newton_converged(o, norms(5e-7, 5e-7), 1));
  EXPECT_FALSE(newton_converged(o, norms(2e-6, 5e-7), 2));
  EXPECT_FALSE(newton_converged(o, norms(5e-7, 2e-6), 2));
}

TEST(NewtonStopping, RelativeStagnationAcceptsAResidualUpToAHundredTolerances) {
  NewtonOptions o;
  o.tolerance = 1e-6;
  EXPECT_TRUE(newton_converged(o, norms(1e-10, 5e-5), 2));
  EXPECT_FALSE(newton_converged(o, norms(1e-10, 2e-4), 2));
  EXPECT_FALSE(newton_converged(o, norms(1e-8, 5e-5), 2));  // the update has not vanished
}

// A drawn cup riding on the punch: internal forces at round-off, so |r| / |f| stays near 0.5
// while |r| is 1.3e-5 N against the sheet's 6 kN (measured: ESAFORM cup, force holder, Swift
// TUAT, friction 0.05, at 44 mm; without this test the run stopped there after 8 cut-backs).
TEST(NewtonStopping, AbsoluteStagnationAgainstTheSheetsCharacteristicForce) {
  NewtonOptions o;
  o.tolerance = 1e-6;
  o.stagnation_force = 6074.0;  // sigma_y(0) h0 R of that cup [N]
  EXPECT_TRUE(newton_converged(o, norms(5.6e-17, 0.54, 1.3e-5), 2));
  EXPECT_FALSE(newton_converged(o, norms(5.6e-17, 0.54, 1e-2), 2));  // above 6.1e-3 N
  EXPECT_FALSE(newton_converged(o, norms(1e-8, 0.54, 1.3e-5), 2));   // still moving
  EXPECT_FALSE(newton_converged(o, norms(5.6e-17, 0.54, 1.3e-5), 1));
  o.stagnation_force = 0.0;  // not set: no absolute test
  EXPECT_FALSE(newton_converged(o, norms(5.6e-17, 0.54, 1.3e-5), 2));
  std::string why;
  o.stagnation_force = -1.0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("stagnation_force"), std::string::npos) << why;
}

}  // namespace
}  // namespace vs
