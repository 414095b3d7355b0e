#include "default_forward_model.h"

#include "run/simulate.h"

namespace vs {

ForwardModel make_default_forward_model() {
  return [](const Scene& scene) { return simulate(scene, RunOptions{}); };
}

}  // namespace vs
