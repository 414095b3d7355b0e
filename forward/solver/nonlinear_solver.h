// Nonlinear solve of one step: find the velocity field that makes the residual vanish at the free
// unknowns. The paper's direct iteration (section 3, steps 2-5) is the Kacanov/secant method: it
// decreases the convex flow potential monotonically and its matrix is always SPD, so it starts
// every solve; Newton with the consistent tangent and an Armijo line search on the same potential
// then converges fast to tight tolerances (numerics.md section 3.3). The solver knows nothing of
// shells: it sees a NonlinearProblem.
#pragma once

#include <Eigen/Core>
#include <string>

#include "element/axisym2.h"
#include "scene/scene.h"
#include "solver/block_tridiag.h"

namespace vs {

class NonlinearProblem {
 public:
  virtual ~NonlinearProblem() = default;
  // Residual at free unknowns (zero at prescribed ones), and the matrix secant + theta (tangent -
  // secant) with prescribed unknowns replaced by identity rows (theta = 0: the paper's direct
  // iteration; theta = 1: Newton). Returns the residual scale (norm of the internal forces).
  virtual double evaluate(const Eigen::VectorXd& x, double theta, BlockTridiag* K,
                          Eigen::VectorXd* residual) = 0;
  virtual double potential(const Eigen::VectorXd& x) = 0;
  // Called after each accepted iterate: update quantities lagged by one iteration (contact
  // pressures for friction).
  virtual void update_lagged(const Eigen::VectorXd& x) = 0;
};

struct NonlinearOptions {
  SolverKind kind = SolverKind::kNewton;
  double tolerance = 1e-6;  // on ||dx||/||x|| (paper eq. 12) and ||r||/||f_internal||
  int max_iterations = 100;
  int picard_before_newton = 1;  // direct iterations that start each Newton solve
  double initial_theta = 0.5;    // first tangent weight after them
  bool verbose = false;          // iteration table on stderr
};

struct NonlinearSummary {
  bool converged = false;
  int iterations = 0;
  int newton_steps = 0;
  int picard_steps = 0;
  double update_norm = 0.0;
  double residual_norm = 0.0;
  std::string message;  // why it stopped
};

// x: start (prescribed values already set); on return, the last iterate.
NonlinearSummary solve_nonlinear(NonlinearProblem& problem, const NonlinearOptions& options,
                                 Eigen::VectorXd* x);

}  // namespace vs
