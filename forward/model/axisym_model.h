// The axisymmetric viscous-shell model: meridian mesh, per-step state, and assembly of the
// residual, the (secant or tangent) stiffness and the flow potential for a velocity field, with
// contact nodes expressed in their nodal friction frames (paper section 4.4).
//
// Unknowns: 3 per node (u, w, beta) in the global frame, except at contact nodes, whose first two
// unknowns are rotated into the tool frame (tangential v_t, normal v_n). A contact node's normal
// velocity equals the tool's; its tangential velocity is free with a regularised Coulomb force
// (arctan law, numerics.md section 3.5) from the lagged normal reaction, or equals the tool's for
// sticking friction. Nodes on the axis have u = beta = 0.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "contact/rigid_tool.h"
#include "element/axisym2.h"
#include "linalg/block_tridiag.h"
#include "material/hardening.h"
#include "material/viscous_law.h"
#include "scene/scene.h"

namespace vs {

struct NodeContact {
  int tool = -1;                                      // index into tools, -1 = free
  Eigen::Vector2d normal = Eigen::Vector2d::UnitY();  // from the tool into the sheet
  double normal_force_N = 0.0;  // lagged normal reaction (compressive > 0), full 360 degrees
  // Force holder: its share pressing this node against the die face. Fixed-gap holder: the
  // gap pressure times the node's flange area, exerted by the face the node does not touch.
  double holder_force_N = 0.0;
  bool on_die_face = false;     // touching the flat face of the die (the flange)
  bool on_holder_face = false;  // touching a fixed-gap blank holder (the flange, from below)
  bool sandwiched = false;      // fixed-gap flange node filling the gap (see AxisymModel)
  // Sticking tool, edge of the stuck patch: the node touches without friction (normal
  // constraint only) until the patch grows past it (see simulate.cc, Driver::attach).
  bool slip_edge = false;
  // Squeeze (ironing): the node touches `tool` and the other surface of the sheet reaches
  // `squeeze_tool` (e.g. a cup wall between the punch and the die wall); the thickness of its
  // elements is held at the clearance between the two tool surfaces through the node. The second
  // tool's pressure force (full 360 degrees, lagged one converged state) adds friction on both
  // faces.
  int squeeze_tool = -1;
  double clearance_mm = 0.0;
  double squeeze_force_N = 0.0;
};

// Everything that changes from step to step.
struct AxisymState {
  double time_s = 0.0;
  std::vector<Eigen::Vector2d> x;            // node coordinates (r, z) [mm]
  std::vector<double> thickness;             // per element [mm]
  std::vector<double> eps_bar;               // per element and thickness point (row-major)
  std::vector<Eigen::Vector2d> tool_offset;  // per tool
  std::vector<NodeContact> contact;          // per node
  Eigen::VectorXd v;                         // last converged velocity (global frame)
};

// The implicit geometry update's coupling (stepping/step_driver.h): the velocity solve in the
// end-of-step configuration x_n + scale v sees the change of its internal forces with that
// configuration through the membrane initial-stress stiffness of the previous iterate's stress
// resultants, K_g (scale) (v - v_ref), with potential (scale / 2) |v - v_ref|^2_K_g.
struct GeometryCoupling {
  double scale_s = 0.0;          // d x / d v = theta dt [s]
  std::vector<Vec5> resultants;  // per element, of the previous iterate
  Eigen::VectorXd v_ref;         // the previous iterate's velocity (global frame)
};

// One evaluation of the discrete system in the nodal (friction) frames.
struct AxisymSystem {
  BlockTridiag K;                  // stiffness with prescribed dofs replaced by identity
  Eigen::VectorXd residual;        // at free dofs; zero at prescribed dofs
  double potential = 0.0;          // flow potential (line-search merit); with kNone and kTangent
  Eigen::VectorXd element_force;   // f_el in the global frame (reactions = f_el - f_ext)
  Eigen::VectorXd external_force;  // f_ext in the global frame
  // Fixed-gap blank holder: contact pressure on the flange per element [MPa] (0 where the flange
  // is thinner than the gap); empty without a fixed-gap holder.
  std::vector<double> gap_pressure;
  std::vector<double> squeeze_pressure;  // per element [MPa] (squeeze constraint, see AxisymModel)
  std::vector<double> squeeze_friction;  // per node: friction of the squeezing tool (local t)
  // Element sums of evaluate_elements() (global frame, before friction and prescribed dofs):
  // the stiffness, K_elements = secant with kSecant or split kTangent, secant + element_weight *
  // tangent part with a kTangent at a fixed weight; and the tangent part with a split kTangent.
  BlockTridiag K_elements;
  BlockTridiag K_tangent_part;
  double element_weight = -1.0;    // kTangent: the weight in K_elements, -1: split
  double element_potential = 0.0;  // with kNone and kTangent
  StiffnessKind element_kind = StiffnessKind::kNone;  // what the element sums hold
  // Workspace, reused when the same AxisymSystem is evaluated again (no allocations per
  // iteration): the global velocity, the prescribed mask and values, one element's output.
  Eigen::VectorXd v_global;
  std::vector<char> fixed;
  // kTangent: flow direction m (2 each) and cut-off rate eh per element and thickness point.
  std::vector<double> directions;
  std::vector<double> cutoff_rates;
  // Set keep_element_states to have evaluate_elements() with kNone also keep the effective strain
  // rate at every thickness point and the stress resultants of every element.
  bool keep_element_states = false;
  std::vector<std::vector<double>> point_rates;
  std::vector<Vec5> resultants;
  Eigen::VectorXd fixed_values;
  Axisym2Output element;
};

class AxisymModel {
 public:
  explicit AxisymModel(const Scene& scene);

