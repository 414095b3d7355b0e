// The forward solver's entry point for both geometries, used in-process by the CLI and by the
// calibration toolkit (its forward model is simulate itself).
#pragma once

#include "run/run_options.h"
#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

// Runs the scene to its total punch travel or until it cannot continue, with the model its
// geometry names (axisymmetric 2-node shell or 3D 9-node shell). Never throws for a solver
// failure: returns Termination::kFailed with a message and all steps done so far. Throws
// InputError if the scene asks for something the solver does not build.
RunResult simulate(const Scene& scene, const RunOptions& options = {});

// The axisymmetric step driver (run/axisym_driver.cc), which simulate() calls for axisymmetric
// scenes; throws InputError for any other geometry.
RunResult simulate_axisymmetric(const Scene& scene, const RunOptions& options = {});

}  // namespace vs
