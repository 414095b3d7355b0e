// The real forward model: vs::simulate. Kept in its own file so that code and tests that inject
// a fake model do not need the solver to link.
#pragma once

#include "forward_model.h"

namespace vs {

// vs::simulate with no per-step callback and no iteration table. The tight calibration
// tolerance is not set here but in the scene copy (SceneBinding writes numerics.tolerance),
// so that the fake models see exactly the scene the solver would see.
ForwardModel make_default_forward_model();

}  // namespace vs
