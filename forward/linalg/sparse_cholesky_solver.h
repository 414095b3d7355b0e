// LinearSolver over a sparse symmetric matrix that lives elsewhere (the 3D assembler's fixed
// pattern): SparseSpdSolver (CHOLMOD supernodal or SimplicialLDLT, linalg/sparse_spd_solver.h)
// with the symbolic analysis done on the first factorisation and kept (the pattern never
// changes).
#pragma once

#include "linalg/linear_solver.h"
#include "linalg/sparse_spd_solver.h"

namespace vs {

class SparseCholeskySolver : public LinearSolver {
 public:
  explicit SparseCholeskySolver(SparseSolverKind preferred = SparseSolverKind::kAuto)
      : solver_(preferred) {}
  // The matrix to factorise from now on (must outlive the solver or be reset).
  void set_matrix(const SparseMatrix* A) { A_ = A; }

  bool factorize() override {
    if (solver_.analyses() == 0) solver_.analyze(*A_);
    return solver_.factorize(*A_);
  }
  void solve_in_place(Eigen::VectorXd* b) const override {
    Eigen::VectorXd x = solver_.solve(*b);  // no aliasing of b in the solve
    b->swap(x);
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
};

}  // namespace vs
