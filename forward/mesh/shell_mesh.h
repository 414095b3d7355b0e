// A mesh of 9-node shell elements: node coordinates, connectivity (lagrange9.h node order),
// nodal thickness, optional exact nodal normals (from a generator of an analytic surface), and
// named node sets (symmetry edges, clamped edges, load points).
#pragma once

#include <Eigen/Core>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace vs::shell3d {

struct ShellMesh {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<int, 9>> elements;
  std::vector<double> thickness;              // per node [mm]
  std::vector<Eigen::Vector3d> exact_normal;  // per node or empty (then averaged, see model)
  std::map<std::string, std::vector<int>> node_sets;

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_elements() const { return static_cast<int>(elements.size()); }
  const std::vector<int>& set(const std::string& name) const;
  // Node nearest to p.
  int nearest_node(const Eigen::Vector3d& p) const;
};

// Builds a 9-node mesh from 4-node quads (corner coordinates, counter-clockwise): midside nodes
// at edge midpoints, shared between neighbours; centre nodes at the bilinear centre.
ShellMesh quad9_from_quad4(const std::vector<Eigen::Vector3d>& corners,
                           const std::vector<std::array<int, 4>>& quads, double thickness);

}  // namespace vs::shell3d