  int num_nodes() const { return static_cast<int>(r0_.size()); }
  int num_elements() const { return num_nodes() - 1; }
  int num_dofs() const { return 3 * num_nodes(); }
  const Scene& scene() const { return scene_; }
  const std::vector<RigidTool>& tools() const { return tools_; }
  const ThicknessRule& rule() const { return rule_; }
  const ViscousLaw& law() const { return law_; }
  const Hardening& hardening() const { return hardening_; }
  double nominal_rate() const { return nominal_rate_; }
  double punch_speed() const { return scene_.process.punch_speed_mm_per_s; }
  double initial_length(int e) const { return l0_[e]; }
  double initial_mid_radius(int e) const { return 0.5 * (r0_[e] + r0_[e + 1]); }
  double initial_radius(int node) const { return r0_[node]; }
  double initial_thickness() const { return scene_.blank.thickness_mm; }
  double element_volume(int e) const { return volume_[e]; }
  int punch_index() const { return punch_; }

  AxisymState initial_state() const;

  // Places the tools at the state's offsets (tools are shared, positions come from the state).
  // With numerics.normal_stress = contact it also freezes the face pressures of the elements for
  // the solves that follow (freeze_face_pressures): the drivers call it at the start of every
  // solve and never inside one.
  void place_tools(const AxisymState& s);

  // Through-thickness normal stress (material/normal_stress.h): each element's face pressures
  // from the contact forces of s, held until the next call. A contact node's pressure is its
  // normal reaction (NodeContact::normal_force_N: the lagged value, which at the start of a solve
  // is the last converged state's) over its nodal area, the half mid-surface areas 2 pi r_m L / 2
  // of its elements (the consistent nodal area of a uniform pressure on the one-point element);
  // a holder's or squeezing tool's force (holder_force_N, squeeze_force_N) presses the other face.
  // An element gets the mean of its two nodes' pressures on each face; the face a tool touches is
  // the lower one if the tool's normal points along the element normal (-s, c).
  void freeze_face_pressures(const AxisymState& s);
  const std::vector<FacePressure>& face_pressures() const { return face_pressure_; }

  // Per-step material data: yield stress sigma_y(eps_bar) and hardening viscosity H(eps_bar) dt
  // per point, shear penalty per element. The solve then sees the flow stress at the end of the
  // step it is used for, sigma_y(eps_bar) + H dt eps_dot (backward Euler in the hardening; dt: the
  // predicted step size). eps_bar: per element and thickness point, as AxisymState::eps_bar
  // (the state's own, or the start-of-step values for the Heun predictor's solve).
  void freeze_material(const std::vector<double>& eps_bar, double dt_predicted);
  void freeze_material(const AxisymState& s, double dt_predicted) {
    freeze_material(s.eps_bar, dt_predicted);
  }

  // Node frames: global = Q * local for the node's 3 unknowns. A contact node's unknowns are
  // (v_t, v_n, beta) along the tool's tangent t = (n_z, -n_r) and normal n. With
  // numerics.friction_surface = face, v_t is the tangential velocity of the face that touches the
  // tool, v.t + k beta (face_arm), so that sticking and friction act on that face: Q is then not
  // orthogonal, and every transformation uses Q (global = Q local) and Q^T (forces, matrix).
  Eigen::Matrix3d frame(const AxisymState& s, int node) const;
  // k of frame(): the touching face lies at zeta = -/+ h/2 along the element normal m = (-s, c)
  // and moves with v - zeta beta t_e (axisym2.h), so along the tool's tangent its velocity is
  // v.t + k beta with k = (h/2) |m . n| (m: the mean normal of the node's elements). Zero for a
  // free node, at the axis, with friction_surface = mid, and where both faces are pressed (a
  // flange under a blank holder, an ironed wall): there the two faces' friction moments cancel.
  double face_arm(const AxisymState& s, int node) const;
  Eigen::VectorXd to_local(const AxisymState& s, const Eigen::VectorXd& v_global) const;
  Eigen::VectorXd to_global(const AxisymState& s, const Eigen::VectorXd& v_local) const;

