// The 3D viscous-shell forming model (paper section 6): a quarter or full blank of 9-node shells in
// updated coordinates, the analytic axisymmetric tools of forward/contact, the shared viscous
// material, and the evaluation of residual, stiffness and flow potential for a velocity field
// with every node's translational unknowns in its own nodal frame (paper section 6.7).
//
// Unknowns per node (5, numbered by ShellModel): u_local = Q^T u (3 velocities in the nodal frame
// Q = [a1, a2, a3]) and the rates about the director axes V1, V2 (shell9_kinematics.h). The nodal
// frame is cylindrical, because every tool is axisymmetric about z:
//   a1 = e_theta (circumferential), a3 = tool normal n (e_z for a free node), a2 = a3 x ... the
//   meridional tangent n_z e_r - n_r e_z (e_r for a free node);
// at a node on the axis Q = I (e_theta is undefined there; its contact normal is e_z; in the
// quarter model its in-plane velocities are fixed by symmetry). Then
//   - a symmetry plane x = 0 or y = 0 (normal e_theta there) is "u_local 0 = 0" and, with the
//     director frame V1 = e_theta projected on the tangent plane, "rate about V2 = 0";
//   - contact with a tool of velocity w is "u_local 2 = w . n" (one dof; the 3x3 block rotation
//     keeps the sparsity pattern), sticking adds u_local 0, 1 = w . a1, w . a2;
//   - Coulomb friction (regularised like the axisymmetric model: |f| = mu N 2/pi atan(|s|/v0)
//     along the relative slip s in the (a1, a2) plane) uses the normal reaction N lagged by one
//     iteration (FormingStepProblem).
// A force blank holder (update_holder) is a load +z on the flange nodes touching the die's flat
// face, shared by lumped nodal area; it adds to the die's normal reaction and brings its own
// Coulomb friction (friction_limit), as in the axisymmetric model. A fixed-gap holder (gap_mm) is
// a flat face below the die face that holds the flange thickness at the gap: derived in
// gap_holder3.h.
// The thickness is nodal, from exact conservation of each node's lumped volume h0 A0_i = h A_i
// with A_i = integral of N_i over the current mid-surface (the 3D analogue of the axisymmetric
// element volume / area).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "contact/rigid_tool.h"
#include "element/shell9.h"
#include "material/hardening.h"
#include "material/hill_plane_stress.h"
#include "material/viscous_law.h"
#include "model/gap_holder3.h"
#include "model/shell_assembler.h"
#include "model/shell_model.h"
#include "scene/scene.h"

namespace vs::shell3d {

struct NodeContact3 {
  int tool = -1;                // index into tools, -1 = free
  Vec3 normal = Vec3::UnitZ();  // from the tool into the sheet
  double normal_force_N = 0.0;  // lagged normal reaction of this node (meshed part)
  bool on_die_face = false;     // touching the flat face of the die (the flange)
  // Force holder: this node's share pressing it up (meshed part). Fixed-gap holder: the holder
  // pressure's nodal force of the last converged state, exerted by the face the node does not
  // touch.
  double holder_force_N = 0.0;
  // Fixed-gap holder: in the gap with its thickness filling it (update_holder; gap_holder3.h).
  bool sandwiched = false;
  // Ironing (update_squeezed): the second tool whose surface the node's other face reaches
  // (-1: none), the clearance between the two tools through the node [mm], and the squeeze
  // pressure's nodal force of the last converged state [N] (meshed part), exerted by that tool.
  int squeeze_tool = -1;
  double clearance_mm = 0.0;
  double squeeze_force_N = 0.0;
};

// Everything that changes from step to step.
struct FormingState {
  double time_s = 0.0;
  std::vector<Vec3> x;                       // mid-surface nodes [mm]
  std::vector<Vec3> director;                // unit directors V3
  std::vector<double> thickness;             // per node [mm]
  std::vector<double> eps_bar;               // per element and flow point
  std::vector<Eigen::Vector2d> tool_offset;  // per tool, (r, z) rigid displacement [mm]
  std::vector<NodeContact3> contact;         // per node
  std::vector<Vec3> velocity;                // last converged nodal velocity (global) [mm/s]
  std::vector<Vec3> omega;                   // last converged director angular velocity [1/s]
};

// The implicit geometry update's coupling (stepping/step_driver.h; as vs::GeometryCoupling of
// the axisymmetric model): K_g (scale) (v - v_ref) with K_g the membrane initial-stress
// stiffness (shell9_stress_stiffness) of the previous iterate's membrane forces. They are tensors
// in global axes, projected onto the tangent planes of the configuration being solved: local
// components of the previous configuration would be read in frames that turn with the elements'
// r-lines, which breaks the mirror symmetry of a symmetric blank (issue 14).
struct GeometryCoupling3 {
  double scale_s = 0.0;                     // d x / d v = theta dt [s]
  std::vector<std::vector<Mat3>> membrane;  // per element and in-plane point, global [N/mm]
  std::vector<Vec3> v_ref;                  // per node, global [mm/s]
};

// One evaluation in the nodal frames; the matrix lives in the model's assembler.
struct FormingSystem {
  Eigen::VectorXd residual;        // local frames; zero at prescribed dofs
  Eigen::VectorXd internal_force;  // element forces, local frames
  Eigen::VectorXd external_force;  // blank-holder loads, local frames
  double potential = 0.0;          // flow potential incl. friction (line-search merit)
};

class FormingModel {
 public:
  explicit FormingModel(const Scene& scene);
  FormingModel(const FormingModel&) = delete;
  FormingModel& operator=(const FormingModel&) = delete;

