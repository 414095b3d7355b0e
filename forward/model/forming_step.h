// One forming step as a NewtonProblem: the model evaluated at a fixed state, the lagged
// normal forces of Coulomb friction (relaxed per node like the axisymmetric AxisymStepProblem:
// the factor halves when a node's change reverses sign and grows back while it keeps its sign),
// and what the driver needs from a converged velocity field (reactions, punch force, rates).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "linalg/sparse_cholesky_solver.h"
#include "model/forming_model.h"
#include "solver/newton.h"

namespace vs::shell3d {

class FormingStepProblem : public NewtonProblem {
 public:
  // model.prepare(*state) must have been called for this state. `linear` factorises the
  // model's matrix; it outlives the problem, so that the next solve can start with chord steps
  // on its factorisation.
  FormingStepProblem(FormingModel& model, FormingState* state, SparseCholeskySolver* linear)
      : model_(model), state_(state), linear_(linear) {
    linear_->set_matrix(&model_.matrix());
  }

  LinearSolver& linear_solver() override { return *linear_; }
  // Primal-dual tangent (forming_model.h): the first tangent of a run is the direct iteration's
  // matrix, later ones move to Newton's by themselves (and a solve's first one is linearised
  // about the previous solve). Measured on ex4a (n = 4, sticking, 4 mm): 78 instead of 121
  // iterations, every step a full one.
  bool self_starting() const override { return true; }
  double evaluate(const Eigen::VectorXd& x, double theta, Eigen::VectorXd* residual,
                  double* potential) override;
  double evaluate_residual(const Eigen::VectorXd& x, Eigen::VectorXd* residual,
                           double* potential) override;
  double potential(const Eigen::VectorXd& x, double /*alpha*/) override {
    return model_.potential(*state_, x);
  }
  bool update_lagged(const Eigen::VectorXd& x) override;
  // The normal forces enter only the nodal friction terms (FormingModel::refresh_friction).
  bool refresh(const Eigen::VectorXd& x, Eigen::VectorXd* residual, double* potential) override;
  // Start vector: the state's last velocities in the current frames, prescribed values imposed.
  Eigen::VectorXd start() const;
  // Final evaluation at the converged x: reactions, punch force and flow-point rates.
  void finish(const Eigen::VectorXd& x);

  // Whole-blank punch force (+z on the sheet) [N] at the last finish().
  double punch_force() const { return punch_force_; }
  // Normal reaction of every node (compressive > 0, meshed part) at the last finish().
  const std::vector<double>& normal_reactions() const { return normal_; }
  // |reaction vector| of every contact node (0 elsewhere) at the last finish().
  const std::vector<double>& reaction_magnitudes() const { return magnitude_; }
  const std::vector<std::vector<double>>& point_rates() const { return rates_; }
  // Membrane force tensors in global axes per element and in-plane point at the last finish()
  // [N/mm].
  const std::vector<std::vector<Mat3>>& membrane_forces() const { return membrane_; }
  double max_point_rate() const { return max_rate_; }

 private:
  void reactions(const Eigen::VectorXd& reaction, std::vector<double>* normal,
                 std::vector<double>* magnitude = nullptr) const;

  FormingModel& model_;
  FormingState* state_;
  SparseCholeskySolver* linear_;
  FormingSystem sys_;
  double punch_force_ = 0.0, max_rate_ = 0.0;
  std::vector<double> normal_, magnitude_;
  std::vector<std::vector<double>> rates_;
  std::vector<std::vector<Mat3>> membrane_;
  std::vector<double> relax_, last_change_;
};

}  // namespace vs::shell3d
