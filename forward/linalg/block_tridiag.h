// Block-tridiagonal matrix with 3x3 blocks: the exact structure of the axisymmetric meridian chain
// (node i couples only to i-1 and i+1). Symmetric by default (only the lower blocks stored),
// factorised by block LDL^T in O(n) with a Cholesky of every pivot block, which doubles as the
// positive-definiteness check. A Newton matrix with a non-symmetric part (Coulomb friction
// proportional to the current normal reaction) is made unsymmetric() and factorised by block LU,
// with every pivot block's symmetric part required positive definite (the same check, applied to
// a matrix that is SPD up to the small friction coupling). The 3x3 kernels
// are written out (block_tridiag.cc): Eigen's LLT solve with a matrix right-hand side goes through
// its dynamic-size triangular solver, which costs more than the arithmetic at this size.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <vector>

namespace vs {

class BlockTridiag {
 public:
  using Block = Eigen::Matrix3d;

  explicit BlockTridiag(int blocks = 0) { resize(blocks); }
  void resize(int blocks);
  void set_zero();
  int blocks() const { return static_cast<int>(diag_.size()); }

  Block& diag(int i) { return diag_[i]; }
  const Block& diag(int i) const { return diag_[i]; }
  // Coupling block K(i+1, i); K(i, i+1) is its transpose while the matrix is symmetric.
  Block& lower(int i) { return lower_[i]; }
  const Block& lower(int i) const { return lower_[i]; }
  // From now on (until set_zero(), resize() or set_symmetric()) the upper blocks K(i, i+1) are
  // stored apart, starting as the transposes of the lower ones.
  void unsymmetric();
  void set_symmetric() { symmetric_ = true; }
  // Forgets the fix_dof() marks (a matrix whose blocks are overwritten for a new assembly).
  void clear_fixed() { std::fill(fixed_.begin(), fixed_.end(), 0); }
  bool symmetric() const { return symmetric_; }
  // Coupling block K(i, i+1) of an unsymmetric() matrix.
  Block& upper(int i) { return upper_[i]; }

  // Replaces row and column of dof (block i, component a) by the identity.
  void fix_dof(int i, int a);

  // y = K x.
  Eigen::VectorXd multiply(const Eigen::VectorXd& x) const;

  // Factorises; false if a pivot block is not positive definite.
  bool factorize();
  // After factorize(): (max / min)^2 of the Cholesky diagonal of the pivot blocks (of their
  // symmetric parts if unsymmetric), over the dofs not fixed by fix_dof(). A lower bound of the
  // 2-norm condition number of the free part of an SPD matrix (cond = |L|^2 |L^-1|^2 >=
  // (max L_ii / min L_ii)^2), computed for free; 1 if every dof is fixed.
  double condition_estimate() const { return condition_estimate_; }
  // Solves K x = b with the last factorisation.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  // The same, overwriting b with x (no allocation).
  void solve_in_place(Eigen::VectorXd* b) const;

 private:
  bool factorize_unsymmetric();
  std::vector<Block> diag_, lower_, upper_;
  bool symmetric_ = true;
  std::vector<char> fixed_;  // per dof: fixed by fix_dof() (identity row and column)
  double condition_estimate_ = 1.0;
  void estimate_condition();
  // Cholesky factor L of every pivot block P_i = L L^T (lower triangle; the diagonal holds
  // 1 / L(a, a)).
  std::vector<Block> pivot_;
  std::vector<Block> W_;  // W_i = lower(i-1) * P_(i-1)^-1
  // Unsymmetric: inverses of the LU pivot blocks U_i (W_i = K(i, i-1) U_(i-1)^-1 as above).
  std::vector<Block> pivot_inverse_;
};

}  // namespace vs
