// The one nonlinear solve of both geometries: find the velocity field that makes the residual
// vanish at the free unknowns of a step problem.
//
// Strategy (numerics.md 3.3). The paper's direct iteration (section 3, steps 2-5) is the
// Kacanov / secant method: it decreases the convex flow potential monotonically and its matrix is
// always SPD. Newton with an Armijo line search on the same potential converges fast to tight
// tolerances. The loop blends the two with a tangent weight theta (0: direct iteration, 1:
// Newton) adapted like a trust region: a step the line search accepts moves theta towards 1, a
// rejected one back towards 0, and a rejected step falls back to the direct iteration.
// A problem may carry dual unknowns that shape its tangent (the primal-dual flow directions of
// material/flow_direction.h): it is told every step direction (set_direction) and step length
// (step_taken), and if its tangent starts every solve at the direct iteration's matrix and moves
// to Newton's by itself (self_starting), the loop starts at weight 1 without direct iterations.
//
// Options that change the work, not the answer:
//   full_step_evaluation  the full Newton step is tried with a complete evaluation (residual and
//                         matrix for the next iteration) instead of a potential-only one: an
//                         accepted full step costs one assembly instead of two; backtracking
//                         then uses potential-only evaluations from alpha = 1/2. Pays where an
//                         assembly costs more than a potential (the 3D shell).
//   chord_start           once a Newton update is below this fraction of |x|, the following
//                         iterations reuse its factorisation with residual-only evaluations
//                         while each update shrinks to at most chord_contraction of the
//                         previous one and passes the Armijo test; otherwise Newton resumes at
//                         the same x. 0 disables chord steps. A solve may also start with chord
//                         steps on an earlier solve's factorisation (reuse_factorisation).
//   krylov_max_iterations where a Newton iteration would factorise its matrix and the linear
//                         solver holds a factorisation that fits the problem (of an earlier
//                         iteration, or of an earlier solve with reuse_factorisation), it first
//                         solves the new matrix by conjugate gradients preconditioned with the
//                         held factorisation (LinearSolver::solve_preconditioned), an inexact
//                         Newton step: to the relative linear residual
//                         eta = min(1/2, max(krylov_tolerance, sqrt(|r|/|f|))) (Dembo, Eisenstat
//                         and Steihaug 1982: superlinear convergence of order 1.5), and
//                         factorises only if that fails within this many iterations. 0 disables.
// After an accepted iterate the problem updates quantities lagged by one iteration
// (update_lagged: the normal forces of Coulomb friction); an evaluation in hand is brought up to
// date by refresh() when the problem can do that more cheaply than a new evaluation.
// The loop knows nothing of shells: it sees a NewtonProblem and its LinearSolver.
#pragma once

#include <Eigen/Core>
#include <string>

#include "linalg/linear_solver.h"
#include "scene/scene.h"

