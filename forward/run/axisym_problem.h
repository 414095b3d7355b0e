// Adapter that presents one step of the axisymmetric model to the generic nonlinear solver, and
// extracts what the driver needs from the converged state (reactions, punch force, point rates).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/axisym_model.h"
#include "solver/nonlinear_solver.h"

namespace vs {

class AxisymStepProblem : public NonlinearProblem {
 public:
  AxisymStepProblem(const AxisymModel& model, AxisymState* state) : model_(model), state_(state) {}

  double evaluate(const Eigen::VectorXd& x, double theta, BlockTridiag* K,
                  Eigen::VectorXd* residual) override;
  double potential(const Eigen::VectorXd& x) override { return model_.potential(*state_, x); }
  void update_lagged(const Eigen::VectorXd& x) override;

  // Start vector: previous velocity in the current frames, prescribed values imposed.
  Eigen::VectorXd start(const Eigen::VectorXd& v_global) const;
  // Final evaluation at the converged local velocity: fills reactions and forces.
  void finish(const Eigen::VectorXd& x);

  double punch_force() const { return punch_force_; }
  // Fixed-gap holder: nodal holder forces from the gap pressure at the last finish() (empty
  // otherwise).
  const std::vector<double>& holder_forces() const { return holder_forces_; }
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
  AxisymSystem sys_;
  double punch_force_ = 0.0;
  double max_rate_ = 0.0;
  std::vector<double> normal_;
  std::vector<std::vector<double>> point_rates_;
  std::vector<Vec5> resultants_;
  // Adaptive relaxation of the lagged normal forces, per node.
  std::vector<double> relax_, last_change_;
  std::vector<double> holder_forces_;
};

}  // namespace vs