  // Prescribed local dofs and their values; free dofs have mask false.
  void prescribed(const AxisymState& s, std::vector<char>* mask, Eigen::VectorXd* values) const;

  // Distributes the blank-holder force over the flange nodes on the die face. With a fixed-gap
  // holder the nodal forces come from the gap pressure instead (set_holder_forces_from_gap) and
  // are only cleared at nodes that left the die face.
  void update_holder(AxisymState* s) const;
  bool fixed_gap_holder() const { return holder_gap_ > 0.0; }
  // Axial load of the holder on a node: a force holder and a gap holder's pressure push a node on
  // the die face up (+z); a gap holder's die-side pressure pushes a node on the holder face down.
  static double holder_load(const NodeContact& c) {
    return c.on_holder_face ? -c.holder_force_N : c.holder_force_N;
  }
  // A node of the flange between the die face and a fixed-gap holder (touching either).
  static bool in_gap(const NodeContact& c) { return c.on_die_face || c.on_holder_face; }
  // A flange node of a fixed-gap holder that touches one face while its thickness fills the gap
  // (within 0.1 %): it touches both faces, so the contact holds whatever the reaction's sign.
  bool sandwiched(const NodeContact& c) const { return fixed_gap_holder() && c.sandwiched; }
  // True if a contact node's tool friction follows its current normal reaction inside the Newton
  // iteration (consistent tangent), false if it uses the lagged NodeContact::normal_force_N.
  bool consistent_friction(const NodeContact& c) const {
    return consistent_friction_ && !sandwiched(c);
  }
  void set_consistent_friction(bool on) { consistent_friction_ = on; }
  // Shortest time over which a squeezed element's thickness overshoot over the clearance is
  // ironed out (add_squeeze): the driver's regular step (its travel grid), so that a short
  // contact-event step does not demand the correction at a rate growing as 1 / dt.
  void set_squeeze_correction_time(double seconds) { squeeze_correction_s_ = seconds; }
  bool consistent_friction() const { return consistent_friction_; }
  // The implicit geometry update's coupling term, or null (none: explicit update). The pointee
  // must outlive the solves it is set for.
  void set_geometry_coupling(const GeometryCoupling* c) { coupling_ = c; }
  void update_sandwiched(AxisymState* s) const;
  // Marks the contact nodes whose other surface reaches a second tool (not a fixed-gap holder,
  // which has its own gap model) and sets their clearance; clears the others.
  void update_squeezed(AxisymState* s) const;
  // Squeeze forces (full 360 degrees) on the squeezed nodes from the element pressures of `sys`.
  std::vector<double> squeeze_forces(const AxisymState& s, const AxisymSystem& sys) const;
  // Fixed-gap holder: nodal holder forces (full 360 degrees) from the element gap pressures of
  // `sys`, each element's pressure times its mid-surface area shared equally by its two nodes.
  std::vector<double> holder_forces_from_gap(const AxisymState& s, const AxisymSystem& sys) const;

  // Evaluates at the local-frame velocity `v_local`.
  // kTangent blends secant and consistent tangent with `tangent_weight` in [0, 1]. The potential is
  // computed with kNone and kTangent (the line search starts from the tangent's point), not with
  // kSecant. Reuse `out` across calls to avoid allocations.
  void evaluate(const AxisymState& s, const Eigen::VectorXd& v_local, StiffnessKind kind,
                AxisymSystem* out, double tangent_weight = 1.0) const;

  // evaluate() in two parts. evaluate_elements() sums the elements (the expensive part; it
  // depends on the velocity only, not on the lagged contact forces); assemble() then adds the
  // holder and friction forces, rotates into the nodal frames and imposes the prescribed dofs, for
  // any kind and tangent weight that the element sums provide (split kTangent sums serve all; a
  // kTangent at a fixed weight serves that weight and kNone).
  // `flow_directions` (kTangent, optional, 2 per element and point): the primal-dual tangent
  // (material/flow_direction.h); empty or null: the consistent tangent. `weight` (kTangent): the
  // fixed tangent weight, or -1 for the split sums (one more matrix product per element).
  void evaluate_elements(const AxisymState& s, const Eigen::VectorXd& v_local, StiffnessKind kind,
                         AxisymSystem* out, const std::vector<double>* flow_directions = nullptr,
                         double weight = -1.0) const;
  void assemble(const AxisymState& s, const Eigen::VectorXd& v_local, StiffnessKind kind,
                AxisymSystem* out, double tangent_weight = 1.0) const;