namespace vs {

class NewtonProblem {
 public:
  virtual ~NewtonProblem() = default;
  // The solver that owns the matrix this problem assembles.
  virtual LinearSolver& linear_solver() = 0;
  // Residual at free unknowns (zero at prescribed ones) and, into linear_solver()'s matrix, the
  // matrix secant + theta (tangent - secant) with prescribed unknowns decoupled (theta = 0: the
  // paper's direct iteration; theta = 1: Newton). Sets *potential = flow potential at x (the
  // line-search merit). Returns the residual scale (norm of the internal forces).
  virtual double evaluate(const Eigen::VectorXd& x, double theta, Eigen::VectorXd* residual,
                          double* potential) = 0;
  // Residual and potential only, the matrix untouched (chord steps). Problems that support
  // chord steps override it; the default is never called while chord_start is 0.
  virtual double evaluate_residual(const Eigen::VectorXd& x, Eigen::VectorXd* residual,
                                   double* potential);
  // The step direction dx chosen at the iterate x; the line search then tries x + alpha dx.
  virtual void set_direction(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*dx*/) {}
  // Flow potential at x_trial = x + alpha dx of the last set_direction().
  virtual double potential(const Eigen::VectorXd& x_trial, double alpha) = 0;
  // The iterate moved to x + alpha dx (called before update_lagged()).
  virtual void step_taken(double /*alpha*/) {}
  // After each accepted iterate: quantities lagged by one iteration (contact normal forces).
  // Returns whether the system at a given x changed (an evaluation made before is stale).
  virtual bool update_lagged(const Eigen::VectorXd& x) = 0;
  // After update_lagged() changed the system: brings the last evaluate(), made at this x, up to
  // date in place (residual, potential and matrix) if the problem can; false if it cannot (the
  // loop then evaluates again).
  virtual bool refresh(const Eigen::VectorXd& /*x*/, Eigen::VectorXd* /*residual*/,
                       double* /*potential*/) {
    return false;
  }
  // True if the tangent starts every solve at the direct iteration's matrix and moves to
  // Newton's by itself (dual unknowns): the loop then starts at weight 1 without direct
  // iterations. Measured on ex1 (24 elements): 36 % fewer element passes than one direct
  // iteration and a weight ramp from 0.5.
  virtual bool self_starting() const { return false; }
};

struct NewtonOptions {
  SolverKind kind = SolverKind::kNewton;  // kPicard: direct iterations only
  double tolerance = 1e-6;                // on ||dx||/||x|| (paper eq. 12) and ||r||/||f_internal||
  int max_iterations = 100;
  // Direct iterations that start each solve, and the first tangent weight after them (ignored
  // for a self-starting problem).
  int picard_before_newton = 1;
  double initial_theta = 0.5;
  bool full_step_evaluation = false;  // see the header comment
  double chord_start = 0.0;           // 0: no chord steps
  double chord_contraction = 0.5;
  int krylov_max_iterations = 0;   // 0: no Krylov steps
  double krylov_tolerance = 1e-2;  // the smallest forcing term eta
  bool verbose = false;            // iteration table on stderr
  // Absolute floor of the residual's scale [N]: ||r|| is measured against
  // max(||f_internal||, force_floor). A sheet that moves rigidly (a cup drawn through the die,
  // nothing left to deform) has internal forces at round-off, and round-off over round-off never
  // converges (measured: a drawn cup stalled at |dx|/|x| = 3e-17, |r|/|f| = 0.999).
  double force_floor = 0.0;
  // The sheet's characteristic force [N] (sigma_y(0) h0 R), for the round-off stagnation test
  // (newton_converged): a stalled iterate whose residual is below `tolerance` times this force is
  // converged whatever the internal forces. 0: no such test.
  double stagnation_force = 0.0;

  // False with the reason if an option is out of its range.
  bool IsValid(std::string* why) const;
};

struct NewtonSummary {
  bool converged = false;
  int iterations = 0;
  int newton_steps = 0;
  int picard_steps = 0;
  int chord_steps = 0;        // steps on an earlier factorisation
  int krylov_steps = 0;       // Newton steps solved by preconditioned CG instead of a factorisation
  int krylov_iterations = 0;  // CG iterations, of successful and failed Krylov solves
  double update_norm = 0.0;
  double residual_norm = 0.0;
  double residual_abs = 0.0;  // ||r|| [N] of the same iterate
  // Largest LinearSolver::condition_estimate() of the Newton matrices factorised in this solve.
  double condition_estimate = 1.0;
  // Work: time in evaluate / evaluate_residual / potential / refresh, time in factorisations,
  // triangular solves and Krylov iterations, number of numeric factorisations.
  double assembly_s = 0.0;
  double factorisation_s = 0.0;
  int factorisations = 0;
  std::string message;  // why it stopped
};

// The stopping test on the norms of the latest iteration `sum`: update and residual within the
// tolerance (Picard: update only), or round-off stagnation: the update has vanished (1e-3 of the
// tolerance) while the residual, limited by the conditioning of rigid zones, sits just above the
// tolerance (up to 100x): the iterate is as good as double precision allows (measured: ex3
// sticking stalled at |dx|/|x| = 3e-17, |r|/|f| = 1.08e-6 with tolerance 1e-6), or below the
// tolerance times NewtonOptions::stagnation_force in absolute terms. Never after the first
// iteration.
bool newton_converged(const NewtonOptions& options, const NewtonSummary& sum, int iteration);

// x: start (prescribed values already set); on return, the last iterate.
// reuse_factorisation: the problem's linear solver holds a factorisation (of an earlier solve)
// that fits this problem's unknowns and constraints; the solve then starts with chord steps on
// it (only with chord_start > 0).
NewtonSummary solve_newton(NewtonProblem& problem, const NewtonOptions& options, Eigen::VectorXd* x,
                           bool reuse_factorisation = false);

}  // namespace vs
