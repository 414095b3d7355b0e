// Checks of a finished run whose results may be numerically meaningless although the run
// completed: a load-travel curve that is noise (e.g. a sheet 1e-4 times the punch radius thick:
// hundreds of slope reversals). The warnings go to run.json and stderr with the run's own.
#pragma once

#include <string>
#include <vector>

#include "run/run_result.h"

namespace vs {

// Roughness of the punch force over the steps. A force increment smaller than 1e-6 of the
// largest |force| counts as flat (no sign); a reversal is a change of sign between two
// consecutive non-flat increments.
struct LoadCurveNoise {
  int increments = 0;  // non-flat force increments
  int reversals = 0;   // slope reversals among them
  // Root mean square of the second differences F[k+1] - 2 F[k] + F[k-1] over the steps, divided
  // by the largest |force| (0 for fewer than 3 steps or no force).
  double rms_second_difference = 0.0;
  // Noise-like: at least kMinReversals reversals and at least kReversalFraction of the
  // increments reversing. A forming curve rises, peaks and falls; contact events and ironing add
  // a few wiggles. Measured (default numerics): ex1 16 reversals in 1046 increments, ex2 16 in
  // 1228, the ex3 cup 112 in 1584 (7 %, ironing) and 90 in 1604 with the fixed-gap holder,
  // ex4a (3D, sticking, 30 mm) 24 in 501; ex1 with thickness 1e-4 x the punch radius 678 in 1104
  // (61 %).
  bool noise_like = false;
  static constexpr int kMinReversals = 20;
  static constexpr double kReversalFraction = 0.25;
};

LoadCurveNoise load_curve_noise(const std::vector<StepRecord>& steps);

// One line per suspect feature of `result` (empty when none).
std::vector<std::string> suspect_result_warnings(const RunResult& result);

}  // namespace vs
