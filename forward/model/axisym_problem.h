// Adapter that presents one step of the axisymmetric model to the generic nonlinear solver, and
// extracts what the driver needs from the converged state (reactions, punch force, point rates).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "linalg/block_tridiag_solver.h"
#include "material/flow_direction.h"
#include "model/axisym_model.h"
#include "solver/newton.h"

namespace vs {

class AxisymStepProblem : public NewtonProblem {
 public:
  AxisymStepProblem(const AxisymModel& model, AxisymState* state);

  LinearSolver& linear_solver() override { return linear_; }
  double evaluate(const Eigen::VectorXd& x, double theta, Eigen::VectorXd* residual,
                  double* potential) override;
  void set_direction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) override;
  double potential(const Eigen::VectorXd& x_trial, double alpha) override;
  void step_taken(double alpha) override;
  bool update_lagged(const Eigen::VectorXd& x) override;
  bool self_starting() const override { return true; }

  // Start vector: previous velocity in the current frames, prescribed values imposed.
  Eigen::VectorXd start(const Eigen::VectorXd& v_global) const;
  // Start the flow directions at those of an earlier converged solve (warm start) instead of
  // zero; ignored if the sizes differ (an empty vector keeps the zero start).
  void warm_start(const std::vector<double>& directions);
  // The flow directions of the current iterate (after the solve: the converged ones).
  const std::vector<double>& directions() const { return dual_; }
  // Final evaluation at the converged local velocity: fills reactions and forces.
  void finish(const Eigen::VectorXd& x);

  double punch_force() const { return punch_force_; }
  // Axial force of the punch on each node at the last finish() (their sum is punch_force()).
  const std::vector<double>& punch_node_forces() const { return punch_node_forces_; }
  // Fixed-gap holder: nodal holder forces from the gap pressure at the last finish() (empty
  // otherwise).
  const std::vector<double>& holder_forces() const { return holder_forces_; }
  // Squeeze forces of the squeezed nodes at the last finish() (AxisymModel::squeeze_forces).
  const std::vector<double>& squeeze_forces() const { return squeeze_forces_; }
  // Normal reaction of each contact node (compressive > 0) at the last finish().
  const std::vector<double>& normal_reactions() const { return normal_; }
  const std::vector<std::vector<double>>& point_rates() const { return point_rates_; }
  double max_point_rate() const { return max_rate_; }
  // Stress resultants (N_s, N_t, M_s, M_t, Q) per element at the last finish().
  const std::vector<Vec5>& resultants() const { return resultants_; }

 private:
  void reactions(const AxisymSystem& sys, std::vector<double>* normal) const;

  const AxisymModel& model_;
  AxisymState* state_;
  BlockTridiagSolver linear_;  // the matrix of the last evaluate() and its factorisation
  // Element sums for the last two velocities evaluated (the iterate and the line search's trial
  // point): an accepted trial point is not summed again by the next evaluate(), and the secant
  // fallback at a rejected Newton step reuses the iterate's sums.
  struct Slot {
    Eigen::VectorXd x;
    AxisymSystem sys;
    bool valid = false;
    long directions_id = -1;  // which flow directions its tangent used (ids below)
  };
  // The slot holding element sums at x that serve `kind` (kTangent: with the flow directions n
  // and tangent weight theta), computed if neither slot does (into the slot the last evaluate()
  // did not use): for weight 1, the weight that self-starting solves keep, at that weight (one
  // matrix product per element); otherwise split (two).
  AxisymSystem& elements_at(const Eigen::VectorXd& x, StiffnessKind kind,
                            const std::vector<double>& n, long n_id, double theta);
  Slot slots_[2];
  int last_ = 0;             // slot of the last evaluate(): its reactions feed update_lagged()
  double last_theta_ = 1.0;  // tangent weight of the last evaluate()
  // Primal-dual Newton (material/flow_direction.h): the flow directions n of the iterate, 2 per
  // element and thickness point (zero at the start of a solve, so that its first matrix is the
  // direct iteration's), and after set_direction() their full-step increment dn; the step alpha
  // moves them to n + alpha dn, projected onto the ball (trial_dual_). Every set of directions
  // gets a new id, which identifies it in the slots without comparing the vectors.
  void trial_directions(double alpha);
  FlowDirectionBall ball_;
  std::vector<double> dual_, dual_step_, trial_dual_, rate_step_;
  long dual_id_ = 0, trial_dual_id_ = -1, next_id_ = 1;
  bool has_dual_step_ = false;
  double trial_alpha_ = -1.0;  // step of trial_dual_ (the last potential() call), -1: none
  double punch_force_ = 0.0;
  double max_rate_ = 0.0;
  std::vector<double> normal_;
  std::vector<std::vector<double>> point_rates_;
  std::vector<Vec5> resultants_;
  // Adaptive relaxation of the lagged normal forces, per node.
  std::vector<double> relax_, last_change_;
  std::vector<double> holder_forces_;
  std::vector<double> squeeze_forces_;
  std::vector<double> punch_node_forces_;
};

}  // namespace vs
