// ParaView files of a 3D run: one .vtu per stage of RunResult::shell (the meshed part: a quarter
// blank needs Reflect twice for the whole, a full blank is whole) and the .pvd series.
//   point data: thickness_mm, eps_thickness, thinning_percent, contact_tool (0 free, k: tool
//               k-1), displacement_mm
//   cell data:  eps_major, eps_minor, eps_thickness_membrane, eps_effective,
//               effective_stress_MPa (when the stage has it), and with a forming-limit
//               curve flc_margin (FLC major strain minus eps_major) and flc_zone (0 safe,
//               1 marginal, 2 failed)
#pragma once

#include <string>

#include "output/forming_limit.h"
#include "run/run_result.h"

namespace vs {

// The .vtu text of one stage.
std::string stage_vtu(const shell3d::ShellMesh& mesh, const ShellStage& stage,
                      double initial_thickness_mm, const FormingLimitCurve& flc = {});

// flc_zone of the .vtu files: 0 safe, 1 marginal, 2 failed, -1 unknown.
double zone_code(FormingZone zone);

}  // namespace vs
