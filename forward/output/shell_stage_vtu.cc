#include "output/shell_stage_vtu.h"

#include <cmath>
#include <vector>

#include "model/forming_fields.h"
#include "output/vtu_writer.h"

namespace vs {

double zone_code(FormingZone zone) {
  switch (zone) {
    case FormingZone::kSafe:
      return 0.0;
    case FormingZone::kMarginal:
      return 1.0;
    case FormingZone::kFailed:
      return 2.0;
    case FormingZone::kUnknown:
      return -1.0;
  }
  return -1.0;
}

std::string stage_vtu(const shell3d::ShellMesh& mesh, const ShellStage& stage,
                      double initial_thickness_mm, const FormingLimitCurve& flc) {
  VtuGrid grid;
  const std::size_t nn = stage.x.size();
  for (const Eigen::Vector3d& x : stage.x) {
    grid.points.insert(grid.points.end(), {x.x(), x.y(), x.z()});
  }
  for (const auto& el : mesh.elements) {
    for (int a : el) grid.connectivity.push_back(a);
    grid.offsets.push_back(static_cast<std::int64_t>(grid.connectivity.size()));
    grid.types.push_back(kVtkBiquadraticQuad);  // same node order as lagrange9.h
  }
  VtuField thickness{"thickness_mm", 1, stage.thickness_mm};
  VtuField eps_t{"eps_thickness", 1, {}};
  VtuField thinning{"thinning_percent", 1, {}};
  VtuField contact{"contact_tool", 1, {}};
  VtuField disp{"displacement_mm", 3, {}};
  for (std::size_t i = 0; i < nn; ++i) {
    eps_t.values.push_back(std::log(stage.thickness_mm[i] / initial_thickness_mm));
    thinning.values.push_back(100.0 * (1.0 - stage.thickness_mm[i] / initial_thickness_mm));
    contact.values.push_back(stage.contact_tool[i] + 1.0);  // 0 free, k = tool k-1
    const Eigen::Vector3d d = stage.x[i] - mesh.nodes[i];
    disp.values.insert(disp.values.end(), {d.x(), d.y(), d.z()});
  }
  const shell3d::ElementStrains e = shell3d::element_strains(mesh, stage);
  std::vector<VtuField> cells = {VtuField{"eps_major", 1, e.major},
                                 VtuField{"eps_minor", 1, e.minor},
                                 VtuField{"eps_thickness_membrane", 1, e.thickness},
                                 VtuField{"eps_effective", 1, e.effective}};
  if (stage.effective_stress_MPa.size() == mesh.elements.size()) {
    cells.push_back(VtuField{"effective_stress_MPa", 1, stage.effective_stress_MPa});
  }
  if (flc.defined()) {
    VtuField margin{"flc_margin", 1, {}};
    VtuField zone{"flc_zone", 1, {}};
    for (std::size_t k = 0; k < e.major.size(); ++k) {
      const FormingMargin m = forming_margin(flc, e.major[k], e.minor[k]);
      margin.values.push_back(m.margin);
      zone.values.push_back(zone_code(m.zone));
    }
    cells.push_back(std::move(margin));
    cells.push_back(std::move(zone));
  }
  return render_vtu(grid, {thickness, eps_t, thinning, contact, disp}, cells);
}

}  // namespace vs
