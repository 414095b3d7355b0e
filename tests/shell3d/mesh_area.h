// Mid-surface area of a 9-node mesh (sum of the element areas), shared by the mesh tests.
#pragma once

#include "element/shell9.h"
#include "mesh/shell_mesh.h"
#include "model/shell_model.h"

namespace vs::shell3d::test {

inline double total_area(const ShellMesh& mesh) {
  ShellModel model(mesh);
  double a = 0.0;
  for (int e = 0; e < mesh.num_elements(); ++e) a += shell9_area(model.element_geometry(e));
  return a;
}

}  // namespace vs::shell3d::test
