// The forward model as the calibration toolkit sees it: a pure function Scene -> RunResult.
// Injected into calibrate() so that the toolkit can be tested with closed-form fakes and so
// that nothing here links against the solver unless the caller asks for it
// (default_forward_model.h is the only file that does).
#pragma once

#include <functional>

#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

// Must be safe to call from several threads at once (finite-difference runs are parallel).
// A solver failure is reported as Termination::kFailed; an exception is also caught and
// counted as a failed run, never propagated into the optimiser.
using ForwardModel = std::function<RunResult(const Scene&)>;

}  // namespace vs