  const Scene& scene() const { return scene_; }
  const ShellMesh& mesh() const { return mesh_; }
  const ShellModel& shell_model() const { return *model_; }
  int num_nodes() const { return mesh_.num_nodes(); }
  int num_elements() const { return mesh_.num_elements(); }
  int num_dofs() const { return model_->num_dofs(); }
  int flow_points() const { return flow_points_; }  // per element
  // The material of the flow points (output: a point's effective stress is
  // law().effective_stress(hardening().flow_stress(eps_bar), rate)).
  const Hardening& hardening() const { return hardening_; }
  const ViscousLaw& law() const { return law_; }
  // Planar anisotropy of the scene ([material.anisotropy]), or null (normal anisotropy).
  const PlanarAnisotropy* planar() const { return planar_.get(); }
  // The point law of element e's flow points in the current step (frozen shear viscosity).
  Shell9Material material(int e) const;
  int thickness_points() const { return static_cast<int>(thick_.zeta.size()); }
  const std::vector<RigidTool>& tools() const { return tools_; }
  int punch_index() const { return punch_; }
  double nominal_rate() const { return nominal_rate_; }
  // 4 for the quarter model, 1 for the full blank: nodal reactions and forces are scaled by it
  // for the whole blank.
  double symmetry_factor() const {
    return scene_.blank.symmetry == BlankSymmetry::kQuarter ? 4.0 : 1.0;
  }
  const Vec3& initial_position(int node) const { return mesh_.nodes[node]; }
  double initial_thickness() const { return scene_.blank.thickness_mm; }
  bool on_axis(int node) const { return axis_[node] != 0; }
  // Force blank holder (tool kind blank_holder with force_N): whole-blank force and friction.
  bool has_holder() const { return holder_force_ > 0.0; }
  int die_index() const { return die_; }
  // Fixed-gap blank holder (gap_mm; gap_holder3.h): its gap and tool index (-1: none).
  bool fixed_gap_holder() const { return holder_gap_ > 0.0; }
  double holder_gap_mm() const { return holder_gap_; }
  int holder_index() const { return holder_; }
  // A flange node between the die face and a fixed-gap holder (touching either).
  bool in_gap(const NodeContact3& c) const {
    return fixed_gap_holder() && (c.on_die_face || (c.tool >= 0 && c.tool == holder_));
  }
  // A node on the fixed-gap holder's face drawn past its inner edge (it leaves the face: the
  // closest point would be the edge itself, and re-attaching there would pin the node).
  bool past_holder_edge(const FormingState& s, int node) const;
  // Fixed-gap holder: the nodal holder forces of local velocities x (after prepare(s)) into the
  // nodes in the gap of s (NodeContact3::holder_force_N), for the next solve.
  void update_gap_holder_forces(const Eigen::VectorXd& x, FormingState* s) const;
  // Spreads the holder force over the flange nodes on the die face (on_die_face), each node's
  // share proportional to its lumped area integral N_i dA in state s (as
  // AxisymModel::update_holder with its nodal ring areas): the consistent nodal loads of a
  // uniform holder pressure on those nodes' areas. Zeroes the shares of every other node.
  // Fixed-gap holder: keeps the nodal forces of the nodes in the gap (update_gap_holder_forces),
  // zeroes the others, and marks the sandwiched nodes.
  void update_holder(FormingState* s) const;
  // Ironing between two tools (as AxisymModel::update_squeezed / add_squeeze): a node touching
  // tool A (not a blank holder, not sandwiched in a fixed gap) is squeezed when its other face
  // comes within 1 % of its thickness of a second tool B (not a blank holder); the clearance
  // through it is h + its gap to B. The squeezed nodes' thickness is held at the clearance by
  // the penalty of gap_holder3.h in its ironing form (an overshoot is ironed out over steps), B
  // presses the other face with the squeeze pressure's nodal force (lagged one converged state,
  // update_squeeze_forces) and adds its Coulomb friction on that force, relative to B's motion.
  // Resets squeeze_force_N where the squeezing tool changed.
  void update_squeezed(FormingState* s) const;
  // The nodal squeeze forces of local velocities x (after prepare(s)) into the squeezed nodes of
  // s, for the next solve.
  void update_squeeze_forces(const Eigen::VectorXd& x, FormingState* s) const;
  // The time over which an overshoot of the clearance is ironed out: a regular (grid) step's, so
  // that a node squeezed at a short contact-event step is not ironed at a multiple of the flow
  // rate (the axisymmetric model's measured failure; set by the driver).
  void set_squeeze_correction_time(double seconds) { squeeze_correction_s_ = seconds; }
  // The punch's share of the friction on the second face of the squeezed nodes in the last
  // evaluate(), z component, whole blank [N]: the reaction of a node on the punch includes the
  // other tool's friction (to be removed), and a node pressed by the punch on its other face
  // carries the punch's friction (to be added). FormingStepProblem::finish adds it.
  double squeeze_punch_friction_z() const;
  // Nodes whose boundary condition (blank.edge) forbids contact (pinned / clamped edge).
  bool contact_eligible(int node) const { return eligible_[node] != 0; }
  // Mesh neighbours (nodes sharing an element), sorted.
  const std::vector<int>& neighbours(int node) const { return neighbours_[node]; }

