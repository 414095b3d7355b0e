// The fixed-gap blank holder of the 3D forming model (tool kind blank_holder with gap_mm): the 3D
// analogue of AxisymModel::add_gap_holder.
//
// The holder is a rigid flat face the gap g below the die face. The flange between the two may
// thicken up to g and no further; from then on the holder presses back with whatever pressure
// keeps it there, and the Coulomb friction of both faces acts on that pressure.
//
// Thickness. The 3D model's nodal thickness is h_i = h0 / s_i, with s_i the area stretch dA/dA0 at
// node i averaged over the elements that contain it (FormingModel::area_stretch). In element e the
// mid-surface area element is J = |g_r x g_s| (g_r = dx/dr, g_s = dx/ds of the 9-node
// interpolation x = sum_a N_a x_a), and its rate is J times the surface divergence of the
// mid-surface velocity v = sum_a N_a v_a:
//   dJ/dt = n . (v_r x g_s + g_r x v_s) = J div_s v,   n = g_r x g_s / J,
//   div_s v = sum_a b_a . v_a,   b_a = [dN_a/dr (g_s x n) + dN_a/ds (n x g_r)] / J
// (the triple products rearranged: n . (v_r x g_s) = v_r . (g_s x n), n . (g_r x v_s) =
// v_s . (n x g_r)). div_s v is the in-plane area rate d_11 + d_22 of the shell's mid-surface, the
// 3D counterpart of the axisymmetric d_s + d_t; a rigid motion gives 0, a uniform in-plane
// stretch v = c (x, y, 0) of a flat sheet gives 2 c (tests/shell3d/gap_holder_test.cc).
//
// Constraint. Over the step dt the thickness at node i ends at h_i exp(-(area rate) dt), which must
// stay <= g:   area rate >= c_i = min(ln(h_i / g), 0) / dt.
// s_i is a mean of the element stretches at node i, and d(ln s_i)/dt is the mean of their rates
// weighted by the stretches; so asking the rate div_s v at node i of EVERY element e that contains
// it to be >= c_i is sufficient for the nodal thickness (and element-local: the matrix keeps the
// element pattern of the assembly). As the axisymmetric model: no correction of an overshoot left
// by an earlier step (c_i <= 0; demanding it back within one step makes the pressure grow without
// bound as cut-backs shrink dt).
//
// Penalty and pressure. The plane-stress shell carries no through-thickness stress, but a holder
// pressure p acts on the flow like a hydrostatic shift of both in-plane stresses by -p: virtual
// power -p (area rate) per unit volume. The constraint of node a in element e is the penalty
//   Phi = k V_ea (c_a - div_s v(node a))_+^2 / 2,   V_ea = h_a integral_e N_a dA,
// k = 1e3 times the element's reference (transverse-shear) viscosity, as the axisymmetric model:
// the multiplier p_ea = k (c_a - div_s v)_+ [MPa] is the holder pressure at the node, its force on
// the velocities -p_ea V_ea b, its matrix k V_ea b b^T (linear in v: the same in the secant and the
// tangent). Nodal holder force: the pressure times the node's area share A_ea = integral_e N_a dA
// (the consistent nodal load of a uniform pressure), summed over the node's elements.
//
// Which nodes. A node is in the gap when it touches the die's flat face or the holder's face. As
// the axisymmetric model constrains every element with a node in the gap (the element straddling
// the holder's inner edge stays constrained until it has left completely; left free, it is
// squeezed between a node held by friction on both faces and a node running over the die
// shoulder, and folds), every node of an element with a node in the gap is constrained in that
// element. The holder force of a constrained node that is not in the gap goes to the element's
// nodes in the gap, shared by their areas (one node in the gap at the edge takes it all).
//
// Friction and contact (FormingModel, shell3d_driver.cc): the nodal holder forces of a converged
// state (lagged one state, as the axisymmetric driver: coupling them inside the Newton iteration
// does not converge) press a node on the die face up (+z) and a node on the holder face down (-z),
// so the tool's reaction carries them, and the opposite face adds its friction on them. A node in
// the gap whose thickness fills it (within 0.1 %) is sandwiched: it touches both faces, is never
// released, and a pull on the face it touches is the other face pushing, with that face's
// friction. A node drawn past the holder's inner edge leaves the holder face.
// At present the lagged holder forces do not reach the next solve, in either geometry: the
// drivers' attach() (AxisymStepper, Shell3dStepper) re-creates every contact node's record at the
// next step's contact maintenance and keeps only its normal force, so the holder's pressure loads
// neither face and its friction acts only through the sandwiched nodes. Keeping the holder force
// there makes a rigid 1.04 mm gap lock the ESAFORM flange in both solvers (measured:
// experiments/05_shell3d/README.md, "ESAFORM cup in 3D, fixed-gap holder").
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "element/shell9.h"
#include "mesh/shell_mesh.h"
#include "model/shell_assembler.h"

