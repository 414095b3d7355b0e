// Bounded Levenberg-Marquardt (Ceres trust region) on the calibration objective. The optimiser
// sees the free parameters divided by their scales, so that its damping, step and parameter
// tolerance mean the same thing for every parameter. Residuals and the finite-difference
// Jacobian come from one custom ceres::CostFunction whose Evaluate runs the forward model through
// the memoising cache; a failed forward run returns false, and Ceres shrinks its step.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

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

  bool IsValid(std::string* why) const;
};

struct LeastSquaresSummary {
  Eigen::VectorXd x;  // free parameters at the end, in their own units
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int iterations = 0;
  bool converged = false;   // Ceres CONVERGENCE
  bool usable = false;      // x is a valid evaluated point (CONVERGENCE or NO_CONVERGENCE)
  std::string termination;  // CONVERGENCE, NO_CONVERGENCE, FAILURE, ...
  std::string message;      // Ceres' reason
};

LeastSquaresSummary solve_least_squares(Objective& objective, const Eigen::VectorXd& x0,
                                        const LeastSquaresOptions& options);

}  // namespace vs
