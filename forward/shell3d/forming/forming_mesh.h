// The initial mesh of a 3D forming scene (geometry = shell3d): quarter circular blank (O-grid of
// three n x n blocks) or quarter square blank (n x n), both in z = 0 with x, y >= 0, and the node
// sets the forming model needs: "x0", "y0" (symmetry planes), "edge" (the outer boundary where
// blank.edge applies) and "diagonal" (x = y, for output profiles).
#pragma once

#include "scene/scene.h"
#include "shell3d/shell_mesh.h"

namespace vs::shell3d {

ShellMesh forming_mesh(const Scene& scene);

}  // namespace vs::shell3d
