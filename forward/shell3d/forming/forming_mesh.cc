#include "shell3d/forming/forming_mesh.h"

#include <cmath>
#include <vector>

#include "core/error.h"
#include "shell3d/mesh_generators.h"

namespace vs::shell3d {

ShellMesh forming_mesh(const Scene& scene) {
  const BlankSpec& b = scene.blank;
  const double R = b.radius_mm, h0 = b.thickness_mm;
  const int n = b.divisions;
  if (b.symmetry != BlankSymmetry::kQuarter) {
    throw InputError(scene.source + ": blank.symmetry: only quarter models are implemented");
  }
  ShellMesh mesh;
  const double tol = 1e-9 * R;
  if (b.shape == BlankShape::kCircle) {
    mesh = quarter_disc(R, n, n, h0);
    mesh.node_sets["edge"] = mesh.set("rim");
  } else {
    mesh = rectangular_plate(R, R, n, n, h0);
    add_node_set(&mesh, "edge", [=](const Eigen::Vector3d& x) {
      return std::abs(x.x() - R) < tol || std::abs(x.y() - R) < tol;
    });
  }
  add_node_set(&mesh, "diagonal",
               [=](const Eigen::Vector3d& x) { return std::abs(x.x() - x.y()) < tol; });
  return mesh;
}

}  // namespace vs::shell3d
