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
};

// Runs the scene to its total punch travel or until it cannot continue. Never throws for a
// solver failure: returns Termination::kFailed with a message and all steps done so far.
// Throws InputError if the scene asks for something this solver does not build.
RunResult simulate(const Scene& scene, const RunOptions& options = {});

}  // namespace vs
