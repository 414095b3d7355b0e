#include "output/shell_stage_vtu.h"

#include <cmath>
#include <vector>

#include "output/vtu_writer.h"
#include "model/forming_fields.h"

namespace vs {

std::string stage_vtu(const shell3d::ShellMesh& mesh, const ShellStage& stage,
                      double initial_thickness_mm) {
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
  VtuField contact{"contact_tool", 1, {}};
  VtuField disp{"displacement_mm", 3, {}};
  for (std::size_t i = 0; i < nn; ++i) {
    eps_t.values.push_back(std::log(stage.thickness_mm[i] / initial_thickness_mm));
    contact.values.push_back(stage.contact_tool[i] + 1.0);  // 0 free, k = tool k-1
    const Eigen::Vector3d d = stage.x[i] - mesh.nodes[i];
    disp.values.insert(disp.values.end(), {d.x(), d.y(), d.z()});
  }
  const shell3d::ElementStrains e = shell3d::element_strains(mesh, stage);
  return render_vtu(grid, {thickness, eps_t, contact, disp},
                    {VtuField{"eps_major", 1, e.major}, VtuField{"eps_minor", 1, e.minor},
                     VtuField{"eps_thickness_membrane", 1, e.thickness},
                     VtuField{"eps_effective", 1, e.effective}});
}

}  // namespace vs
