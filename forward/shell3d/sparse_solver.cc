#include "shell3d/sparse_solver.h"

namespace vs::shell3d {

SparseSpdSolver::SparseSpdSolver(SolverKind preferred)
    : requested_(preferred),
      preferred_(preferred == SolverKind::kAuto ? SolverKind::kCholmodSupernodal : preferred),
      active_(preferred_) {}

SparseSpdSolver::~SparseSpdSolver() = default;

void SparseSpdSolver::analyze(const SparseMatrix& A) {
  ++analyses_;
  ldlt_analyzed_ = false;
  if (requested_ == SolverKind::kAuto) {
    preferred_ =
        A.rows() < kAutoCholmodDofs ? SolverKind::kSimplicialLDLT : SolverKind::kCholmodSupernodal;
  }
  if (preferred_ == SolverKind::kCholmodSupernodal) {
    cholmod_ = std::make_unique<Cholmod>();
    cholmod_->analyzePattern(A);
  } else {
    ldlt_ = std::make_unique<Ldlt>();
    ldlt_->analyzePattern(A);
    ldlt_analyzed_ = true;
  }
}

bool SparseSpdSolver::factorize(const SparseMatrix& A) {
  if (preferred_ == SolverKind::kCholmodSupernodal) {
    cholmod_->factorize(A);
    if (cholmod_->info() == Eigen::Success) {
      active_ = SolverKind::kCholmodSupernodal;
      return true;
    }
  }
  if (!ldlt_analyzed_) {
    ldlt_ = std::make_unique<Ldlt>();
    ldlt_->analyzePattern(A);
    ldlt_analyzed_ = true;
  }
  ldlt_->factorize(A);
  active_ = SolverKind::kSimplicialLDLT;
  return ldlt_->info() == Eigen::Success;
}

Eigen::VectorXd SparseSpdSolver::solve(const Eigen::VectorXd& b) const {
  if (active_ == SolverKind::kCholmodSupernodal) return cholmod_->solve(b);
  return ldlt_->solve(b);
}

}  // namespace vs::shell3d
