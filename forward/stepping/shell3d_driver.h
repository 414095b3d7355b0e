// Entry point of the 3D forming solver (geometry = "shell3d"): the step driver of paper section
// 3 (steps 1-7) with the 3D contact-event step (eqs. 81-85, corrected), mirroring the
// axisymmetric vs::simulate (forward/run/simulate.cc): steps end on a fixed travel grid and at
// the output travels, contact events split grid intervals, the strain increment is capped, the
// geometry update is Heun (or Euler) and a failed step is cut back and retried.
#pragma once

#include "run/run_options.h"
#include "run/run_result.h"
#include "scene/scene.h"

namespace vs::shell3d {

// Runs the scene to its punch travel or until it cannot continue; never throws for a solver
// failure (Termination::kFailed, message, everything so far). Throws InputError for a scene it
// does not build (not shell3d, fixed-gap holder, ...). The result holds the nodal fields of the
// output stages (RunResult::shell) and their line profiles (RunResult::profiles, shell_profiles
// of forming_fields.h). vs::simulate() calls it for shell3d scenes.
RunResult simulate_shell3d(const Scene& scene, const RunOptions& options = {});

class FormingModel;
// The element length of the per-length travel cap (numerics.max_travel_increment_per_length):
// the smallest sqrt(A_e) over the initial 9-node elements [mm]. A 9-node element spans two node
// intervals, so this is twice its node spacing; robust to the curved, skewed elements of the
// O-grid blank, where a single edge would not be. With it the default 0.025 of the axisymmetric
// 2-node element (whose length is its node spacing) also removes the 3D step jitter.
double shortest_element_size(const FormingModel& model);

}  // namespace vs::shell3d