  FormingState initial_state() const;
  // Places the tools at the state's offsets; with numerics.normal_stress = contact it also
  // freezes the nodal face pressures (freeze_face_pressures) for the solves that follow (the
  // driver calls it at the start of every solve, never inside one).
  void place_tools(const FormingState& s);
  // Through-thickness normal stress (material/normal_stress.h), as
  // AxisymModel::freeze_face_pressures: a contact node's pressure is its lagged normal reaction
  // (NodeContact3::normal_force_N; at the start of a solve the last converged state's) over its
  // lumped area integral N_i dA (the consistent nodal area of a uniform pressure), on the lower
  // face (t = -1) if the tool's normal into the sheet points along the node's director, else on
  // the upper face; a force holder's share (holder_force_N) and a squeezing tool's force
  // (squeeze_force_N) press the other face. The element
  // interpolates the nodal pressures to its in-plane points with its shape functions.
  void freeze_face_pressures(const FormingState& s);
  // Nodal face pressures (empty: plane stress).
  const std::vector<FacePressure>& face_pressures() const { return face_pressure_; }

  // Per-step material data (as AxisymModel::freeze_material): yield stress and hardening
  // viscosity theta H dt per flow point, shear penalty viscosity per element.
  // eps_bar: per element and flow point, as FormingState::eps_bar (the state's own, or the
  // start-of-step values for the Heun predictor's solve with backward-Euler hardening).
  void freeze_material(const std::vector<double>& eps_bar, double dt_predicted);
  void freeze_material(const FormingState& s, double dt_predicted) {
    freeze_material(s.eps_bar, dt_predicted);
  }
  // The weight theta of the hardening viscosity theta H dt: 1/2 midpoint (the default), 1
  // backward Euler (smoother in the parameters; see freeze_material in forming_model.cc).
  void set_hardening_theta(double theta) { hardening_theta_ = theta; }
  double hardening_theta() const { return hardening_theta_; }
  // Nodal frames, director frames, prescribed values and the element operators
  // (shell9_operators) of state s; call before evaluate(), potential() and point_rates(), which
  // then evaluate state s (their s argument must be the prepared state).
  void prepare(const FormingState& s);

