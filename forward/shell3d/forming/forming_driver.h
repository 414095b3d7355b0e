// Entry point of the 3D forming solver (geometry = "shell3d"): the step driver of paper section
// 3 (steps 1-7) with the 3D contact-event step (eqs. 81-85, corrected), mirroring the
// axisymmetric vs::simulate (forward/run/simulate.cc): steps end on a fixed travel grid and at
// the output travels, contact events split grid intervals, the strain increment is capped, the
// geometry update is Heun (or Euler) and a failed step is cut back and retried.
#pragma once

#include <functional>

#include "scene/scene.h"
#include "shell3d/forming/forming_result.h"

namespace vs::shell3d {

struct Shell3dRunOptions {
  std::function<void(const StepRecord&)> on_step;  // after every converged step; may be empty
  bool verbose = false;                            // nonlinear iteration tables on stderr
};

// Runs the scene to its punch travel or until it cannot continue; never throws for a solver
// failure (Termination::kFailed, message, everything so far). Throws InputError for a scene it
// does not build (not shell3d, blank holder, ...).
Shell3dResult simulate_shell3d(const Scene& scene, const Shell3dRunOptions& options = {});

}  // namespace vs::shell3d
