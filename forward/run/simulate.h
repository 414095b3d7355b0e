// The forward solver's entry point, used in-process by the CLI and by the calibration toolkit.
#pragma once

#include <functional>

#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

struct RunOptions {
  // Called after every converged step (progress line, streaming writers). May be empty.
  std::function<void(const StepRecord&)> on_step;
  // Print the nonlinear iteration table to stderr.
  bool verbose = false;
  // Coulomb friction from the current normal reactions, with their derivative in Newton's matrix
  // (true), or from the reactions lagged by one iteration and relaxed (false; the formulation
  // before Nov 2026, kept for comparison). Both converge to the same solution; the first needs
  // 2-3x fewer iterations with friction and falls back to the second for a solve it cannot
  // converge (RunResult::friction_fallbacks).
  bool consistent_friction = true;
};

// Runs the scene to its total punch travel or until it cannot continue. Never throws for a
// solver failure: returns Termination::kFailed with a message and all steps done so far.
// Throws InputError if the scene asks for something this solver does not build.
RunResult simulate(const Scene& scene, const RunOptions& options = {});

}  // namespace vs
