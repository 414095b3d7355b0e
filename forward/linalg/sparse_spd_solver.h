// Sparse SPD solve: CHOLMOD supernodal LL^T through Eigen (symbolic analysis once per pattern,
// numeric factorisation per call), with Eigen's SimplicialLDLT as fallback when CHOLMOD reports a
// failure (e.g. not positive definite) or when selected. numerics.md 4.1: CHOLMOD factorises a
// 1e5-dof shell matrix ~2x faster than SimplicialLDLT on this machine, with a 7-15x faster
// analysis. Both read the lower triangle of the (full) symmetric matrix.
// kAuto (the default) picks SimplicialLDLT below kAutoCholmodDofs unknowns: measured on the ex4a
// quarter disc (CPU time per numeric factorisation, Nov 2026), 1 085 dofs: LDLT 2.7 ms, CHOLMOD
// supernodal 4.6-6.2 ms (its per-call overhead: a transposed copy, small supernodes); 4 085
// dofs: 23-26 ms / 28-31 ms; 15 845 dofs: 310 ms / 190-210 ms.
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <memory>

#include "linalg/sparse_matrix.h"

namespace vs {

enum class SparseSolverKind { kCholmodSupernodal, kSimplicialLDLT, kAuto };

inline constexpr int kAutoCholmodDofs = 8000;

// What kAuto resolves to for a matrix of `dofs` unknowns.
inline SparseSolverKind auto_sparse_solver(int dofs) {
  return dofs < kAutoCholmodDofs ? SparseSolverKind::kSimplicialLDLT
                                 : SparseSolverKind::kCholmodSupernodal;
}

class SparseSpdSolver {
 public:
  explicit SparseSpdSolver(SparseSolverKind preferred = SparseSolverKind::kAuto);
  ~SparseSpdSolver();

  // Symbolic analysis of the pattern (call again only if the pattern changes).
  void analyze(const SparseMatrix& A);
  // Numeric factorisation; returns false if both CHOLMOD and the fallback fail.
  bool factorize(const SparseMatrix& A);
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  // The solver that produced the last successful factorisation.
  SparseSolverKind active() const { return active_; }
  int analyses() const { return analyses_; }

 private:
  using Cholmod = Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>;
  using Ldlt = Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>;
  SparseSolverKind requested_, preferred_, active_;  // preferred_: kAuto resolved at analyze()
  std::unique_ptr<Cholmod> cholmod_;
  std::unique_ptr<Ldlt> ldlt_;
  bool ldlt_analyzed_ = false;
  int analyses_ = 0;
};

}  // namespace vs
