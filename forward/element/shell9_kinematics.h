// Kinematics of the 9-node degenerated (Ahmad) shell in rate form (paper eqs. 67-72).
//
// A point with surface coordinates (r, s) and thickness coordinate t in [-1, 1] sits at
//   x(r, s, t) = sum_a N_a(r, s) (x_a + t c_a V3_a),   c_a = h_a / 2,
// and moves with u = sum_a N_a (v_a + t c_a dV3_a), where v_a is the nodal velocity and dV3_a the
// rate of the director. The director stays a unit vector, so dV3_a = omega_a x V3_a for the
// angular velocity omega_a of the normal; the node's rotation dofs q_a give dV3_a = P_a q_a:
//   5-dof node (smooth surface): q = rates about the nodal axes V1, V2, omega = q1 V1 + q2 V2,
//     P = [V1 x V3, V2 x V3] = [-V2, V1]                       (paper eq. 69);
//   6-dof node (kink): q = omega in global axes, P = -[V3]_x; the rate about V3 ("drilling")
//     does not move this element's director and gets a small artificial stiffness (section 6.3).
//
// Covariant base vectors g_r = x_{,r}, g_s = x_{,s}, g_t = x_{,t}; the covariant strain rates
// (linearised: the velocity field is evaluated on the current geometry)
//   e_rr = g_r.u_{,r},  e_ss = g_s.u_{,s},  2e_rs = g_r.u_{,s} + g_s.u_{,r},
//   2e_rt = g_r.u_{,t} + g_t.u_{,r},  2e_st = g_s.u_{,t} + g_t.u_{,s}
// are collected as [e_rr, e_ss, 2e_rs, 2e_rt, 2e_st]; e_tt is dropped (plane stress). They are
// tensor components on the contravariant basis g^i (rows of J^-1, J = [g_r g_s g_t]), so the
// components in the local orthonormal frame (e1, e2, e3) are eps_ab = e_ij (g^i.e_a)(g^j.e_b).
// e3 = g_r x g_s / |.|, e1 = g_r / |g_r|, e2 = e3 x e1; g^t is parallel to e3, so e_tt never
// reaches the in-plane or transverse shear components (eq. 71: theta^T du/dx theta).
#pragma once

#include <Eigen/Core>
#include <array>

#include "element/lagrange9.h"

namespace vs::shell3d {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Mat5 = Eigen::Matrix<double, 5, 5>;
using Vec5 = Eigen::Matrix<double, 5, 1>;
using Mat5X = Eigen::Matrix<double, 5, Eigen::Dynamic>;

struct Shell9Geometry {
  std::array<Vec3, 9> x;            // mid-surface node positions [mm]
  std::array<Vec3, 9> director;     // unit directors V3 (the element's own normal at kinks)
  std::array<double, 9> thickness;  // h_a [mm]
  std::array<Mat3, 9> rot_map;      // P_a: columns 0..n_rot-1 map rotation dofs to dV3_a
  std::array<int, 9> n_rot;         // 2 or 3
  // Optional nodal velocity frames: with has_vel_frame, the 3 velocity dofs of node a are
  // components in the frame vel_frame[a] (global velocity = vel_frame[a] * dofs), so element
  // forces and matrices come out in those frames (the forming model's nodal frames, paper 6.7).
  bool has_vel_frame = false;
  std::array<Mat3, 9> vel_frame;
  // Optional material axes (planar anisotropy): the initial mid-surface nodes and the rolling
  // direction there. The element convects RD with the sheet: a material line along RD in the
  // initial configuration, dX = c_r G_r + c_s G_s (natural increments c), is c_r g_r + c_s g_s
  // now (shell9.h, Shell9Operators::FlowRow::rd_cos).
  bool has_material_axes = false;
  std::array<Vec3, 9> x_initial;
  Vec3 rd_initial = Vec3::UnitX();

  // Element dofs: per node 3 velocities then n_rot rotation rates.
  int ndof() const;
  int offset(int a) const;
};

// P for a 5-dof node with frame (V1, V2, V3), and for a 6-dof node with director V3.
Mat3 rot_map_5dof(const Vec3& v1, const Vec3& v2);
Mat3 rot_map_6dof(const Vec3& v3);

struct PointBasis {
  Mat3 J;       // columns g_r, g_s, g_t
  double detJ;  // dV = detJ dr ds dt
  Mat3 frame;   // columns e1, e2, e3
  Mat3 C;       // C(i, a) = g^i . e_a
  double h;     // interpolated thickness
};

PointBasis point_basis(const Shell9Geometry& g, const Shape9& sh, double t);

// Covariant strain rates [e_rr, e_ss, 2e_rs, 2e_rt, 2e_st] = B * q (element dofs q).
Mat5X covariant_B(const Shell9Geometry& g, const Shape9& sh, const PointBasis& pb, double t);

// Local engineering components [eps11, eps22, gam12, gam13, gam23] = T * covariant vector.
Mat5 local_transform(const Mat3& C);

}  // namespace vs::shell3d
