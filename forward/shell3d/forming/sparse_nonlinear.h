// Nonlinear solve of one forming step on a sparse system: the sparse analogue of
// forward/solver/nonlinear_solver.h (same options, summary and strategy, which that header
// explains: Newton with the tangent weight theta adapted like a trust region and an Armijo line
// search on the convex flow potential; a rejected step falls back to the always-SPD direct
// iteration). The problem's tangent is taken to be self-starting (the forming model's primal-dual
// tangent, forming_model.h: its first matrix in a run is the direct iteration's), so every solve
// starts at weight 1 without direct iterations. The matrix lives in the problem; the sparse
// symbolic analysis is done once per solver object (the pattern never changes).
// Differences: the full Newton step is tried with a complete evaluation (residual and matrix for
// the next iteration) instead of a potential-only one, so an accepted full step costs one
// assembly instead of two; backtracking uses potential-only evaluations; a step that already
// passes the convergence test ends the solve without evaluating its end point.
// Chord steps: once a Newton update is below 3e-2 of |x|, the following iterations reuse its
// factorisation with residual-only evaluations (no element matrices, no factorisation) while
// each update shrinks to at most half the previous one and passes the Armijo test; otherwise
// Newton resumes at the same x. A solve may also start with chord steps on the factorisation of
// an earlier solve (reuse_factorisation). After a lagged update (update_lagged) the evaluation in
// hand is brought up to date by refresh() when the problem can, instead of a new one.
#pragma once

#include <Eigen/Core>

#include "shell3d/sparse_solver.h"
#include "solver/nonlinear_solver.h"

namespace vs::shell3d {

class SparseNonlinearProblem {
 public:
  virtual ~SparseNonlinearProblem() = default;
  // Residual at free unknowns (zero at prescribed ones) and, in matrix(), secant + theta
  // (tangent - secant) with prescribed rows and columns decoupled. Returns the residual scale
  // (norm of the internal forces); *potential = flow potential at x.
  virtual double evaluate(const Eigen::VectorXd& x, double theta, Eigen::VectorXd* residual,
                          double* potential) = 0;
  // Residual and potential only (matrix() unchanged); returns the residual scale.
  virtual double evaluate_residual(const Eigen::VectorXd& x, Eigen::VectorXd* residual,
                                   double* potential) = 0;
  virtual const SparseMatrix& matrix() const = 0;
  virtual double potential(const Eigen::VectorXd& x) = 0;
  // After each accepted iterate: quantities lagged by one iteration (contact normal forces).
  // Returns whether the system at a given x changed (an evaluation made before is stale).
  virtual bool update_lagged(const Eigen::VectorXd& x) = 0;
  // After update_lagged() changed the system: brings the last evaluate(), made at this x, up to
  // date in place (residual, potential and matrix) if the problem can do that more cheaply than
  // a new evaluation; returns false if it cannot (the solver then evaluates again).
  virtual bool refresh(const Eigen::VectorXd& /*x*/, Eigen::VectorXd* /*residual*/,
                       double* /*potential*/) {
    return false;
  }
};

struct SparseSolveTimings {
  double assembly_s = 0.0;       // evaluate() and potential() calls
  double factorisation_s = 0.0;  // symbolic analysis, numeric factorisation and triangular solves
  int factorisations = 0;
};

// x: start (prescribed values already set); on return, the last iterate. Timings accumulate.
// reuse_factorisation: the solver's factorisation (of an earlier solve) fits this problem's
// unknowns and constraints; the solve then starts with chord steps on it.
NonlinearSummary solve_sparse_nonlinear(SparseNonlinearProblem& problem,
                                        const NonlinearOptions& options, SparseSpdSolver* solver,
                                        Eigen::VectorXd* x, SparseSolveTimings* timings,
                                        bool reuse_factorisation = false);

}  // namespace vs::shell3d