  // Translational frame Q of a node (global = Q local) and its director axes V1, V2.
  const Mat3& frame(int node) const { return frame_[node]; }
  // friction_surface = face (issue 15; docs/contact_face.md): at a node touching one tool the
  // first two translational unknowns are the tangential velocity components of the face that
  // touches it, u_face = u + C r (u: the mid-surface velocity in the nodal frame, r: the rates
  // about V1, V2), so that sticking holds that face and Coulomb friction acts on its slip, with
  // the friction's moment about the mid-surface (the work f . u_face). C is zero for a free node,
  // at the axis, with friction_surface = mid and where both faces are pressed (holder, ironing).
  using FaceCoupling = Eigen::Matrix<double, 3, 2>;
  const FaceCoupling& face_coupling(int node) const {
    return face_[static_cast<std::size_t>(node)];
  }
  // The node's mid-surface velocity in its nodal frame from its 5 local unknowns q.
  Vec3 mid_velocity(int node, const Eigen::Matrix<double, 5, 1>& q) const {
    return q.head<3>() - face_[static_cast<std::size_t>(node)] * q.tail<2>();
  }
  const Vec3& v1(int node) const { return v1_[node]; }
  const Vec3& v2(int node) const { return v2_[node]; }
  const std::vector<char>& prescribed_mask() const { return mask_; }
  const std::vector<double>& prescribed_value() const { return value_; }

  // Local-frame vector <-> nodal global velocities and angular velocities.
  Eigen::VectorXd to_local(const std::vector<Vec3>& velocity, const std::vector<Vec3>& omega) const;
  void to_global(const Eigen::VectorXd& x, std::vector<Vec3>* velocity,
                 std::vector<Vec3>* omega) const;

  // Residual, potential and (kind != kNone) matrix at local velocities x. kTangent blends secant
  // and tangent with theta; its rank-one part uses the primal-dual flow directions (shell9.h,
  // Shell9FlowDirection) from the previous kTangent evaluations (dual_prepare(): linearised about
  // the last one, or its damped step; after prepare() about the last one of the previous solve;
  // none: the first tangent of the model's life is the secant matrix, so Newton solves start
  // without direct iterations). Only the matrix depends on that history, never the residual or
  // the potential.
  // The matrix has prescribed rows and columns decoupled (diagonal kept).
  void evaluate(const FormingState& s, const Eigen::VectorXd& x, Shell9Stiffness kind, double theta,
                FormingSystem* out);
  // false: kTangent is the consistent tangent, the derivative of the residual at x (rank-one part
  // along the current flow direction; what the tests compare with finite differences); true (the
  // default): the primal-dual tangent above.
  void set_primal_dual(bool on) { primal_dual_ = on; }
  double potential(const FormingState& s, const Eigen::VectorXd& x);
  // After the lagged normal forces in s changed (FormingStepProblem::update_lagged): replaces the
  // Coulomb friction terms of the last evaluate(), which must have been at this x with this s,
  // in its residual, potential and matrix. The element terms do not depend on the normal forces,
  // so this equals a new evaluate() at a fraction of its cost (nodal terms only), up to round-off.
  void refresh_friction(const FormingState& s, const Eigen::VectorXd& x, FormingSystem* out);
  const SparseMatrix& matrix() const { return assembler_->matrix(); }

  // Effective rate at every flow point (per element) at local velocities x, and (if asked) the
  // membrane force tensor in global axes (3x3, N/mm) at every in-plane point.
  void point_rates(const FormingState& s, const Eigen::VectorXd& x,
                   std::vector<std::vector<double>>* rates,
                   std::vector<std::vector<Mat3>>* membrane = nullptr) const;

