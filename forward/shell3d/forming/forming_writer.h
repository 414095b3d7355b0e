// The run folder of a 3D forming run (vshell run on a geometry = "shell3d" scene):
//   load_travel.csv                 every step (same columns as the axisymmetric run; whole blank)
//   profiles_travel_<T>mm.csv       per output stage: nodal profiles from the centre along
//                                   y0 (the x axis, x >= 0), x0 (the y axis, y >= 0) and the
//                                   diagonal (x = y >= 0); a full blank adds the other halves
//                                   y0_neg, x0_neg, diagonal_neg (r0_mm: distance from the axis)
//   fld_points.csv                  final major / minor / thickness / effective strain per element
//   stage_<k>.vtu, stages.pvd       ParaView series (the meshed part: a quarter blank needs
//                                   Reflect twice for the whole, a full blank is whole)
//   load_travel.svg, thickness_strain.svg, fld.svg   (if output.plots)
// A failed run writes the same files with what it has.
#pragma once

#include <string>

#include "scene/scene.h"
#include "shell3d/forming/forming_result.h"

namespace vs::shell3d {

void write_shell3d_run_folder(const Scene& scene, const Shell3dResult& result,
                              const std::string& dir);

// CSV text of the profiles of one stage (all lines of the mesh, see above).
std::string profiles_csv(const ShellMesh& mesh, const ShellStage& stage,
                         double initial_thickness_mm);

// The .vtu text of one stage.
std::string stage_vtu(const ShellMesh& mesh, const ShellStage& stage, double initial_thickness_mm);

}  // namespace vs::shell3d
