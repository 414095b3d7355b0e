// LinearSolver over a sparse symmetric matrix, stored in full (both triangles), that lives
// elsewhere (the 3D assembler's fixed pattern): SparseSpdSolver (CHOLMOD supernodal or
// SimplicialLDLT, linalg/sparse_spd_solver.h) with the symbolic analysis done on the first
// factorisation and kept (the pattern never changes).
#pragma once

#include "linalg/linear_solver.h"
#include "linalg/preconditioned_cg.h"
#include "linalg/sparse_spd_solver.h"

namespace vs {

class SparseCholeskySolver : public LinearSolver {
 public:
  explicit SparseCholeskySolver(SparseSolverKind preferred = SparseSolverKind::kAuto)
      : solver_(preferred) {}
  // The matrix to factorise from now on (must outlive the solver or be reset).
  void set_matrix(const SparseMatrix* A) { A_ = A; }
  // The preconditioner of solve_preconditioned and solve_approximately_in_place in single
  // precision (SparseSpdSolver).
  void set_single_precision_preconditioner(bool on) { solver_.set_single_precision(on); }
  // Numeric factorisations on two threads (SparseSpdSolver).
  void set_parallel_factorisation(bool on) { solver_.set_parallel_factorisation(on); }

  bool factorize() override {
    if (solver_.analyses() == 0) solver_.analyze(*A_);
    factorized_ = solver_.factorize(*A_);
    return factorized_;
  }
  void solve_in_place(Eigen::VectorXd* b) const override {
    Eigen::VectorXd x = solver_.solve(*b);  // no aliasing of b in the solve
    b->swap(x);
  }
  // The preconditioner's solve (single precision by default, SparseSpdSolver::precondition).
  void solve_approximately_in_place(Eigen::VectorXd* b) const override {
    Eigen::VectorXd x;
    solver_.precondition(*b, &x);
    b->swap(x);
  }
  // PCG on the matrix (multiply_symmetric, linalg/sparse_matrix.h) with the held factorisation as
  // the preconditioner.
  bool solve_preconditioned(const Eigen::VectorXd& b, Eigen::VectorXd* x, double tolerance,
                            int max_iterations, int* iterations) const override {
    *iterations = 0;
    if (!factorized_) return false;
    const PcgSummary sum = preconditioned_cg(
        [this](const Eigen::VectorXd& p, Eigen::VectorXd* q) { multiply_symmetric(*A_, p, q); },
        [this](const Eigen::VectorXd& r, Eigen::VectorXd* z) { solver_.precondition(r, z); }, b, x,
        tolerance, max_iterations);
    *iterations = sum.iterations;
    return sum.converged;
  }
  // Analysed (and factorised at least once, successfully or not): what the chord start needs.
  bool has_factorization() const override { return solver_.analyses() > 0; }
  std::string name() const override {
    return solver_.active() == SparseSolverKind::kCholmodSupernodal ? "CHOLMOD supernodal LL^T"
                                                                    : "Eigen SimplicialLDLT";
  }
  const SparseSpdSolver& solver() const { return solver_; }

 private:
  SparseSpdSolver solver_;
  const SparseMatrix* A_ = nullptr;
  bool factorized_ = false;  // the last factorisation succeeded
};

}  // namespace vs
