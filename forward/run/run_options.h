// Options of a forward run (both geometries): callbacks and diagnostics that do not change the
// answer. The numerics that do are scene keys (numerics.*).
#pragma once

#include <functional>

#include "run/run_result.h"

namespace vs {

struct RunOptions {
  // Called after every converged step (progress line, streaming writers). May be empty.
  std::function<void(const StepRecord&)> on_step;
  // Print the nonlinear iteration table to stderr.
  bool verbose = false;
  // Axisymmetric runs: Coulomb friction from the current normal reactions, with their derivative
  // in Newton's matrix (true), or from the reactions lagged by one iteration and relaxed (false;
  // the formulation before Nov 2026, kept for comparison). Both converge to the same solution;
  // the first needs 2-3x fewer iterations with friction and falls back to the second for a solve
  // it cannot converge (RunResult::friction_fallbacks). The 3D solver always lags them.
  bool consistent_friction = true;
};

}  // namespace vs