  // The implicit geometry update's coupling term from the next prepare() on, or null (none).
  // The pointee must outlive the solves it is set for.
  void set_geometry_coupling(const GeometryCoupling3* c) { coupling_ = c; }

  // Element geometry of state s (directors, nodal thickness, director frames and nodal velocity
  // frames of prepare()).
  Shell9Geometry geometry(const FormingState& s, int e) const;
  // Lumped nodal mid-surface areas integral N_i dA of configuration x.
  std::vector<double> lumped_areas(const std::vector<Vec3>& x) const;
  // Nodal area stretch dA/dA0 of configuration x: at the node's own natural coordinates in every
  // element that contains it (the mesh is material, so that is the same particle), averaged over
  // those elements. Exact incompressibility of the interpolated mid-surface then gives the nodal
  // thickness h = h0 / stretch. (The volume-lumped alternative h0 A0_i / A_i weights the
  // point values by N_i, which is negative over parts of a 9-node element: measured on ex4a it
  // makes the corner node on the axis thicken by 0.6 % where it should thin.)
  std::vector<double> area_stretch(const std::vector<Vec3>& x) const;

  // 3D closest point data of a node w.r.t. tool t: signed gap (minus h/2), normal, and the
  // point on the mid-surface offset by h/2 from the tool surface.
  struct ToolProjection {
    double gap = 0.0;
    Vec3 normal = Vec3::UnitZ();
    Vec3 surface_point = Vec3::Zero();  // mid-surface position touching the tool
    bool on_die_face = false;           // closest point on the die's flat face
  };
  ToolProjection project(int tool, const Vec3& x, double h, bool axis_node) const;

 private:
  void element_kernel(const FormingState& s, int e, const Eigen::VectorXd& qe, Shell9Stiffness kind,
                      double theta, ElementContribution* c);
  // The geometry coupling's force, potential and (want_matrix) matrix on element e.
  void add_coupling(int e, const Eigen::VectorXd& qe, bool want_matrix,
                    ElementContribution* c) const;
  // Adds the Coulomb friction terms at x to out (residual, potential, matrix if want_matrix) and
  // records them in friction_; with `replace`, first removes the recorded ones.
  void friction(const FormingState& s, const Eigen::VectorXd& x, bool want_matrix, double theta,
                Shell9Stiffness kind, bool replace, FormingSystem* out);
  // Prescribed value v of local dof k of a node (prepare()).
  void prescribe(int node, int k, double v);
  // C of a node of state s (face_coupling(); prepare(), after its frames).
  FaceCoupling face_coupling(const FormingState& s, int node) const;
  // Prescribes the dofs of node i that remove the rigid-body modes: the symmetry planes of the
  // quarter model, or for a full blank with a free edge the in-plane translation and rotation
  // about z.
  void fix_rigid_modes(int i);
  // The node whose circumferential velocity fixes the rotation about z of a free full blank: the
  // outermost node of `line` (on y = 0, where that velocity vanishes by mirror symmetry).
  int spin_reference(const std::vector<int>& line) const;
  double friction_limit(const NodeContact3& c) const;
  void holder_loads(const FormingState& s, const Eigen::VectorXd& x, FormingSystem* out) const;
  void read_holder(const Scene& scene);

