// Bounded Levenberg-Marquardt (Ceres trust region) on the calibration objective. The optimiser
// sees the free parameters divided by their scales, so that its damping, step and parameter
// tolerance mean the same thing for every parameter. Residuals and the finite-difference
// Jacobian come from one custom ceres::CostFunction whose Evaluate runs the forward model through
// the memoising cache; a failed forward run returns false, and Ceres shrinks its step.
//
// Two additions to plain Ceres (issues 14 and 15):
//
// * Stop at the forward solver's noise floor. Each forward output carries a convergence error
//   delta_i (the caller states it per residual, already weighted: residual_noise), so a cost
//   C = |r|^2 / 2 is only known to within F = |r| |delta| + |delta|^2 / 2 (first-order change of
//   C under r -> r + delta, Cauchy-Schwarz). At every accepted point the linearised model
//   offers at best D = |Q^T r|^2 / 2 (Q: orthonormal basis of the range of the Jacobian columns
//   that may move, i.e. the Gauss-Newton decrease, whatever the trust region). When D <= F no
//   further decrease can be told apart from the solver's own noise: the fit stops there
//   ("stopped at the noise floor") instead of spending runs on rejected steps.
//
// * Active-set bounds. Ceres projects its trust-region step onto the bounds; a parameter whose
//   optimum lies beyond a bound then creeps along it (issue 15: 50 iterations, 327 forward runs
//   with friction at 0). Here a parameter that reaches a bound with the cost gradient pushing it
//   outward is held on the bound (a SubsetManifold; its Jacobian column is no longer
//   differentiated) and Ceres restarts from that point. At the end a held parameter whose
//   gradient now points inward, by more than the noise floor, is released and the fit resumes.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "objective.h"

namespace vs {

struct LeastSquaresOptions {
  int max_iterations = 50;
  // Ceres' three convergence tests (relative cost decrease, max gradient, relative step in
  // scaled parameters).
  double function_tolerance = 1e-10;
  double gradient_tolerance = 1e-12;
  double parameter_tolerance = 1e-10;
  // Consecutive steps whose evaluation failed before giving up (Ceres' own default is 5).
  int max_consecutive_invalid_steps = 10;
  // One line per iteration (iteration, cost, |step|, forward runs so far, elapsed). May be empty.
  std::function<void(const std::string&)> progress;
  // Per residual, the forward solver's resolution of that residual (weighted, like the
  // residual). Empty: no noise-floor stop.
  Eigen::VectorXd residual_noise;
  // Hold parameters on a bound they are pushed against (see the file comment).
  bool active_set = true;

  bool IsValid(std::string* why) const;
};

struct LeastSquaresSummary {
  Eigen::VectorXd x;  // free parameters at the end, in their own units
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int iterations = 0;
  bool converged = false;           // Ceres CONVERGENCE
  bool usable = false;              // x is a valid evaluated point (CONVERGENCE or NO_CONVERGENCE)
  std::string termination;          // CONVERGENCE, NO_CONVERGENCE, FAILURE, ...
  std::string message;              // Ceres' reason, or the noise-floor statement
  bool noise_floor = false;         // stopped because no decrease above the noise floor is left
  double noise_floor_cost = 0.0;    // F at the last accepted point (0 without residual_noise)
  double predicted_decrease = 0.0;  // D at the last accepted point
  int passes = 1;                   // Ceres solves (active-set restarts + 1)
  // Per free parameter: -1 held on its lower bound, +1 on its upper bound, 0 free, at the end.
  std::vector<int> held;
};

// F and D of the file comment for residuals r, Jacobian columns `jacobian` (columns with
// `held` true left out) and per-residual noise `noise` (empty: F = 0).
double noise_floor_cost(const Eigen::VectorXd& r, const Eigen::VectorXd& noise);
double predicted_decrease(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r,
                          const std::vector<bool>& held);

LeastSquaresSummary solve_least_squares(Objective& objective, const Eigen::VectorXd& x0,
                                        const LeastSquaresOptions& options);

}  // namespace vs
