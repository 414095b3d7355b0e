// Sparse SPD solve: CHOLMOD supernodal LL^T through Eigen (symbolic analysis once per pattern,
// with CHOLMOD's nested dissection ordering (NESDIS; sparse_spd_solver.cc), numeric
// factorisation per call), with Eigen's SimplicialLDLT as fallback when CHOLMOD reports a
// failure (e.g. not positive definite) or when selected. numerics.md 4.1: CHOLMOD factorises a
// 1e5-dof shell matrix ~2x faster than SimplicialLDLT on this machine, with a 7-15x faster
// analysis. CHOLMOD reads the upper triangle of the (full) symmetric matrix, which spares it a
// transposed copy per factorisation (8 % at 15 845 and 62 405 unknowns, experiments/09); the
// fallback reads the lower one. The 3D matrix is symmetric to round-off (~1e-20 relative).
// kAuto (the default) picks SimplicialLDLT below kAutoCholmodDofs unknowns: measured on the ex4a
// quarter disc (a numeric factorisation, quiet 2-core machine, experiments/09_linear_solver),
// with CHOLMOD's OpenMP teams capped (linalg/dynamic_teams.h; uncapped they cost it 3-4x at these
// sizes): 1 085 dofs LDLT 1.9 ms, CHOLMOD supernodal 1.4 ms; 4 085 dofs 15.7 / 9.0 ms; 15 845
// dofs 154 / 68 ms.
// CHOLMOD's own messages are off (its "matrix not positive definite" warning printed a line per
// refused factorisation: 4 789 lines in one 3D cup run); fallbacks() counts the refusals instead.
// Every numeric factorisation after CHOLMOD's first of an analysis is the two-thread one of
// linalg/supernodal_cholesky.h, written into CHOLMOD's factor (set_parallel_factorisation): it
// reads both triangles of the matrix (the same matrix to round-off). One it refuses (not positive
// definite, not finite, or a pattern outside the analysed one) is made again by CHOLMOD, and a
// refusal by CHOLMOD too goes to the fallback and is counted.
// precondition() applies the inverse of the held factorisation as a preconditioner: with a CHOLMOD
// factor and single_precision set (the default), through a single-precision copy of the factor
// (linalg/supernodal_factor.h), made at the first call after each factorisation.
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <memory>

#include "linalg/sparse_matrix.h"
#include "linalg/supernodal_cholesky.h"
#include "linalg/supernodal_factor.h"

namespace vs {

enum class SparseSolverKind { kCholmodSupernodal, kSimplicialLDLT, kAuto };

inline constexpr int kAutoCholmodDofs = 1000;  // 8 000 before the teams were capped

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
  // z ~ A^-1 r for a preconditioner: solve(), or the single-precision solves (see above).
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd* z) const;
  void set_single_precision(bool on) { single_precision_ = on; }
  // With a CHOLMOD factor: every numeric factorisation after the first of an analysis by
  // SupernodalCholesky (two threads, linalg/supernodal_cholesky.h) into CHOLMOD's factor; one it
  // refuses (not positive definite) is made again by CHOLMOD (and its fallback). On by default.
  void set_parallel_factorisation(bool on) { parallel_factorisation_ = on; }
  // CHOLMOD's factor of the last successful factorisation, null if that was not CHOLMOD's.
  const cholmod_factor* held_cholmod_factor() const {
    return active_ == SparseSolverKind::kCholmodSupernodal && cholmod_ ? cholmod_->factor()
                                                                       : nullptr;
  }
  // The solver that produced the last successful factorisation.
  SparseSolverKind active() const { return active_; }
  int analyses() const { return analyses_; }
  // Factorisations CHOLMOD refused (not positive definite) that the fallback then did.
  int fallbacks() const { return fallbacks_; }

 private:
  // Eigen's CHOLMOD wrapper with its factor (a protected member) readable and writable.
  class Cholmod : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Upper> {
   public:
    const cholmod_factor* factor() const { return m_cholmodFactor; }
    cholmod_factor* mutable_factor() { return m_cholmodFactor; }
    // After the factor's values were written by other means.
    void mark_factorised() {
      m_info = Eigen::Success;
      m_factorizationIsOk = true;
    }
  };
  using Ldlt = Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>;
  SparseSolverKind requested_, preferred_, active_;  // preferred_: kAuto resolved at analyze()
  std::unique_ptr<Cholmod> cholmod_;
  std::unique_ptr<Ldlt> ldlt_;
  bool ldlt_analyzed_ = false;
  int analyses_ = 0;
  int fallbacks_ = 0;
  bool single_precision_ = true;
  bool parallel_factorisation_ = true;
  SupernodalCholesky numeric_;
  mutable SinglePrecisionFactor single_;
  mutable bool single_current_ = false;  // single_ copies the last CHOLMOD factorisation
};

}  // namespace vs
