// ParaView files of a 3D run: one .vtu per stage of RunResult::shell (the meshed part: a quarter
// blank needs Reflect twice for the whole, a full blank is whole) and the .pvd series.
//   point data: thickness_mm, eps_thickness, contact_tool (0 free, k: tool k-1),
//               displacement_mm
//   cell data:  eps_major, eps_minor, eps_thickness_membrane, eps_effective
#pragma once

#include <string>

#include "run/run_result.h"

namespace vs {

// The .vtu text of one stage.
std::string stage_vtu(const shell3d::ShellMesh& mesh, const ShellStage& stage,
                      double initial_thickness_mm);

}  // namespace vs
