#include "linalg/sparse_spd_solver.h"

#include "linalg/blas_library.h"
#include "linalg/dynamic_teams.h"

namespace vs {

SparseSpdSolver::SparseSpdSolver(SparseSolverKind preferred)
    : requested_(preferred),
      preferred_(preferred == SparseSolverKind::kAuto ? SparseSolverKind::kCholmodSupernodal
                                                      : preferred),
      active_(preferred_) {
  keep_blas_on_calling_thread();
}

SparseSpdSolver::~SparseSpdSolver() = default;

void SparseSpdSolver::analyze(const SparseMatrix& A) {
  ++analyses_;
  ldlt_analyzed_ = false;
  if (requested_ == SparseSolverKind::kAuto) {
    preferred_ = auto_sparse_solver(static_cast<int>(A.rows()));
  }
  if (preferred_ == SparseSolverKind::kCholmodSupernodal) {
    cholmod_ = std::make_unique<Cholmod>();
    cholmod_->cholmod().print = 0;  // a refusal is handled (the fallback) and counted, not printed
    // The fill-reducing ordering: CHOLMOD's nested dissection (METIS separators, constrained
    // minimum degree inside), not its default AMD. On the 3D forming matrix it gives a factor
    // with fewer entries and a flatter elimination tree, whose two halves the parallel
    // factorisation and solves share more evenly (experiments/09_linear_solver, "The ordering").
    // Measured (ex4a, 2-core AMD EPYC): 62 405 unknowns, factor 1.28e7 -> 1.18e7 entries, two-
    // thread factorisation 92 -> 68 ms, single-precision solve 3.6 -> 3.3 ms; 15 845 unknowns 12.2
    // -> 11.2 ms. Its analysis takes longer (0.27 -> 0.33 s at 62 405 unknowns), once per run.
    // METIS is deterministic (fixed seed), so the ordering and every bit after it are too.
    cholmod_->cholmod().nmethods = 1;
    cholmod_->cholmod().method[0].ordering = CHOLMOD_NESDIS;
    const DynamicTeams teams;
    cholmod_->analyzePattern(A);
  } else {
    ldlt_ = std::make_unique<Ldlt>();
    ldlt_->analyzePattern(A);
    ldlt_analyzed_ = true;
  }
}

bool SparseSpdSolver::factorize(const SparseMatrix& A) {
  single_current_ = false;
  if (preferred_ == SparseSolverKind::kCholmodSupernodal) {
    // After CHOLMOD's first factorisation of an analysis (which allocates the factor): ours, on
    // two threads, into the same factor (linalg/supernodal_cholesky.h).
    cholmod_factor* L = cholmod_->mutable_factor();
    if (parallel_factorisation_ && L && (numeric_.fits(*L) || numeric_.analyze(*L)) &&
        numeric_.factorize(A, L)) {
      cholmod_->mark_factorised();
      active_ = SparseSolverKind::kCholmodSupernodal;
      return true;
    }
    {
      const DynamicTeams teams;
      cholmod_->factorize(A);
    }
    if (cholmod_->info() == Eigen::Success) {
      active_ = SparseSolverKind::kCholmodSupernodal;
      return true;
    }
    ++fallbacks_;
  }
  if (!ldlt_analyzed_) {
    ldlt_ = std::make_unique<Ldlt>();
    ldlt_->analyzePattern(A);
    ldlt_analyzed_ = true;
  }
  ldlt_->factorize(A);
  active_ = SparseSolverKind::kSimplicialLDLT;
  return ldlt_->info() == Eigen::Success;
}

Eigen::VectorXd SparseSpdSolver::solve(const Eigen::VectorXd& b) const {
  if (active_ == SparseSolverKind::kCholmodSupernodal) {
    const DynamicTeams teams;
    return cholmod_->solve(b);
  }
  return ldlt_->solve(b);
}

void SparseSpdSolver::precondition(const Eigen::VectorXd& r, Eigen::VectorXd* z) const {
  const cholmod_factor* L = held_cholmod_factor();
  if (single_precision_ && L) {
    if (!single_current_) single_current_ = single_.assign(*L);
    if (single_current_) {
      single_.solve(r, z);
      return;
    }
  }
  *z = solve(r);
}

}  // namespace vs
