// The linear-solver interface the Newton loop sees (MFEM's Solver, Ceres' LinearSolver): a
// problem assembles its matrix into the storage its solver owns, the Newton loop asks the solver
// to factorise that matrix and to solve with the factorisation. Two implementations:
//   BlockTridiagSolver (linalg/block_tridiag_solver.h)   the axisymmetric meridian chain, O(n)
//   SparseCholeskySolver (linalg/sparse_cholesky_solver.h)  the 3D shell: CHOLMOD supernodal
//                                                         (numeric factorisations and solves on
//                                                         two threads) or Eigen's SimplicialLDLT,
//                                                         analysis once
// Only the problem knows the matrix type; the loop knows analyse / factorise / solve / info.
// A solver may also solve the matrix the problem last assembled iteratively, preconditioned by
// the factorisation it holds (of an earlier matrix): solve_preconditioned, the Krylov step of
// solver/newton.h.
#pragma once

#include <Eigen/Core>
#include <string>

namespace vs {

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // Factorises the matrix the problem last assembled (the symbolic analysis, where there is one,
  // is done on the first call and kept while the pattern does not change). False if the matrix
  // is not positive definite (or, unsymmetric, has a pivot block whose symmetric part is not).
  virtual bool factorize() = 0;
  // Overwrites b with K^-1 b, using the last successful factorisation.
  virtual void solve_in_place(Eigen::VectorXd* b) const = 0;
  // Overwrites b with an approximation of K^-1 b, for steps that are approximate anyway (chord
  // steps on an earlier matrix): a solver may use a cheaper copy of its factorisation (the
  // sparse solver's single-precision one). By default solve_in_place.
  virtual void solve_approximately_in_place(Eigen::VectorXd* b) const { solve_in_place(b); }
  // A cheap lower bound of the condition number of the last factorised matrix, 1 if unknown.
  virtual double condition_estimate() const { return 1.0; }
  // Whether a factorisation is held (a solve may then start with chord steps on it).
  virtual bool has_factorization() const = 0;
  // Solves A x = b for the matrix A the problem last assembled (not necessarily the one
  // factorised) by preconditioned conjugate gradients, with the held factorisation as the
  // preconditioner, from x = 0, until |b - A x| <= tolerance |b| within max_iterations. False if
  // the solver cannot (the default), holds no factorisation, meets a direction of non-positive
  // curvature, or does not converge; *iterations gets the iterations spent either way.
  virtual bool solve_preconditioned(const Eigen::VectorXd& /*b*/, Eigen::VectorXd* /*x*/,
                                    double /*tolerance*/, int /*max_iterations*/,
                                    int* iterations) const {
    *iterations = 0;
    return false;
  }
  // Short name for run.json ("block tridiagonal LDL^T", "CHOLMOD supernodal", ...).
  virtual std::string name() const = 0;
};

}  // namespace vs
