// Nonlinear solve of one step: find the velocity field that makes the residual vanish at the free
// unknowns. The paper's direct iteration (section 3, steps 2-5) is the Kacanov/secant method: it
// decreases the convex flow potential monotonically and its matrix is always SPD; Newton with an
// Armijo line search on the same potential converges fast to tight tolerances (numerics.md section
// 3.3). The problem may carry dual unknowns that shape its tangent (the axisymmetric problem: the
// primal-dual flow directions of material/flow_direction.h, which start every solve at the direct
// iteration's matrix and move to Newton's, NonlinearProblem::self_starting()); the solver tells it
// each step direction and step length. The secant step remains the fallback when the line search
// rejects a step. The solver knows nothing of shells: it sees a NonlinearProblem.
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
  // iteration; theta = 1: Newton). Returns the residual scale (norm of the internal forces). With
  // theta > 0 also sets *potential = potential(x), which the line search starts from (computed in
  // the same pass over the elements).
  virtual double evaluate(const Eigen::VectorXd& x, double theta, BlockTridiag* K,
                          Eigen::VectorXd* residual, double* potential) = 0;
  // The step direction dx chosen at the iterate x; the line search then tries x + alpha dx.
  virtual void set_direction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
    (void)x;
    (void)dx;
  }
  // Flow potential at x_trial = x + alpha dx of the last set_direction().
  virtual double potential(const Eigen::VectorXd& x_trial, double alpha) = 0;
  // The iterate moved to x + alpha dx (called before update_lagged()).
  virtual void step_taken(double alpha) { (void)alpha; }
  // Called after each accepted iterate: update quantities lagged by one iteration (contact
  // pressures for friction).
  virtual void update_lagged(const Eigen::VectorXd& x) = 0;
  // True if the problem's tangent starts every solve at the direct iteration's matrix and moves
  // to Newton's by itself (dual unknowns): the solver then starts at tangent weight 1 without
  // direct iterations. Measured on ex1 (24 elements): 36% fewer element passes than one direct
  // iteration and a weight ramp from 0.5.
  virtual bool self_starting() const { return false; }
};

struct NonlinearOptions {
  SolverKind kind = SolverKind::kNewton;
  double tolerance = 1e-6;  // on ||dx||/||x|| (paper eq. 12) and ||r||/||f_internal||
  int max_iterations = 100;
  // Direct iterations that start each Newton solve, and the first tangent weight after them
  // (ignored for a problem with a self-starting tangent, NonlinearProblem::self_starting()).
  int picard_before_newton = 1;
  double initial_theta = 0.5;
  bool verbose = false;  // iteration table on stderr
};

struct NonlinearSummary {
  bool converged = false;
  int iterations = 0;
  int newton_steps = 0;
  int picard_steps = 0;
  int chord_steps = 0;  // 3D solver: steps on an earlier Newton factorisation
  double update_norm = 0.0;
  double residual_norm = 0.0;
  // Largest BlockTridiag::condition_estimate() of the matrices factorised in this solve (a
  // lower bound of their condition numbers).
  double condition_estimate = 1.0;
  std::string message;  // why it stopped
};

// The stopping test of every nonlinear solve (axisymmetric and 3D), on the norms of the latest
// iteration `sum`: update and residual within the tolerance (Picard: update only), or round-off
// stagnation: the update has vanished (1e-3 of the tolerance) while the residual, limited by the
// conditioning of rigid zones, sits just above the tolerance (up to 100x): the iterate is as good
// as double precision allows (measured: ex3 sticking stalled at |dx|/|x| = 3e-17,
// |r|/|f| = 1.08e-6 with tolerance 1e-6). Never after the first iteration.
bool nonlinear_converged(const NonlinearOptions& options, const NonlinearSummary& sum,
                         int iteration);

// x: start (prescribed values already set); on return, the last iterate.
NonlinearSummary solve_nonlinear(NonlinearProblem& problem, const NonlinearOptions& options,
                                 Eigen::VectorXd* x);

}  // namespace vs