  // The flow potential at v_local from element sums there (evaluate_elements() with kNone or
  // kTangent): what assemble() puts into AxisymSystem::potential, without residual and matrix
  // (the line search's trial points).
  double potential(const AxisymState& s, const Eigen::VectorXd& v_local,
                   const AxisymSystem& sums) const;

  // In-plane rate increments (2 per element and thickness point) of a local-frame velocity
  // increment.
  void point_rate_increments(const AxisymState& s, const Eigen::VectorXd& dv_local,
                             std::vector<double>* dd) const;

  // Per-node contact force on the sheet (global frame): f_el - f_ext at the node.
  Eigen::Vector2d node_force(const AxisymSystem& sys, int node) const;

  // Current element geometry and node thickness (average of neighbouring elements).
  Axisym2Geometry geometry(const AxisymState& s, int e) const;
  double node_thickness(const AxisymState& s, int node) const;

 private:
  // Fixed-gap holder penalty on flange elements (see the .cc); fills out->gap_pressure.
  void add_gap_holder(const AxisymState& s, const Eigen::VectorXd& v_global, bool want_k,
                      AxisymSystem* out) const;
  // The geometry coupling's force, potential and (want_k) matrix.
  void add_geometry_coupling(const AxisymState& s, const Eigen::VectorXd& v_global, bool want_k,
                             AxisymSystem* out) const;
  // Squeeze (ironing) penalty on elements with a squeezed node; fills out->squeeze_pressure.
  void add_squeeze(const AxisymState& s, const Eigen::VectorXd& v_global, bool want_k,
                   AxisymSystem* out) const;
  // The penalty both use on element e: area rate d_s + d_t >= log_ratio / dt (the thickness at
  // the end of the step h exp(-(d_s + d_t) dt) <= h exp(-log_ratio)); adds its force, potential
  // and (want_k) matrix; returns the pressure [MPa], 0 if inactive.
  double area_rate_penalty(const AxisymState& s, const Eigen::VectorXd& v_global, int e,
                           double log_ratio, bool want_k, AxisymSystem* out) const;
  // Nodal forces (full 360 degrees) of element pressures, each element's pressure times its
  // mid-surface area shared by its nodes for which `pressed` holds.
  std::vector<double> nodal_pressure_forces(
      const AxisymState& s, const std::vector<double>& pressure,
      const std::function<bool(const NodeContact&)>& pressed) const;
  // v <- global-frame velocities of the local-frame v, in place.
  void rotate_to_global(const AxisymState& s, Eigen::VectorXd* v) const;
  // normal_N: the normal reaction that sets the tool's Coulomb limit (the lagged one, or the
  // current one with consistent_friction()).
  void friction_terms(const AxisymState& s, int node, double vt_rel, double normal_N, double* force,
                      double* stiff_secant, double* stiff_tangent, double* potential) const;
  // Friction of a squeezed node's second tool on the node's local tangential velocity
  // `vt_local`; false (nothing to add) unless the node is squeezed with a force and that tool
  // slides (a sticking second tool is taken as frictionless).
  bool squeeze_friction_terms(const AxisymState& s, int node, double vt_local, double* force,
                              double* stiff_secant, double* stiff_tangent, double* potential) const;

  Scene scene_;
  ThicknessRule rule_;
  Hardening hardening_;
  ViscousLaw law_;
  std::vector<RigidTool> tools_;
  std::vector<double> r0_, l0_, volume_;
  double nominal_rate_ = 1.0;        // punch speed / blank radius [1/s]
  double friction_velocity_ = 1e-4;  // arctan regularisation velocity [mm/s]
  // Tool friction from the current normal reaction with its Newton derivative (default), or from
  // the lagged one; the driver switches it off for a solve that does not converge with it.
  bool consistent_friction_ = true;
  int punch_ = -1, die_ = -1, holder_ = -1;  // holder_: fixed-gap holder surface
  double holder_force_ = 0.0, holder_friction_ = 0.0;
  double holder_gap_ = 0.0;  // fixed-gap holder: gap to the die face [mm]; 0 = force holder
  double step_dt_ = 0.0;     // step size the frozen material data were made for [s]
  double squeeze_correction_s_ = 0.0;  // shortest time over which an ironing overshoot is removed
  bool has_holder_ = false;
  const GeometryCoupling* coupling_ = nullptr;
  // Frozen per step.
  std::vector<std::vector<double>> sigma_y_;              // per element, per point
  std::vector<std::vector<double>> hardening_viscosity_;  // per element, per point
  std::vector<double> shear_viscosity_;                   // per element
  std::vector<FacePressure> face_pressure_;               // per element; empty: plane stress
};

}  // namespace vs
