#include "mesh/forming_mesh.h"

#include <cmath>
#include <string>
#include <vector>

#include "mesh/mesh_generators.h"

namespace vs::shell3d {

namespace {

ShellMesh quarter_blank(const BlankSpec& b) {
  const double R = b.radius_mm, tol = 1e-9 * R;
  const int n = b.divisions;
  if (b.shape == BlankShape::kCircle) {
    ShellMesh mesh = quarter_disc(R, n, b.ring_divisions(), b.thickness_mm);
    mesh.node_sets["edge"] = mesh.set("rim");
    return mesh;
  }
  ShellMesh mesh = rectangular_plate(R, R, n, n, b.thickness_mm);
  add_node_set(&mesh, "edge", [=](const Eigen::Vector3d& x) {
    return std::abs(x.x() - R) < tol || std::abs(x.y() - R) < tol;
  });
  return mesh;
}

// Splits the whole line `name` through the centre into the half with coordinate c >= 0 (kept
// under `name`, so profiles and comparisons read the same set as for a quarter blank) and the
// half c <= 0 (`name`_neg); both start at the centre node.
void split_line(ShellMesh* mesh, const std::string& name, int axis, double tol) {
  std::vector<int> pos, neg;
  for (int i : mesh->set(name)) {
    const double c = mesh->nodes[i](axis);
    if (c > -tol) pos.push_back(i);
    if (c < tol) neg.push_back(i);
  }
  mesh->node_sets[name] = pos;
  mesh->node_sets[name + "_neg"] = neg;
}

ShellMesh full_blank(const BlankSpec& b) {
  const double R = b.radius_mm;
  const int n = b.divisions;
  ShellMesh mesh = b.shape == BlankShape::kCircle
                       ? full_disc(R, 2 * n, b.ring_divisions(), b.thickness_mm)
                       : full_square(R, 2 * n, b.thickness_mm);
  const double tol = 1e-9 * R;
  split_line(&mesh, "y0", 0, tol);
  split_line(&mesh, "x0", 1, tol);
  split_line(&mesh, "diagonal", 0, tol);
  return mesh;
}

}  // namespace

ShellMesh forming_mesh(const Scene& scene) {
  const BlankSpec& b = scene.blank;
  if (b.symmetry == BlankSymmetry::kFull) return full_blank(b);
  ShellMesh mesh = quarter_blank(b);
  const double tol = 1e-9 * b.radius_mm;
  add_node_set(&mesh, "diagonal",
               [=](const Eigen::Vector3d& x) { return std::abs(x.x() - x.y()) < tol; });
  return mesh;
}

}  // namespace vs::shell3d
