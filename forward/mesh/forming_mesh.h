// The initial mesh of a 3D forming scene (geometry = shell3d), in z = 0, and the node sets the
// forming model and the outputs need.
//   blank.symmetry = quarter: quarter circular blank (O-grid of three n x n blocks) or quarter
//     square blank (n x n), x, y >= 0; "x0", "y0" are the symmetry planes.
//   blank.symmetry = full: the quarter mesh of the same divisions mirrored onto all four
//     quadrants (full_disc(R, 2n, n) / full_square(R, 2n)), so a full and a quarter run of one
//     scene discretise the same sheet; no symmetry planes.
// Sets: "edge" (the outer boundary where blank.edge applies), the profile lines from the centre
// "y0" (x >= 0 on y = 0), "x0" (y >= 0 on x = 0), "diagonal" (x = y >= 0), and for full blanks
// their other halves "y0_neg" (x <= 0), "x0_neg" (y <= 0), "diagonal_neg" (x = y <= 0).
#pragma once

#include "mesh/shell_mesh.h"
#include "scene/scene.h"

namespace vs::shell3d {

ShellMesh forming_mesh(const Scene& scene);

}  // namespace vs::shell3d
