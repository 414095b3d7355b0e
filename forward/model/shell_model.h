// Nodal directors, nodal frames, dof numbering and constraints of a 9-node shell mesh.
//
// Directors: the exact normal when the mesh has one, else the normalised average of the element
// normals g_r x g_s at the node. A node is "kinked" (non-coplanar, paper section 6.3) when an
// element normal there deviates from the average by more than kink_angle_deg. Kinked nodes get
// 6 dofs (3 velocities, global angular velocity) and each element uses its own normal there, so
// one element's drilling rate is another's bending rate; a small drilling stiffness keeps the
// matrix regular (shell9.h). Smooth nodes get 5 dofs (3 velocities, rates about V1 and V2).
//
// Nodal frame (V1, V2, V3): V1 is a reference direction projected onto the tangent plane (by
// default global x, or global y when V3 is within 25 degrees of x), V2 = V3 x V1. A symmetry
// plane with normal n needs the rotation components normal to n fixed: set the frame hint V1 = n
// at its nodes, then fix the rate about V2 (fix_rotation_about checks representability).
//
// Global dofs are numbered node by node. Constraints are kept as (dof, value) and imposed on the
// assembled system without changing its pattern (assembler.h).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "element/shell9_kinematics.h"
#include "mesh/shell_mesh.h"

namespace vs::shell3d {

struct ShellModelOptions {
  double kink_angle_deg = 5.0;
  bool all_six_dof = false;  // 6 dofs at every node (tests, branched shells)
};

class ShellModel {
 public:
  explicit ShellModel(const ShellMesh& mesh, const ShellModelOptions& options = {});

  const ShellMesh& mesh() const { return *mesh_; }
  int num_dofs() const { return num_dofs_; }
  int num_nodes() const { return mesh_->num_nodes(); }
  int num_elements() const { return mesh_->num_elements(); }

  bool six_dof(int node) const { return six_[node]; }
  int num_kinked() const;
  const Vec3& director(int node) const { return v3_[node]; }
  const Vec3& v1(int node) const { return v1_[node]; }
  const Vec3& v2(int node) const { return v2_[node]; }
  // Re-orients V1 towards `dir` (projected on the tangent plane). Dof count is unchanged.
  void set_frame_hint(int node, const Vec3& dir);

  // Global dof of component k of a node: 0..2 velocities (global x, y, z), 3.. rotation rates.
  int dof(int node, int k) const { return first_dof_[node] + k; }
  int node_dofs(int node) const { return six_[node] ? 6 : 5; }

  Shell9Geometry element_geometry(int e) const;
  std::vector<int> element_dofs(int e) const;

  // Constraints (value = prescribed rate).
  void fix(int node, int k, double value = 0.0);
  void fix_translation(int node, int axis, double value = 0.0);
  // Zero rotation rate about `axis`: at 5-dof nodes `axis` must be parallel to V1 or V2 (or to V3,
  // which carries no dof); at 6-dof nodes it must be a global axis.
  void fix_rotation_about(int node, const Vec3& axis);
  void clamp(int node);
  // Symmetry plane with normal n along a global axis: u.n = 0 and rotation components
  // perpendicular to n zero; V3 must lie in the plane. Sets the frame hint V1 = n first.
  void symmetry(int node, const Vec3& n);
  const std::vector<char>& fixed() const { return fixed_; }
  const std::vector<double>& fixed_value() const { return value_; }

 private:
  void number_dofs();

  const ShellMesh* mesh_;
  std::vector<Vec3> v1_, v2_, v3_;
  std::vector<char> six_;
  std::vector<int> first_dof_;
  int num_dofs_ = 0;
  std::vector<char> fixed_;
  std::vector<double> value_;
};

// Element normal g_r x g_s / |.| at node a of a 9-node element with node coordinates x.
Vec3 element_normal_at_node(const std::array<Vec3, 9>& x, int a);

}  // namespace vs::shell3d
