// simulate(): the model the scene's geometry names, behind one entry point and one result type.
#include "run/simulate.h"

#include "run/elastic_strains.h"
#include "stepping/shell3d_driver.h"

namespace vs {

RunResult simulate(const Scene& scene, const RunOptions& options) {
  RunResult result = scene.geometry == Geometry::kShell3d
                         ? shell3d::simulate_shell3d(scene, options)
                         : simulate_axisymmetric(scene, options);
  add_elastic_strains(scene, &result);
  return result;
}

}  // namespace vs
