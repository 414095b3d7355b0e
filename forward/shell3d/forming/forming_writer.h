// The run folder of a 3D forming run (vshell run on a geometry = "shell3d" scene):
//   load_travel.csv                 every step (same columns as the axisymmetric run; whole blank)
//   profiles_travel_<T>mm.csv       per output stage: nodal profiles along the symmetry lines
//                                   y0 (the x axis), x0 (the y axis) and the diagonal
//   fld_points.csv                  final major / minor / thickness / effective strain per element
//   stage_<k>.vtu, stages.pvd       ParaView series (quarter blank; Reflect twice for the whole)
//   load_travel.svg, thickness_strain.svg, fld.svg   (if output.plots)
// A failed run writes the same files with what it has.
#pragma once

#include <string>

#include "scene/scene.h"
#include "shell3d/forming/forming_result.h"

namespace vs::shell3d {

void write_shell3d_run_folder(const Scene& scene, const Shell3dResult& result,
                              const std::string& dir);

// CSV text of the profiles of one stage (all three lines).
std::string profiles_csv(const ShellMesh& mesh, const ShellStage& stage,
                         double initial_thickness_mm);

// The .vtu text of one stage.
std::string stage_vtu(const ShellMesh& mesh, const ShellStage& stage, double initial_thickness_mm);

}  // namespace vs::shell3d
