#include "model/shell_model.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace vs::shell3d {

Vec3 element_normal_at_node(const std::array<Vec3, 9>& x, int a) {
  const auto rs = lagrange9_node(a);
  const Shape9 sh = lagrange9(rs[0], rs[1]);
  Vec3 gr = Vec3::Zero(), gs = Vec3::Zero();
  for (int b = 0; b < 9; ++b) {
    gr += sh.dr(b) * x[b];
    gs += sh.ds(b) * x[b];
  }
  return gr.cross(gs).normalized();
}

namespace {
std::array<Vec3, 9> element_coords(const ShellMesh& m, int e) {
  std::array<Vec3, 9> x;
  for (int a = 0; a < 9; ++a) x[a] = m.nodes[m.elements[e][a]];
  return x;
}
}  // namespace

ShellModel::ShellModel(const ShellMesh& mesh, const ShellModelOptions& options) : mesh_(&mesh) {
  const int nn = mesh.num_nodes();
  std::vector<Vec3> sum(nn, Vec3::Zero());
  std::vector<std::vector<Vec3>> seen(nn);
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const auto x = element_coords(mesh, e);
    for (int a = 0; a < 9; ++a) {
      const Vec3 n = element_normal_at_node(x, a);
      sum[mesh.elements[e][a]] += n;
      seen[mesh.elements[e][a]].push_back(n);
    }
  }
  const double cos_tol = std::cos(options.kink_angle_deg * std::numbers::pi / 180.0);
  v1_.resize(nn);
  v2_.resize(nn);
  v3_.resize(nn);
  six_.assign(nn, 0);
  for (int i = 0; i < nn; ++i) {
    const Vec3 avg = sum[i].normalized();
    six_[i] = options.all_six_dof ? 1 : 0;
    for (const Vec3& n : seen[i])
      if (n.dot(avg) < cos_tol) six_[i] = 1;
    v3_[i] = mesh.exact_normal.empty() ? avg : mesh.exact_normal[i].normalized();
    const Vec3 ref = std::abs(v3_[i].x()) > std::cos(25.0 * std::numbers::pi / 180.0)
                         ? Vec3::UnitY()
                         : Vec3::UnitX();
    set_frame_hint(i, ref);
  }
  number_dofs();
}

int ShellModel::num_kinked() const {
  int n = 0;
  for (char c : six_) n += c;
  return n;
}

void ShellModel::set_frame_hint(int node, const Vec3& dir) {
  const Vec3& v3 = v3_[node];
  const Vec3 p = dir - dir.dot(v3) * v3;
  if (p.norm() < 1e-8 * dir.norm()) throw std::invalid_argument("frame hint parallel to V3");
  v1_[node] = p.normalized();
  v2_[node] = v3.cross(v1_[node]);
}

void ShellModel::number_dofs() {
  const int nn = mesh_->num_nodes();
  first_dof_.resize(nn);
  num_dofs_ = 0;
  for (int i = 0; i < nn; ++i) {
    first_dof_[i] = num_dofs_;
    num_dofs_ += node_dofs(i);
  }
  fixed_.assign(num_dofs_, 0);
  value_.assign(num_dofs_, 0.0);
}

Shell9Geometry ShellModel::element_geometry(int e) const {
  Shell9Geometry g;
  const auto& conn = mesh_->elements[e];
  for (int a = 0; a < 9; ++a) g.x[a] = mesh_->nodes[conn[a]];
  for (int a = 0; a < 9; ++a) {
    const int i = conn[a];
    g.thickness[a] = mesh_->thickness[i];
    if (six_[i]) {
      g.director[a] = element_normal_at_node(g.x, a);
      g.rot_map[a] = rot_map_6dof(g.director[a]);
      g.n_rot[a] = 3;
    } else {
      g.director[a] = v3_[i];
      g.rot_map[a] = rot_map_5dof(v1_[i], v2_[i]);
      g.n_rot[a] = 2;
    }
  }
  return g;
}

std::vector<int> ShellModel::element_dofs(int e) const {
  std::vector<int> d;
  for (int i : mesh_->elements[e])
    for (int k = 0; k < node_dofs(i); ++k) d.push_back(first_dof_[i] + k);
  return d;
}

void ShellModel::fix(int node, int k, double value) {
  if (k < 0 || k >= node_dofs(node)) throw std::out_of_range("ShellModel::fix: bad component");
  fixed_[dof(node, k)] = 1;
  value_[dof(node, k)] = value;
}

void ShellModel::fix_translation(int node, int axis, double value) { fix(node, axis, value); }

void ShellModel::fix_rotation_about(int node, const Vec3& axis) {
  const Vec3 a = axis.normalized();
  constexpr double kTol = 1e-6;
  if (six_[node]) {
    for (int k = 0; k < 3; ++k)
      if (std::abs(std::abs(a(k)) - 1.0) < kTol) return fix(node, 3 + k);
    throw std::invalid_argument("fix_rotation_about: 6-dof node needs a global axis");
  }
  if (std::abs(std::abs(a.dot(v1_[node])) - 1.0) < kTol) return fix(node, 3);
  if (std::abs(std::abs(a.dot(v2_[node])) - 1.0) < kTol) return fix(node, 4);
  if (std::abs(std::abs(a.dot(v3_[node])) - 1.0) < kTol) return;  // no drilling dof
  throw std::invalid_argument("fix_rotation_about: axis not along V1, V2 or V3");
}

void ShellModel::clamp(int node) {
  for (int k = 0; k < node_dofs(node); ++k) fix(node, k);
}

void ShellModel::symmetry(int node, const Vec3& n) {
  const Vec3 u = n.normalized();
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(u(k)) - 1.0) < 1e-12) fix_translation(node, k);
  if (six_[node]) {
    for (int k = 0; k < 3; ++k)
      if (std::abs(u(k)) < 1e-12) fix(node, 3 + k);
    return;
  }
  // A node already on another symmetry plane (V3 along the intersection of the two planes) has
  // all tangential rotation rates zero; re-orienting its frame would misplace the first fix.
  if (fixed_[dof(node, 3)] || fixed_[dof(node, 4)]) {
    fix(node, 3);
    fix(node, 4);
    return;
  }
  set_frame_hint(node, u);
  fix(node, 4);  // rate about V2 = V3 x n; the rate about V3 has no dof
}

}  // namespace vs::shell3d