namespace vs::shell3d {

// The surface divergence operator of the 9-node mid-surface with nodes x at natural coordinates
// (r, s): div_s v = sum_a b.row(a) . v_a for global nodal velocities v_a (see the header comment).
// `area_jacobian` (optional) receives J = |g_r x g_s|.
Eigen::Matrix<double, 9, 3> surface_divergence(const std::array<Vec3, 9>& x, double r, double s,
                                               double* area_jacobian = nullptr);

// Lumped area shares integral_e N_a dA of one 9-node element with nodes x (3 x 3 Gauss, as
// FormingModel::lumped_areas).
std::array<double, 9> element_area_shares(const std::array<Vec3, 9>& x);

struct GapHolderInput {
  const ShellMesh* mesh = nullptr;
  const std::vector<Vec3>* x = nullptr;            // node positions [mm]
  const std::vector<double>* thickness = nullptr;  // per node [mm]
  const std::vector<char>* in_gap = nullptr;       // per node
  const std::vector<Mat3>* frame = nullptr;        // nodal velocity frames (global = Q local)
  // Optional face couplings C (FormingModel::face_coupling): the mid-surface velocity of a node
  // is Q (q_t - C q_r) in its 5 local unknowns q = (q_t, q_r); null: C = 0.
  const std::vector<Eigen::Matrix<double, 3, 2>>* face = nullptr;
  const std::vector<double>* viscosity = nullptr;  // per element reference viscosity [MPa s]
  double gap_mm = 0.0;
  double dt_s = 0.0;  // the step the constraint is for
  // Ironing between two tools (FormingModel::update_squeezed; AxisymModel::add_squeeze): each
  // node in the gap has its own clearance (node_gap, per node [mm]; an element's gap is the
  // smallest of its nodes in the gap), and an overshoot h > g is corrected: the bound is
  //   c = ironing_log_target(h, g, max_log_ratio, correction) / dt   (model/ironing.h)
  // instead of min(ln(h / g), 0) / dt, as the axisymmetric model: max_log_ratio (the strain cap
  // of a step) and correction (dt / the time of a regular step, <= 1) spread the correction of
  // an overshoot over steps. Null / 0: the fixed-gap holder.
  const std::vector<double>* node_gap = nullptr;
  double max_log_ratio = 0.0;
  double correction = 1.0;
};

class GapHolder3 {
 public:
  // Builds the constraints of a configuration (FormingModel::prepare).
  void prepare(const GapHolderInput& in);
  bool empty() const { return constrained_elements_ == 0; }
  // Adds the penalty's force, potential and (want_matrix) matrix of element e at its element
  // velocities qe (5 per node, velocities first in the nodal frames) to c. Thread-safe.
  void add(int e, const Eigen::VectorXd& qe, bool want_matrix, ElementContribution* c) const;
  // Nodal holder forces [N] (meshed part) of element velocities gathered by `gather`.
  template <class Gather>
  std::vector<double> nodal_forces(int num_nodes, const Gather& gather) const {
    std::vector<double> f(static_cast<std::size_t>(num_nodes), 0.0);
    for (std::size_t e = 0; e < constraints_.size(); ++e) {
      if (constraints_[e].empty()) continue;
      add_element_forces(static_cast<int>(e), gather(static_cast<int>(e)), &f);
    }
    return f;
  }

 private:
  struct Constraint {
    int local = 0;                   // node of the element (0-8)
    double rate_bound = 0.0;         // c [1/s]
    double stiffness = 0.0;          // k V_ea [N s mm]
    double penalty = 0.0;            // k [MPa s]
    double area = 0.0;               // A_ea [mm^2]
    Eigen::Matrix<double, 45, 1> b;  // div_s v = b . (the 5 local unknowns of the 9 nodes)
  };
  void add_element_forces(int e, const Eigen::VectorXd& qe, std::vector<double>* f) const;

  const ShellMesh* mesh_ = nullptr;
  std::vector<std::vector<Constraint>> constraints_;  // per element
  std::vector<std::array<char, 9>> gap_nodes_;        // per element: which nodes are in the gap
  int constrained_elements_ = 0;
};

}  // namespace vs::shell3d