  Scene scene_;
  ShellMesh mesh_;
  std::unique_ptr<ShellModel> model_;
  std::unique_ptr<ShellAssembler> assembler_;
  ThicknessRule thick_;
  Shell9Rule rule_ = Shell9Rule::kMitc9;
  int flow_points_ = 0;
  Hardening hardening_;
  ViscousLaw law_;
  HillPlaneStressLaw hill_;
  std::unique_ptr<PlanarAnisotropy> planar_;  // null: normal anisotropy (hill_)
  // Yld2000-2d: warm starts of the local dual solves, per element and flow point (Shell9State::
  // flow_guess); written by every evaluation, each element its own slice.
  mutable std::vector<PlaneVector> flow_guess_;
  std::vector<RigidTool> tools_;
  int punch_ = -1, die_ = -1;
  double holder_force_ = 0.0, holder_friction_ = 0.0;  // whole blank [N], Coulomb coefficient
  int holder_ = -1;          // fixed-gap holder's tool (a face gap_mm below the die face)
  double holder_gap_ = 0.0;  // [mm]; 0: no fixed-gap holder
  double step_dt_ = 0.0;     // step the frozen material data are for [s] (freeze_material)
  GapHolder3 gap_;           // the fixed-gap holder's constraints of the prepared state
  GapHolder3 squeeze_;       // the ironing constraints of the prepared state
  double squeeze_correction_s_ = 0.0;
  double nominal_rate_ = 1.0;
  double friction_velocity_ = 1e-4;
  double hardening_theta_ = 0.5;
  std::vector<char> axis_, sym_, eligible_;
  int spin_node_ = -1;  // full blank, free edge: see fix_rigid_modes()
  std::vector<std::vector<int>> neighbours_;
  // Frozen per step.
  std::vector<double> sigma_y_, hardening_viscosity_;  // per element * flow point
  std::vector<double> shear_viscosity_;                // per element
  std::vector<FacePressure> face_pressure_;            // per node; empty: plane stress
  // Face pressures at the in-plane points of element e from the nodal ones; null if none of its
  // nodes is pressed. The buffer is per thread.
  const FacePressure* element_face_pressure(int e) const;
  // Element e's frozen point data (yield stresses, hardening viscosities, face pressures, flow
  // guesses) for shell9_evaluate.
  Shell9State element_state(int e) const;
  // The operators of element e + 1 (null for the last): shell9_evaluate's `next`. The
  // assembler's threads take elements in runs of consecutive numbers, so it is usually the
  // thread's next.
  const Shell9Operators* next_operators(int e) const {
    const std::size_t n = static_cast<std::size_t>(e) + 1;
    return n < operators_.size() ? &operators_[n] : nullptr;
  }
  // The friction terms of the last evaluate() (refresh_friction), per node in contact.
  struct FrictionTerm {
    int dof = 0;  // first tangential dof
    int node = 0;
    int contact_tool = -1;     // the node's contact tool
    int other_face_tool = -1;  // a squeezed node's second face: that tool (-1: its contact tool)
    Eigen::Vector2d force = Eigen::Vector2d::Zero();
    Eigen::Matrix2d stiffness = Eigen::Matrix2d::Zero();
    double potential = 0.0;
  };
  struct FrictionRecord {
    std::vector<FrictionTerm> terms;
    bool matrix = false;  // the evaluation's arguments, for the refresh
    double theta = 0.0;
    Shell9Stiffness kind = Shell9Stiffness::kNone;
  };
  FrictionRecord friction_;
  const GeometryCoupling3* coupling_ = nullptr;
  // Per prepare().
  std::vector<Shell9Operators> operators_;               // per element
  std::vector<Eigen::Matrix<double, 9, 9>> coupling_k_;  // per element, scale K_g (with coupling_)
  std::vector<Mat3> frame_;
  std::vector<Vec3> v1_, v2_;
  std::vector<FaceCoupling> face_;
  std::vector<char> mask_;
  std::vector<double> value_;
  // Primal-dual tangent (shell9.h, Shell9FlowDirection): the records (per element and flow
  // point) and velocities of the last two tangent evaluations since prepare(), and the buffers
  // the current one writes / reads (dual_given_: a damped dual step).
  struct DualRecord {
    std::vector<Shell9FlowDirection> points;
    Eigen::VectorXd x;
  };
  void dual_prepare(const Eigen::VectorXd& x);
  void dual_finish(const Eigen::VectorXd& x);
  enum class DualMode { kNone, kAnchor, kGiven };
  DualRecord dual_[3];  // [0] the last, [1] the one before, [2] the one being written
  int dual_count_ = 0;  // valid records in dual_[0..1]
  DualMode dual_mode_ = DualMode::kNone;
  bool dual_same_point_ = false;  // the current evaluation repeats the last one's x
  bool primal_dual_ = true;
  std::vector<Vec3> dual_given_;
};

}  // namespace vs::shell3d
