// simulate(): the model the scene's geometry names, behind one entry point and one result type.
#include "run/simulate.h"

#include "stepping/shell3d_driver.h"

namespace vs {

RunResult simulate(const Scene& scene, const RunOptions& options) {
  switch (scene.geometry) {
    case Geometry::kShell3d:
      return shell3d::simulate_shell3d(scene, options);
    case Geometry::kAxisymmetric:
      break;
  }
  return simulate_axisymmetric(scene, options);
}

}  // namespace vs
