// Linear elastic shell benchmarks of numerics.md section 1.3 as functions of the rule and mesh;
// each returns the computed displacement divided by the reference value. Shared by the tests.
#pragma once

#include <cmath>
#include <numbers>

#include "element/quadrature.h"
#include "mesh/mesh_generators.h"
#include "model/linear_shell.h"

namespace vs::shell3d::bench {

inline constexpr double kDeg = std::numbers::pi / 180.0;

inline LinearShellOptions options(Shell9Rule rule) {
  LinearShellOptions o;
  o.rule = rule;
  o.thickness = thickness_rule(ThicknessKind::kGauss, 2);
  return o;
}

// Scordelis-Lo roof, quarter model, n x n: vertical deflection at mid-span of the free edge
// over 0.3024 (MacNeal-Harder).
inline double scordelis_lo(Shell9Rule rule, int n) {
  const double R = 25.0;
  const ShellMesh mesh = cylinder_patch(R, 0.0, 25.0, 0.0, 40.0 * kDeg, n, n, 0.25);
  ShellModel model(mesh);
  for (int i : mesh.set("y1")) {  // rigid diaphragm: u_x = u_z = 0
    model.fix_translation(i, 0);
    model.fix_translation(i, 2);
  }
  for (int i : mesh.set("y0")) model.symmetry(i, Vec3::UnitY());
  for (int i : mesh.set("theta0")) model.symmetry(i, Vec3::UnitX());
  LinearShellProblem p(model, Shell9Material::Elastic(4.32e8, 0.0), options(rule));
  p.add_surface_load(Vec3(0.0, 0.0, -90.0));
  const Eigen::VectorXd q = p.solve();
  const int node =
      mesh.nearest_node(Vec3(R * std::sin(40.0 * kDeg), 0.0, R * std::cos(40.0 * kDeg)));
  return -p.translation(q, node).z() / 0.3024;
}

// Pinched cylinder with end diaphragms, octant model, n x n: radial displacement under the load
// over 1.8248e-5 (Lindberg, Olson & Cowper).
inline double pinched_cylinder(Shell9Rule rule, int n) {
  const double R = 300.0;
  const ShellMesh mesh = cylinder_patch(R, 0.0, 300.0, 0.0, 90.0 * kDeg, n, n, 3.0);
  ShellModel model(mesh);
  for (int i : mesh.set("y1")) {
    model.fix_translation(i, 0);
    model.fix_translation(i, 2);
  }
  for (int i : mesh.set("y0")) model.symmetry(i, Vec3::UnitY());
  for (int i : mesh.set("theta0")) model.symmetry(i, Vec3::UnitX());
  for (int i : mesh.set("theta1")) model.symmetry(i, Vec3::UnitZ());
  LinearShellProblem p(model, Shell9Material::Elastic(3e6, 0.3), options(rule));
  const int node = mesh.nearest_node(Vec3(0.0, 0.0, R));
  p.add_point_load(node, Vec3(0.0, 0.0, -0.25));
  const Eigen::VectorXd q = p.solve();
  return -p.translation(q, node).z() / 1.8248e-5;
}

// Pinched hemisphere with an 18-degree hole, quarter model, n x n: radial displacement under the
// load over 0.094 (MacNeal-Harder).
inline double pinched_hemisphere(Shell9Rule rule, int n) {
  const double R = 10.0;
  const ShellMesh mesh = sphere_patch(R, 18.0 * kDeg, 90.0 * kDeg, 0.0, 90.0 * kDeg, n, n, 0.04);
  ShellModel model(mesh);
  for (int i : mesh.set("a0")) model.symmetry(i, Vec3::UnitY());
  for (int i : mesh.set("a1")) model.symmetry(i, Vec3::UnitX());
  const int px = mesh.nearest_node(Vec3(R, 0.0, 0.0));
  const int py = mesh.nearest_node(Vec3(0.0, R, 0.0));
  model.fix_translation(px, 2);  // the remaining rigid mode: translation along z
  LinearShellProblem p(model, Shell9Material::Elastic(6.825e7, 0.3), options(rule));
  p.add_point_load(px, Vec3(1.0, 0.0, 0.0));
  p.add_point_load(py, Vec3(0.0, -1.0, 0.0));
  const Eigen::VectorXd q = p.solve();
  return p.translation(q, px).x() / 0.094;
}

// Twisted beam (90 degree pretwist, clamped root), n x 6n mesh, unit tip load along the tip's
// width direction (global z, reference 5.424e-3) or thickness direction (global y, 1.754e-3);
// thin variant t = 0.0032 with load 1e-6 (5.256e-3, 1.294e-3). Returns the tip-centre
// displacement along the load over the reference.
inline double twisted_beam(Shell9Rule rule, int n, bool load_z, bool thin = false) {
  const double t = thin ? 0.0032 : 0.32, P = thin ? 1e-6 : 1.0;
  const ShellMesh mesh = twisted_strip(12.0, 1.1, 90.0 * kDeg, n, 6 * n, t);
  ShellModel model(mesh);
  for (int i : mesh.set("root")) model.clamp(i);
  LinearShellProblem p(model, Shell9Material::Elastic(29e6, 0.22), options(rule));
  const Vec3 dir = load_z ? Vec3::UnitZ() : Vec3::UnitY();
  // Consistent edge load: per element edge weights 1/6, 4/6, 1/6 of its share 1/n.
  const auto& tip = mesh.set("tip");
  for (std::size_t k = 0; k < tip.size(); ++k) {
    const bool end = (k == 0 || k + 1 == tip.size());
    const double w = (k % 2 == 1) ? 4.0 / 6.0 : (end ? 1.0 / 6.0 : 2.0 / 6.0);
    p.add_point_load(tip[k], (P * w / n) * dir);
  }
  const Eigen::VectorXd q = p.solve();
  const int centre = mesh.nearest_node(Vec3(12.0, 0.0, 0.0));
  const double ref = thin ? (load_z ? 5.256e-3 : 1.294e-3) : (load_z ? 5.424e-3 : 1.754e-3);
  return p.translation(q, centre).dot(dir) / ref;
}

// Clamped square plate, side 1, L/h = 100, E = 3, nu = 0.5, uniform q = 1, quarter model
// n x n: centre deflection over Kirchhoff 0.00126532 q a^4 / D.
inline double clamped_plate(Shell9Rule rule, int n, double h = 0.01) {
  const ShellMesh mesh = rectangular_plate(0.5, 0.5, n, n, h);
  ShellModel model(mesh);
  for (int i : mesh.set("x1")) model.clamp(i);
  for (int i : mesh.set("y1")) model.clamp(i);
  for (int i : mesh.set("x0")) model.symmetry(i, Vec3::UnitX());
  for (int i : mesh.set("y0")) model.symmetry(i, Vec3::UnitY());
  const double E = 3.0, nu = 0.5;
  LinearShellProblem p(model, Shell9Material::Elastic(E, nu), options(rule));
  p.add_surface_load(Vec3(0.0, 0.0, -1.0));
  const Eigen::VectorXd q = p.solve();
  const double D = E * h * h * h / (12.0 * (1.0 - nu * nu));
  return -p.translation(q, mesh.nearest_node(Vec3::Zero())).z() / (0.00126532 / D);
}

}  // namespace vs::shell3d::bench
